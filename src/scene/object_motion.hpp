// One scene object over one step, in world space: its reduced coordinates at both ends,
// its rigid frames, and what the inter-object tests need from it, computed on first use
// and shared by all the pairs it belongs to: world vertex positions, node sweeps (from the
// hierarchy's O(r) subspace bounds) and triangle sweeps (from the positions). Private to
// the library; per step, not shared between threads.
#pragma once

#include <Eigen/Core>

#include <memory>
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
    return cache().x0[v];
  }
  const Eigen::Vector3d& end(int v) {
    ensure(v);
    return cache().x1[v];
  }
  /// Node n's sweep: its subspace bound at each end, in world space (O(r)); for leaves the
  /// hull of its triangles' exact sweeps, which is tighter.
  const Sweep& node_sweep(int n);
  /// The sweep of the triangle at position i of the hierarchy's order (exact boxes).
  const Sweep& triangle_sweep(int i);
  long vertices_computed() const { return vertices_computed_; }

 private:
  /// Per-vertex and per-node storage, made on first use: most objects of a step are
  /// decided by their root's bound alone.
  struct Cache {
    explicit Cache(const SubspaceBvh& bvh);
    std::vector<Eigen::Vector3d> x0, x1;
    std::vector<char> computed;
    LazyBoxes<Sweep> node_sweeps;
    LazyBoxes<Sweep> triangle_sweeps;
  };
  Cache& cache();
  void ensure(int v);
  Sweep subspace_sweep(int n) const;

  const SubspaceBvh& bvh_;
  Eigen::VectorXd q_hat0_, q_hat1_;
  double norm0_, norm1_;
  RigidFrame frame0_, frame1_;
  Sweep root_;
  std::unique_ptr<Cache> cache_;
  long vertices_computed_ = 0;
};

}  // namespace sscc::detail
