#include "sscc/mesh/excluded_pairs.hpp"

#include <stdexcept>
#include <string>

#include "sscc/ccd/kernels.hpp"

namespace sscc {

ExcludedPairs::ExcludedPairs(int triangle_count, std::vector<std::pair<int, int>> pairs) {
  for (auto& [a, b] : pairs) {
    if (a < 0 || b < 0 || a >= triangle_count || b >= triangle_count) {
      throw std::invalid_argument("ExcludedPairs: pair (" + std::to_string(a) + ", " + std::to_string(b) +
                                  ") outside [0, " + std::to_string(triangle_count) + ")");
    }
    if (a == b) throw std::invalid_argument("ExcludedPairs: triangle " + std::to_string(a) + " paired with itself");
    if (a > b) std::swap(a, b);
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  if (pairs.empty()) return;
  pairs_ = std::move(pairs);
  offsets_.assign(triangle_count + 1, 0);
  for (const auto& [a, b] : pairs_) {
    ++offsets_[a + 1];
    ++offsets_[b + 1];
  }
  for (int t = 0; t < triangle_count; ++t) offsets_[t + 1] += offsets_[t];
  partners_.resize(offsets_.back());
  std::vector<int> next(offsets_.begin(), offsets_.end() - 1);
  for (const auto& [a, b] : pairs_) {
    partners_[next[a]++] = b;
    partners_[next[b]++] = a;
  }
  for (int t = 0; t < triangle_count; ++t)
    std::sort(partners_.begin() + offsets_[t], partners_.begin() + offsets_[t + 1]);
}

ExcludedPairs ExcludedPairs::touching_at_rest(const TriangleMesh& mesh) {
  // Sweep and prune along x over the triangles' closed boxes, then the exact test.
  const int n = mesh.triangle_count();
  std::vector<Aabb> boxes(n, Aabb::empty());
  for (int t = 0; t < n; ++t) {
    for (int v : mesh.triangles()[t]) boxes[t].add(mesh.vertices()[v]);
  }
  std::vector<int> order(n);
  for (int t = 0; t < n; ++t) order[t] = t;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return boxes[a].lo.x() < boxes[b].lo.x(); });
  std::vector<std::pair<int, int>> touching;
  for (int i = 0; i < n; ++i) {
    const int a = order[i];
    for (int j = i + 1; j < n && boxes[order[j]].lo.x() <= boxes[a].hi.x(); ++j) {
      const int b = order[j];
      if (!boxes[a].overlaps(boxes[b]) || mesh.adjacent(a, b)) continue;
      const Triangle& ta = mesh.triangles()[a];
      const Triangle& tb = mesh.triangles()[b];
      const auto& x = mesh.vertices();
      if (ccd::triangles_intersect(x[ta[0]], x[ta[1]], x[ta[2]], x[tb[0]], x[tb[1]], x[tb[2]])) {
        touching.emplace_back(a, b);
      }
    }
  }
  return ExcludedPairs(n, std::move(touching));
}

}  // namespace sscc
