// write_off round trip: any doubles (finite ones; the mesh refuses the rest) and any
// triangles written as OFF and read back must give the same mesh, bit for bit.
#include <unistd.h>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "sscc/mesh/mesh_io.hpp"
#include "sscc/mesh/write_off.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  // The first byte: vertex count 3..66; then 24 bytes per vertex; then 3 bytes per triangle.
  const std::size_t vertex_count = 3 + data[0] % 64;
  if (size < 1 + 24 * vertex_count) return 0;
  std::vector<Eigen::Vector3d> vertices(vertex_count);
  for (std::size_t v = 0; v < vertex_count; ++v) std::memcpy(vertices[v].data(), data + 1 + 24 * v, 24);
  std::vector<sscc::Triangle> triangles;
  for (std::size_t at = 1 + 24 * vertex_count; at + 3 <= size; at += 3) {
    triangles.push_back(
        {data[at] % int(vertex_count), data[at + 1] % int(vertex_count), data[at + 2] % int(vertex_count)});
  }
  std::vector<sscc::Triangle> kept;  // a triangle that repeats a vertex is not a triangle
  for (const sscc::Triangle& t : triangles) {
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) kept.push_back(t);
  }
  bool finite = true;
  for (const Eigen::Vector3d& x : vertices) finite = finite && x.allFinite();
  if (!finite || kept.empty()) return 0;
  const sscc::TriangleMesh mesh(vertices, kept);
  const std::string path = "/tmp/sscc_fuzz_write_" + std::to_string(getpid()) + ".off";
  sscc::write_off(path, mesh);
  sscc::TriangleMesh back = [&] {
    try {
      return sscc::read_mesh(path);
    } catch (const std::exception&) {
      std::abort();  // what write_off writes must read
    }
  }();
  if (back.vertex_count() != mesh.vertex_count() || back.triangles() != mesh.triangles()) std::abort();
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    for (int k = 0; k < 3; ++k) {
      const double a = mesh.vertices()[v][k], b = back.vertices()[v][k];
      if (std::memcmp(&a, &b, sizeof a) != 0) std::abort();
    }
  }
  return 0;
}
