#include "query/unconsidered_leaf_pairs.hpp"

#include <algorithm>

namespace sscc::detail {

UnconsideredLeafPairs::UnconsideredLeafPairs(const SubspaceBvh& bvh) {
  const SubspaceModel& model = bvh.model();
  const TriangleMesh& mesh = model.mesh();
  const int nodes = static_cast<int>(bvh.nodes().size());
  std::vector<int> leaf_of(mesh.triangle_count(), -1);
  for (int n = 0; n < nodes; ++n) {
    const SubspaceBvh::Node& node = bvh.nodes()[n];
    if (!node.is_leaf()) continue;
    for (int i = node.triangle_begin; i < node.triangle_end; ++i) leaf_of[bvh.triangle_order()[i]] = n;
  }
  const auto holds_none = [&](const SubspaceBvh::Node& a, const SubspaceBvh::Node& b) {
    for (int i = a.triangle_begin; i < a.triangle_end; ++i) {
      for (int j = b.triangle_begin; j < b.triangle_end; ++j) {
        if (model.considers(bvh.triangle_order()[i], bvh.triangle_order()[j])) return false;
      }
    }
    return true;
  };
  offsets_.assign(nodes + 1, 0);
  std::vector<int> around;
  for (int n = 0; n < nodes; ++n) {
    offsets_[n] = static_cast<int>(partners_.size());
    const SubspaceBvh::Node& node = bvh.nodes()[n];
    if (!node.is_leaf()) continue;
    // Each triangle of a listed leaf shares a vertex with n's first triangle: the leaf is
    // among those around that triangle's vertices.
    around.clear();
    for (int v : mesh.triangles()[bvh.triangle_order()[node.triangle_begin]]) {
      for (const int* t = mesh.triangles_of_vertex_begin(v); t != mesh.triangles_of_vertex_end(v); ++t) {
        if (leaf_of[*t] != n) around.push_back(leaf_of[*t]);
      }
    }
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    for (int m : around) {
      if (holds_none(node, bvh.nodes()[m])) partners_.push_back(m);
    }
  }
  offsets_[nodes] = static_cast<int>(partners_.size());
}

}  // namespace sscc::detail
