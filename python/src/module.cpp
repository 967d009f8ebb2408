// The compiled part of the sscc Python package (imported by sscc/__init__.py).
#include "bindings.hpp"

#include "sscc/certificates/certificates.hpp"
#include "sscc/mesh/mesh_io.hpp"

namespace sscc::python {

void register_errors() {
  // The library's file errors carry the file name and the problem; keep the message.
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const FileError& error) {
      PyErr_SetString(PyExc_OSError, error.what());
    } catch (const MeshFileError& error) {
      PyErr_SetString(PyExc_OSError, error.what());
    } catch (const CertificateFileError& error) {
      PyErr_SetString(PyExc_OSError, error.what());
    }
  });
}

}  // namespace sscc::python

PYBIND11_MODULE(_sscc, module) {
  module.doc() =
      "Continuous collision detection for deformable triangle meshes with Subspace Self-Collision "
      "Culling (the compiled part of the sscc package; import sscc instead).";
  using namespace sscc::python;
  register_errors();
  bind_meshes(module);
  bind_models(module);
  bind_queries(module);
  bind_scene(module);
  bind_kernels(module);
  bind_shards(module);
}
