#include "scene/object_motion.hpp"

namespace sscc::detail {

Aabb world_box(const Aabb& local, const RigidFrame& frame) {
  const Eigen::Vector3d centre = 0.5 * (local.lo + local.hi);
  const Eigen::Vector3d half = 0.5 * (local.hi - local.lo);
  const Eigen::Matrix3d magnitude = frame.rotation.cwiseAbs();
  const Eigen::Vector3d world_centre = frame.rotation * centre + frame.translation;
  const Eigen::Vector3d world_half = magnitude * half;
  const Eigen::Vector3d margin =
      kWorldBoxMargin * (magnitude * (centre.cwiseAbs() + half) + frame.translation.cwiseAbs() + world_half);
  return {world_centre - world_half - margin, world_centre + world_half + margin};
}

ObjectMotion::ObjectMotion(const SubspaceBvh& bvh, const ObjectStep& step)
    : bvh_(bvh),
      q_hat0_(bvh.model().scaled_coordinates(step.q0)),
      q_hat1_(bvh.model().scaled_coordinates(step.q1)),
      norm0_(q_hat0_.stableNorm()),
      norm1_(q_hat1_.stableNorm()),
      frame0_(step.frame0),
      frame1_(step.frame1),
      root_(bvh.nodes()[0].is_leaf() ? Sweep::empty() : subspace_sweep(0)) {}

ObjectMotion::Cache::Cache(const SubspaceBvh& bvh)
    : x0(bvh.model().mesh().vertex_count()),
      x1(bvh.model().mesh().vertex_count()),
      computed(bvh.model().mesh().vertex_count(), 0),
      node_sweeps(bvh.nodes().size()),
      triangle_sweeps(bvh.model().mesh().triangle_count()) {}

ObjectMotion::Cache& ObjectMotion::cache() {
  if (!cache_) cache_ = std::make_unique<Cache>(bvh_);
  return *cache_;
}

Sweep ObjectMotion::subspace_sweep(int n) const {
  return Sweep{world_box(bvh_.box(n, q_hat0_, norm0_), frame0_), world_box(bvh_.box(n, q_hat1_, norm1_), frame1_)};
}

void ObjectMotion::ensure(int v) {
  Cache& c = cache();
  if (c.computed[v]) return;
  const SubspaceModel& model = bvh_.model();
  Eigen::Vector3d local0, local1;
  model.position_pair(v, q_hat0_, q_hat1_, local0, local1);
  c.x0[v] = frame0_.rotation * local0 + frame0_.translation;
  c.x1[v] = frame1_.rotation * local1 + frame1_.translation;
  c.computed[v] = 1;
  ++vertices_computed_;
}

const Sweep& ObjectMotion::node_sweep(int n) {
  if (n == 0 && !bvh_.nodes()[0].is_leaf()) return root_;
  return cache().node_sweeps.get(n, [&](int m) {
    const SubspaceBvh::Node& node = bvh_.nodes()[m];
    if (!node.is_leaf()) return subspace_sweep(m);
    Sweep sweep = Sweep::empty();
    for (int i = node.triangle_begin; i < node.triangle_end; ++i) sweep.merge(triangle_sweep(i));
    return sweep;
  });
}

const Sweep& ObjectMotion::triangle_sweep(int i) {
  return cache().triangle_sweeps.get(i, [&](int k) {
    const Triangle& t = mesh().triangles()[bvh_.triangle_order()[k]];
    for (int v : t) ensure(v);
    const Cache& c = cache();
    return Sweep{box_at(c.x0, t), box_at(c.x1, t)};
  });
}

}  // namespace sscc::detail
