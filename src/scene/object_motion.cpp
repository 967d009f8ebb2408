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
      x0_(mesh().vertex_count()),
      x1_(mesh().vertex_count()),
      computed_(mesh().vertex_count(), 0),
      node_sweeps_(bvh.nodes().size()),
      triangle_sweeps_(mesh().triangle_count()) {}

void ObjectMotion::ensure(int v) {
  if (computed_[v]) return;
  const SubspaceModel& model = bvh_.model();
  x0_[v] = frame0_.rotation * model.position(v, q_hat0_) + frame0_.translation;
  x1_[v] = frame1_.rotation * model.position(v, q_hat1_) + frame1_.translation;
  computed_[v] = 1;
  ++vertices_computed_;
}

const Sweep& ObjectMotion::node_sweep(int n) {
  return node_sweeps_.get(n, [&](int m) {
    const SubspaceBvh::Node& node = bvh_.nodes()[m];
    if (node.is_leaf()) {
      Sweep sweep = Sweep::empty();
      for (int i = node.triangle_begin; i < node.triangle_end; ++i) sweep.merge(triangle_sweep(i));
      return sweep;
    }
    return Sweep{world_box(bvh_.box(m, q_hat0_, norm0_), frame0_), world_box(bvh_.box(m, q_hat1_, norm1_), frame1_)};
  });
}

const Sweep& ObjectMotion::triangle_sweep(int i) {
  return triangle_sweeps_.get(i, [&](int k) {
    const Triangle& t = mesh().triangles()[bvh_.triangle_order()[k]];
    for (int v : t) ensure(v);
    return Sweep{box_at(x0_, t), box_at(x1_, t)};
  });
}

}  // namespace sscc::detail
