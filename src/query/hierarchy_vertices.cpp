#include "query/hierarchy_vertices.hpp"

#include <algorithm>

namespace sscc::detail {

HierarchyVertices::HierarchyVertices(const SubspaceBvh& bvh) {
  const SubspaceModel& model = bvh.model();
  const TriangleMesh& mesh = model.mesh();
  const int count = mesh.vertex_count();
  rank_.assign(count, -1);
  order_.reserve(count);
  for (int t : bvh.triangle_order()) {
    for (int v : mesh.triangles()[t]) {
      if (rank_[v] < 0) {
        rank_[v] = static_cast<int>(order_.size());
        order_.push_back(v);
      }
    }
  }
  // Vertices of no triangle, which no query reaches, keep the order complete.
  for (int v = 0; v < count; ++v) {
    if (rank_[v] < 0) {
      rank_[v] = static_cast<int>(order_.size());
      order_.push_back(v);
    }
  }
  block_size_ = 3 * static_cast<std::ptrdiff_t>(model.mode_count());
  rows_.resize(static_cast<std::size_t>(block_size_) * count);
  const double* basis = model.scaled_basis().data();
  for (int i = 0; i < count; ++i) {
    std::copy_n(basis + order_[i] * block_size_, block_size_, rows_.begin() + i * block_size_);
  }
}

}  // namespace sscc::detail
