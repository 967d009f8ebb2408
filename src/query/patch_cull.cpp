#include "query/patch_cull.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace sscc::detail {

PatchCull::PatchCull(const SubspaceBvh& bvh, const NodeBoundaries& boundaries, const std::vector<Eigen::Vector3d>& x0,
                     const std::vector<Eigen::Vector3d>& x1, EnsureTriangle ensure_triangle, Caches& caches)
    : bvh_(bvh),
      boundaries_(boundaries),
      x0_(x0),
      x1_(x1),
      ensure_triangle_(std::move(ensure_triangle)),
      cones_(caches.cones),
      self_verdicts_(caches.self_verdicts),
      union_chain_(caches.union_chain) {
  cones_.reset(bvh.nodes().size());
  self_verdicts_.reset(bvh.nodes().size());
}

PatchCull::NodeCone PatchCull::leaf_cone(const SubspaceBvh::Node& leaf) {
  std::array<BernsteinNormals, kMaxLeafTriangles> normals;
  NodeCone result{NormalCone{}, Eigen::Vector3d::Zero()};
  for (int i = leaf.triangle_begin; i < leaf.triangle_end; ++i) {
    ensure_triangle_(i);
    const Triangle& t = bvh_.model().mesh().triangles()[bvh_.triangle_order()[i]];
    BernsteinNormals& n = normals[i - leaf.triangle_begin];
    n = bernstein_normals(x0_[t[0]], x0_[t[1]], x0_[t[2]], x1_[t[0]], x1_[t[1]], x1_[t[2]]);
    result.normal_sum += n.value[0] + n.value[1] + n.value[2];
  }
  result.cone = cone_of(result.normal_sum, normals.data(), normals.data() + (leaf.triangle_end - leaf.triangle_begin));
  return result;
}

const PatchCull::NodeCone& PatchCull::cone(int n) {
  return cones_.get(n, [&](int m) {
    const SubspaceBvh::Node& node = bvh_.nodes()[m];
    if (node.is_leaf()) return leaf_cone(node);
    std::array<NormalCone, kBranchingFactor> parts;
    NodeCone result{NormalCone{}, Eigen::Vector3d::Zero()};
    for (int c = 0; c < node.child_count; ++c) {
      const NodeCone& child = cone(node.first_child + c);
      parts[c] = child.cone;
      result.normal_sum += child.normal_sum;
    }
    result.cone = merged_cone(result.normal_sum, parts.data(), parts.data() + node.child_count);
    return result;
  });
}

bool PatchCull::contour_stays_simple(const Eigen::Vector3d& d, const std::vector<DirectedEdge>& chain) const {
  return winds_once_star_shaped(d, chain, x0_, x1_) || stays_simple_in_projection(d, chain, x0_, x1_);
}

int PatchCull::triangle_count(int n) const { return bvh_.nodes()[n].triangle_end - bvh_.nodes()[n].triangle_begin; }

bool PatchCull::cannot_self_touch(int n) {
  if (triangle_count(n) < kSmallestConeNode) return false;
  const int size = CullRecord::size_class(triangle_count(n));
  return self_verdicts_.get(n, [&](int m) -> char {
    if (!boundaries_.simple_cycle(m) || !self_tests_.worth_trying(size)) return 0;
    const NormalCone& own = cone(m).cone;
    return own.within_half_space() && self_tests_.record(size, contour_stays_simple(own.axis, boundaries_.chain(m)));
  }) != 0;
}

bool PatchCull::cannot_touch(int a, int b) {
  const int smaller = std::min(triangle_count(a), triangle_count(b));
  const int larger = std::max(triangle_count(a), triangle_count(b));
  if (smaller < kSmallestUnionPart || larger > kLargestUnionRatio * smaller) return false;
  const int size = CullRecord::size_class(smaller + larger);
  if (!pair_tests_.worth_trying(size)) return false;
  // Each part proven on its own (a disc whose normals stay in a half-space, its contour
  // simple): the union often is one too, and otherwise rarely. Only parts the traversal has
  // already tried: another's cone would cost its whole subtree's normals, which a pair's
  // descent along the shared boundary does not need (a part another cull skipped).
  const auto proven_alone = [&](int n) { return self_verdicts_.known(n) && self_verdicts_.value(n) != 0; };
  if (!proven_alone(a) || !proven_alone(b)) return false;
  const NodeCone& cone_a = cone(a);
  const NodeCone& cone_b = cone(b);
  const std::array<NormalCone, 2> parts{cone_a.cone, cone_b.cone};
  const NormalCone joint = merged_cone(cone_a.normal_sum + cone_b.normal_sum, parts.data(), parts.data() + 2);
  if (!joint.within_half_space()) return false;
  return union_is_simple_cycle(boundaries_.chain(a), boundaries_.chain(b), union_chain_) &&
         pair_tests_.record(size, contour_stays_simple(joint.axis, union_chain_));
}

double mean_patch_at_rest(const SubspaceBvh& bvh, const NodeBoundaries& boundaries) {
  const std::vector<Eigen::Vector3d>& rest = bvh.model().mesh().vertices();
  PatchCull::Caches caches;
  PatchCull cull(
      bvh, boundaries, rest, rest, [](int) {}, caches);
  long triangles = 0, patches = 0;
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    const SubspaceBvh::Node& node = bvh.nodes()[n];
    if (cull.cannot_self_touch(n)) {
      triangles += node.triangle_end - node.triangle_begin;
      ++patches;
    } else if (!node.is_leaf()) {
      for (int c = node.first_child; c < node.first_child + node.child_count; ++c) stack.push_back(c);
    }
  }
  return patches > 0 ? static_cast<double>(triangles) / static_cast<double>(patches) : 0.0;
}

}  // namespace sscc::detail
