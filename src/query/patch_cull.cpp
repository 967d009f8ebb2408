#include "query/patch_cull.hpp"

#include <cmath>
#include <utility>

namespace sscc::detail {

namespace {

/// d / |d|, or nothing usable (zero or not finite: no cone).
bool unit(const Eigen::Vector3d& d, Eigen::Vector3d& out) {
  const double length = d.norm();
  if (!(length > 0.0) || !std::isfinite(length)) return false;
  out = d / length;
  return true;
}

}  // namespace

PatchCull::PatchCull(const SubspaceBvh& bvh, const NodeBoundaries& boundaries, const std::vector<Eigen::Vector3d>& x0,
                     const std::vector<Eigen::Vector3d>& x1, EnsureTriangle ensure_triangle)
    : bvh_(bvh),
      boundaries_(boundaries),
      x0_(x0),
      x1_(x1),
      ensure_triangle_(std::move(ensure_triangle)),
      normals_(bvh.triangle_order().size()),
      axes_(bvh.nodes().size()),
      own_cone_(bvh.nodes().size(), -1) {}

const BernsteinNormals& PatchCull::normals(int i) {
  return normals_.get(i, [&](int k) {
    ensure_triangle_(k);
    const Triangle& t = bvh_.model().mesh().triangles()[bvh_.triangle_order()[k]];
    return bernstein_normals(x0_[t[0]], x0_[t[1]], x0_[t[2]], x1_[t[0]], x1_[t[1]], x1_[t[2]]);
  });
}

const Eigen::Vector3d& PatchCull::axis(int n) {
  return axes_.get(n, [&](int m) {
    const SubspaceBvh::Node& node = bvh_.nodes()[m];
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    if (node.is_leaf()) {
      for (int i = node.triangle_begin; i < node.triangle_end; ++i) sum += normals(i).value[0] + normals(i).value[2];
    } else {
      for (int c = node.first_child; c < node.first_child + node.child_count; ++c) sum += axis(c);
    }
    return sum;
  });
}

bool PatchCull::cone_holds(const Eigen::Vector3d& d, int n) {
  const SubspaceBvh::Node& node = bvh_.nodes()[n];
  for (int i = node.triangle_begin; i < node.triangle_end; ++i) {
    if (!certainly_positive(d, normals(i))) return false;
  }
  return true;
}

bool PatchCull::own_cone_holds(int n) {
  if (own_cone_[n] < 0) {
    Eigen::Vector3d d;
    own_cone_[n] = unit(axis(n), d) && cone_holds(d, n);
  }
  return own_cone_[n] == 1;
}

bool PatchCull::cannot_self_touch(int n) {
  if (!boundaries_.simple_cycle(n) || !own_cone_holds(n)) return false;
  Eigen::Vector3d d;
  unit(axis(n), d);
  return winds_once_star_shaped(d, boundaries_.chain(n), x0_, x1_);
}

bool PatchCull::cannot_touch(int a, int b) {
  if (!own_cone_holds(a) || !own_cone_holds(b)) return false;
  std::vector<DirectedEdge> edges = boundaries_.chain(a);
  edges.insert(edges.end(), boundaries_.chain(b).begin(), boundaries_.chain(b).end());
  const std::vector<DirectedEdge> chain = boundary_chain(std::move(edges));
  if (!is_simple_cycle(chain)) return false;
  Eigen::Vector3d d;
  if (!unit(axis(a) + axis(b), d)) return false;
  return cone_holds(d, a) && cone_holds(d, b) && winds_once_star_shaped(d, chain, x0_, x1_);
}

}  // namespace sscc::detail
