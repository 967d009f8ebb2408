// One scene object over one step, in world space: its reduced coordinates at both ends,
// its rigid frames, and what the inter-object tests need from it, computed on first use
// and shared by all the pairs it belongs to: world vertex positions, node sweeps (from the
// hierarchy's O(r) subspace bounds) and triangle sweeps (from the positions). Private to
// the library; per step, not shared between threads.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "query/sweep.hpp"
#include "sscc/scene/scene.hpp"

namespace sscc::detail {

/// Relative widening of a box mapped to world space, 2^-48: covers the rounding of
/// R x + t (a few units in the last place of |R| |x| + |t|) with a wide margin. Smaller
/// values could let a world box miss a vertex by an ulp; larger ones only cull less.
inline constexpr double kWorldBoxMargin = 0x1p-48;

/// The world box of a local box under a rigid frame.
Aabb world_box(const Aabb& local, const RigidFrame& frame);

class ObjectMotion {
 public:
  ObjectMotion(const SubspaceBvh& bvh, const ObjectStep& step);

  const SubspaceBvh& bvh() const { return bvh_; }
  const TriangleMesh& mesh() const { return bvh_.model().mesh(); }
  /// World positions of vertex v at the two ends.
  const Eigen::Vector3d& start(int v) {
    ensure(v);
    return x0_[v];
  }
  const Eigen::Vector3d& end(int v) {
    ensure(v);
    return x1_[v];
  }
  /// Node n's sweep: its subspace bound at each end, in world space (O(r)); for leaves the
  /// hull of its triangles' exact sweeps, which is tighter.
  const Sweep& node_sweep(int n);
  /// The sweep of the triangle at position i of the hierarchy's order (exact boxes).
  const Sweep& triangle_sweep(int i);
  long vertices_computed() const { return vertices_computed_; }

 private:
  void ensure(int v);

  const SubspaceBvh& bvh_;
  Eigen::VectorXd q_hat0_, q_hat1_;
  double norm0_, norm1_;
  RigidFrame frame0_, frame1_;
  std::vector<Eigen::Vector3d> x0_, x1_;
  std::vector<char> computed_;
  LazyBoxes<Sweep> node_sweeps_;
  LazyBoxes<Sweep> triangle_sweeps_;
  long vertices_computed_ = 0;
};

}  // namespace sscc::detail
