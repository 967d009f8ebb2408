// Continuous self-collision detection for simulators without a subspace: cloth, full-space
// finite elements, anything that knows only its vertex positions at each step. This is
// their entry point. It is built from the mesh alone (no basis, no certificates); each
// query refits the hierarchy's boxes from the positions at both ends of the step and runs
// the traversal, culls and kernels of SelfCcd::query_positions, so the report is the same:
// the considered triangle pairs (neither adjacent nor excluded, excluded_pairs.hpp) that
// come into contact while every vertex moves linearly from x0 to x1, their vertex-face and
// edge-edge features with times of impact, and the earliest time of impact.
//
// Guarantee: exact for the given positions (the leaf kernels are exact, the refitted boxes
// contain the swept triangles), so nothing is missed and nothing is invented. The tree's
// grouping of triangles comes from the rest shape and is kept: a mesh that deforms far from
// it gets looser boxes and slower queries, never wrong reports. As for every continuous
// query, the step is assumed to start free of intersections.
//
// Immutable once built; query() is thread-safe, and runs on SelfCcdOptions::threads threads
// with a report independent of the count. Copies share the hierarchy (O(1)).
#pragma once

#include <Eigen/Core>

#include <vector>

#include "sscc/mesh/excluded_pairs.hpp"
#include "sscc/mesh/triangle_mesh.hpp"
#include "sscc/query/self_ccd.hpp"

namespace sscc {

class PositionCcd {
 public:
  /// Builds the hierarchy over the rest positions of `mesh`; `excluded` pairs are ignored
  /// (for instance ExcludedPairs::touching_at_rest(mesh)).
  explicit PositionCcd(TriangleMesh mesh, ExcludedPairs excluded = {});

  const TriangleMesh& mesh() const { return detector_.bvh().model().mesh(); }
  const ExcludedPairs& excluded_pairs() const { return detector_.bvh().model().excluded_pairs(); }

  /// The step from positions x0 to x1 (one per vertex). Throws std::invalid_argument for a
  /// wrong count or a NaN/infinity. options.use_certificates has no effect (there are none).
  SelfCcdReport query(const std::vector<Eigen::Vector3d>& x0, const std::vector<Eigen::Vector3d>& x1,
                      const SelfCcdOptions& options = {}) const {
    return detector_.query_positions(x0, x1, options);
  }

 private:
  SelfCcd detector_;
};

}  // namespace sscc
