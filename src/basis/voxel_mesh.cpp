#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "sscc/basis/volume_mesh.hpp"

namespace sscc {

namespace {

/// A regular grid of cubic cells with one empty cell of margin on every side.
struct Grid {
  Eigen::Vector3d origin;
  double cell = 0.0;
  std::array<int, 3> cells{};

  long index(int i, int j, int k) const {
    return i + static_cast<long>(cells[0]) * (j + static_cast<long>(cells[1]) * k);
  }
  std::array<int, 3> cell_of(const Eigen::Vector3d& p) const {
    std::array<int, 3> c;
    for (int a = 0; a < 3; ++a) {
      c[a] = std::clamp(static_cast<int>(std::floor((p[a] - origin[a]) / cell)), 1, cells[a] - 2);
    }
    return c;
  }
};

Grid make_grid(const TriangleMesh& mesh, int resolution) {
  const Aabb box = mesh.bounding_box();
  const Eigen::Vector3d& lo = box.lo;
  const Eigen::Vector3d& hi = box.hi;
  Grid grid;
  grid.cell = (hi - lo).maxCoeff() / resolution;
  if (!(grid.cell > 0.0)) throw std::invalid_argument("voxelize_surface: the mesh has no extent");
  grid.origin = lo - Eigen::Vector3d::Constant(grid.cell);
  for (int a = 0; a < 3; ++a) grid.cells[a] = static_cast<int>(std::ceil((hi[a] - lo[a]) / grid.cell)) + 3;
  return grid;
}

/// Cells the surface passes through, found by sampling every triangle at half a cell.
std::vector<char> surface_cells(const TriangleMesh& mesh, const Grid& grid) {
  std::vector<char> marked(static_cast<std::size_t>(grid.cells[0]) * grid.cells[1] * grid.cells[2], 0);
  for (const Triangle& t : mesh.triangles()) {
    const Eigen::Vector3d& a = mesh.vertices()[t[0]];
    const Eigen::Vector3d& b = mesh.vertices()[t[1]];
    const Eigen::Vector3d& c = mesh.vertices()[t[2]];
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const int n = std::max(1, static_cast<int>(std::ceil(2.0 * longest / grid.cell)));
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        const Eigen::Vector3d p = a + (static_cast<double>(i) / n) * (b - a) + (static_cast<double>(j) / n) * (c - a);
        const auto cell = grid.cell_of(p);
        marked[grid.index(cell[0], cell[1], cell[2])] = 1;
      }
    }
  }
  return marked;
}

/// Surface cells plus the cells they enclose: everything a face-connected flood from the
/// margin cannot reach. An open surface lets the flood in and leaves its shell of cells.
std::vector<char> solid_cells(const Grid& grid, std::vector<char> marked) {
  std::vector<char> outside(marked.size(), 0);
  std::vector<std::array<int, 3>> stack{{0, 0, 0}};
  outside[0] = 1;
  while (!stack.empty()) {
    const auto c = stack.back();
    stack.pop_back();
    for (int a = 0; a < 3; ++a) {
      for (int step : {-1, 1}) {
        auto n = c;
        n[a] += step;
        if (n[a] < 0 || n[a] >= grid.cells[a]) continue;
        const long id = grid.index(n[0], n[1], n[2]);
        if (outside[id] || marked[id]) continue;
        outside[id] = 1;
        stack.push_back(n);
      }
    }
  }
  for (std::size_t id = 0; id < marked.size(); ++id) marked[id] = outside[id] ? 0 : 1;
  return marked;
}

/// The six tetrahedra of a cube around its main diagonal (corner 0 to corner 7; corner
/// bits are x, y, z). The same split in every cell makes the tetrahedra conforming.
constexpr std::array<std::array<int, 4>, 6> kCubeTetrahedra{
    {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}}};

}  // namespace

VolumeMesh voxelize_surface(const TriangleMesh& mesh, int resolution) {
  if (resolution < 2) throw std::invalid_argument("voxelize_surface: resolution must be at least 2");
  if (mesh.vertex_count() == 0) throw std::invalid_argument("voxelize_surface: the mesh has no vertices");
  const Grid grid = make_grid(mesh, resolution);
  const std::vector<char> solid = solid_cells(grid, surface_cells(mesh, grid));

  const std::array<int, 3> corners{grid.cells[0] + 1, grid.cells[1] + 1, grid.cells[2] + 1};
  auto corner_index = [&](int i, int j, int k) {
    return i + static_cast<long>(corners[0]) * (j + static_cast<long>(corners[1]) * k);
  };
  std::vector<int> node_of_corner(static_cast<std::size_t>(corners[0]) * corners[1] * corners[2], -1);
  VolumeMesh volume;
  volume.method = "voxel";
  auto cell_corner_nodes = [&](int i, int j, int k) {
    std::array<int, 8> ids;
    for (int bit = 0; bit < 8; ++bit) {
      const int ci = i + (bit & 1), cj = j + ((bit >> 1) & 1), ck = k + ((bit >> 2) & 1);
      int& node = node_of_corner[corner_index(ci, cj, ck)];
      if (node < 0) {
        node = static_cast<int>(volume.nodes.size());
        volume.nodes.push_back(grid.origin + grid.cell * Eigen::Vector3d(ci, cj, ck));
      }
      ids[bit] = node;
    }
    return ids;
  };
  for (int k = 0; k < grid.cells[2]; ++k) {
    for (int j = 0; j < grid.cells[1]; ++j) {
      for (int i = 0; i < grid.cells[0]; ++i) {
        if (!solid[grid.index(i, j, k)]) continue;
        const auto ids = cell_corner_nodes(i, j, k);
        for (const auto& tet : kCubeTetrahedra) {
          volume.tetrahedra.push_back(
              positively_oriented(volume.nodes, {ids[tet[0]], ids[tet[1]], ids[tet[2]], ids[tet[3]]}));
        }
      }
    }
  }
  // Every vertex is a sample of its triangles, so its cell is solid and its corners exist.
  volume.embedding.resize(mesh.vertex_count(), static_cast<Eigen::Index>(volume.nodes.size()));
  volume.embedding.reserve(Eigen::VectorXi::Constant(mesh.vertex_count(), 8));
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    const Eigen::Vector3d& p = mesh.vertices()[v];
    const auto cell = grid.cell_of(p);
    const Eigen::Vector3d local =
        ((p - grid.origin) / grid.cell - Eigen::Vector3d(cell[0], cell[1], cell[2])).cwiseMax(0.0).cwiseMin(1.0);
    for (int bit = 0; bit < 8; ++bit) {
      const int ci = cell[0] + (bit & 1), cj = cell[1] + ((bit >> 1) & 1), ck = cell[2] + ((bit >> 2) & 1);
      const int node = node_of_corner[corner_index(ci, cj, ck)];
      if (node < 0) throw std::logic_error("voxelize_surface: a surface vertex outside the solid cells");
      double weight = 1.0;
      for (int a = 0; a < 3; ++a) weight *= ((bit >> a) & 1) ? local[a] : 1.0 - local[a];
      volume.embedding.insert(v, node) = weight;
    }
  }
  volume.embedding.makeCompressed();
  return volume;
}

}  // namespace sscc
