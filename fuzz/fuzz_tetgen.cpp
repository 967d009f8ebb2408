// TetGen's input: a closed surface (a tetrahedron, an octahedron or a cube, by the first
// byte) with its vertices moved by the next bytes on a 1/32 grid (so surfaces fold,
// flatten, cross themselves and repeat points), and a volume bound from one more byte,
// tetrahedralised as the modal analysis does. A volume mesh or an exception naming the
// problem, never a crash: the surface vertices come first and unchanged, every
// tetrahedron's nodes are in range, every node is finite.
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "sscc/basis/volume_mesh.hpp"

namespace {

struct Shape {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<sscc::Triangle> triangles;
};

Shape shape(int which) {
  switch (which % 3) {
    case 0:
      return {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
    case 1:
      return {{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
              {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
    default:
      return {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
              {{0, 2, 1},
               {0, 3, 2},
               {4, 5, 6},
               {4, 6, 7},
               {0, 1, 5},
               {0, 5, 4},
               {1, 2, 6},
               {1, 6, 5},
               {2, 3, 7},
               {2, 7, 6},
               {3, 0, 4},
               {3, 4, 7}}};
  }
}

/// The grid the vertices move on, and how far they may move (grid steps either way).
constexpr double kGrid = 1.0 / 32;
constexpr int kReach = 48;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  Shape s = shape(data[0]);
  // A volume bound of 1/8 to 1/2040 of a unit cube, or none: at most a few thousand tetrahedra.
  const double max_volume = data[1] == 0 ? 0.0 : 1.0 / (8.0 * data[1]);
  std::size_t at = 2;
  for (Eigen::Vector3d& x : s.vertices) {
    for (int k = 0; k < 3 && at < size; ++k, ++at) x[k] += kGrid * (int(data[at] % (2 * kReach + 1)) - kReach);
  }
  try {
    const sscc::TriangleMesh mesh(s.vertices, s.triangles);
    const sscc::VolumeMesh volume = sscc::tetrahedralize_surface(mesh, 1.414, max_volume);
    if (volume.nodes.size() < s.vertices.size()) std::abort();
    for (std::size_t v = 0; v < s.vertices.size(); ++v) {
      if (volume.nodes[v] != s.vertices[v]) std::abort();
    }
    for (const Eigen::Vector3d& x : volume.nodes) {
      if (!x.allFinite()) std::abort();
    }
    for (const sscc::Tetrahedron& t : volume.tetrahedra) {
      for (int n : t) {
        if (n < 0 || n >= int(volume.nodes.size())) std::abort();
      }
    }
  } catch (const std::exception&) {  // refused, with TetGen's complaint or the mesh's
  }
  return 0;
}
