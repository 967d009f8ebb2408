// The parts of the sscc Python module, one file each.
#pragma once

#include <pybind11/pybind11.h>

#include <stdexcept>
#include <utility>

namespace sscc::python {

namespace py = pybind11;

/// A file that cannot be read or written: raised in Python as OSError.
struct FileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Runs a file operation of the library, whose failures are std::runtime_error, so that
/// they reach Python as OSError (bad arguments stay ValueError).
template <typename Operation>
auto file_operation(Operation&& operation) {
  try {
    return std::forward<Operation>(operation)();
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const std::runtime_error& error) {
    throw FileError(error.what());
  }
}

void register_errors();
void bind_meshes(py::module_& module);
void bind_models(py::module_& module);
void bind_queries(py::module_& module);
void bind_scene(py::module_& module);
void bind_kernels(py::module_& module);
void bind_shards(py::module_& module);

}  // namespace sscc::python
