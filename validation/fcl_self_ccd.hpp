// FCL 0.7's continuous self-collision of a deforming mesh, for comparison: a
// BVHModel<AABB> updated each step (previous and current vertices), traversed against
// itself with MeshContinuousCollisionTraversalNode, adjacent and excluded triangle pairs
// skipped (the pairs the library's queries do not consider).
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "sscc/mesh/excluded_pairs.hpp"
#include "sscc/mesh/triangle_mesh.hpp"

namespace sscc::validation {

class FclSelfCcd {
 public:
  /// Throws std::logic_error when built without FCL.
  explicit FclSelfCcd(const TriangleMesh& mesh, ExcludedPairs excluded = {});
  ~FclSelfCcd();
  /// Colliding considered (non-adjacent, not excluded) triangle pairs (first < second, sorted) between the positions
  /// x0 (start of step) and x1 (end).
  std::vector<std::pair<int, int>> step(const std::vector<Eigen::Vector3d>& x0, const std::vector<Eigen::Vector3d>& x1);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sscc::validation
