// Any bytes as an OFF, OBJ or PLY file (the format chosen at compile time by
// SSCC_FUZZ_EXTENSION): a mesh or a MeshFileError, never a crash; a mesh that reads has
// every triangle's indices in range.
#include <cstdlib>
#include <stdexcept>

#include "fuzz_support.hpp"
#include "sscc/mesh/mesh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = sscc::fuzz::scratch_file(data, size, SSCC_FUZZ_EXTENSION);
  try {
    const sscc::TriangleMesh mesh = sscc::read_mesh(path);
    for (const sscc::Triangle& t : mesh.triangles()) {
      for (int v : t) {
        if (v < 0 || v >= mesh.vertex_count()) std::abort();
      }
    }
  } catch (const sscc::MeshFileError&) {
  } catch (const std::invalid_argument&) {  // a mesh the connectivity refuses (non-manifold, ...)
  }
  return 0;
}
