// Boxes over one time step, shared by the self and inter-object queries: an object's boxes
// at t = 0 and t = 1, the test of two of them interpolated over the step, and per-query
// caches. Private to the library.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "sscc/bvh/subspace_bvh.hpp"
#include "sscc/mesh/triangle_mesh.hpp"

namespace sscc::detail {

/// Box of triangle t at positions x (indexed by vertex).
inline Aabb box_at(const Eigen::Vector3d* x, const Triangle& t) {
  return {x[t[0]].cwiseMin(x[t[1]]).cwiseMin(x[t[2]]), x[t[0]].cwiseMax(x[t[1]]).cwiseMax(x[t[2]])};
}
inline Aabb box_at(const std::vector<Eigen::Vector3d>& x, const Triangle& t) { return box_at(x.data(), t); }

/// Node boxes computed on first use (each at most once per query). The boxes start
/// default-initialised (not zeroed: most are never read), the flags zeroed.
template <typename Box>
class LazyBoxes {
 public:
  LazyBoxes() = default;
  explicit LazyBoxes(std::size_t nodes) { reset(nodes); }
  /// Every box unknown again, for `nodes` nodes: the storage is kept when large enough, so a
  /// reused cache costs no allocation (nor the page faults of fresh memory).
  void reset(std::size_t nodes) {
    if (nodes > capacity_) {
      boxes_.reset(new Box[nodes]);
      capacity_ = nodes;
    }
    known_.assign(nodes, 0);
  }
  /// Node n's value, computed by compute(n) on first use. The check inlines and the
  /// computation stays out of line: the traversal asks again for most boxes it has (measured
  /// with callgrind on the lion's cones query: a call's register saves cost more than the
  /// check).
  template <typename Compute>
  const Box& get(int n, Compute compute) {
    if (!known_[n]) fill(n, compute);
    return boxes_[n];
  }
  bool known(int n) const { return known_[n] != 0; }
  /// Sets node n's value, known from then on.
  void set(int n, const Box& box) {
    boxes_[n] = box;
    known_[n] = 1;
  }
  /// Node n's value; only once known(n).
  const Box& value(int n) const { return boxes_[n]; }

 private:
  template <typename Compute>
  [[gnu::noinline]] void fill(int n, Compute& compute) {
    boxes_[n] = compute(n);
    known_[n] = 1;
  }

  std::unique_ptr<Box[]> boxes_;
  std::size_t capacity_ = 0;
  std::vector<char> known_;
};

/// Relative slack on a gap compared with a minimum separation d > 0: the gap's subtraction
/// rounds (relative error 2^-53); rounding is monotone, so a computed gap above d already
/// proves the exact one above d, and the factor is a margin beyond that. Below 1 would cull
/// pairs exactly d apart; larger only culls less.
inline constexpr double kSeparationSlack = 1.0 + 1e-12;

/// Whether an interval ending at `upper_end` lies below one starting at `lower_end` by more
/// than d (d = 0: strictly below; touching intervals are not apart). Every box test here is
/// made of these.
inline bool below_by_more_than(double upper_end, double lower_end, double d) {
  if (d == 0.0) return upper_end < lower_end;
  return lower_end - upper_end > d * kSeparationSlack;
}

/// Whether the intervals [a_lo, a_hi] and [b_lo, b_hi] stay farther apart than d: the boxes'
/// test, and the feature boxes' before the kernels.
inline bool apart(double a_lo, double a_hi, double b_lo, double b_hi, double d) {
  return below_by_more_than(a_hi, b_lo, d) || below_by_more_than(b_hi, a_lo, d);
}

/// Whether two boxes come within d of each other along every axis.
inline bool overlap(const Aabb& a, const Aabb& b, double d) {
  for (int k = 0; k < 3; ++k) {
    if (apart(a.lo[k], a.hi[k], b.lo[k], b.hi[k], d)) return false;
  }
  return true;
}
inline Aabb hull(const Aabb& a, const Aabb& b) { return {a.lo.cwiseMin(b.lo), a.hi.cwiseMax(b.hi)}; }

/// An object (triangle or node) over the step: start bounds its vertices at t = 0 and end
/// those at t = 1, each on its own. Every vertex moves linearly between its ends (the path the
/// kernels take: in a scene, linear in world coordinates), so at time t the object lies in the
/// box interpolated linearly between them: lo(t) = (1 - t) start.lo + t end.lo, and likewise hi(t).
struct Sweep {
  Aabb start, end;

  /// The empty sweep, neutral for merge().
  static Sweep empty() { return {Aabb::empty(), Aabb::empty()}; }
  void merge(const Sweep& part) {
    start = hull(start, part.start);
    end = hull(end, part.end);
  }
};

/// Whether a stays below b along axis k, farther than d, for the whole step: the gap between
/// b's interpolated lower face and a's upper face is linear in t, so beyond d at both ends it
/// is beyond d throughout. The test compares the ends only (d = 0: no arithmetic, exact).
inline bool below_throughout(const Sweep& a, const Sweep& b, int k, double d) {
#ifdef SSCC_MUTANT_SWEEP_EITHER_END
  return below_by_more_than(a.start.hi[k], b.start.lo[k], d) || below_by_more_than(a.end.hi[k], b.end.lo[k], d);
#endif
  return below_by_more_than(a.start.hi[k], b.start.lo[k], d) && below_by_more_than(a.end.hi[k], b.end.lo[k], d);
}

/// Whether two sweeps may come within d (0: touch): no axis along which one stays below the
/// other throughout. At least as tight as the swept boxes' test (the hull of both ends) in
/// every frame moving linearly in t, where neighbours that move alike sweep small boxes: it is
/// that test in the best such frame, chosen per axis.
inline bool sweeps_may_touch(const Sweep& a, const Sweep& b, double d) {
  for (int k = 0; k < 3; ++k) {
    if (below_throughout(a, b, k, d) || below_throughout(b, a, k, d)) return false;
  }
  return true;
}

/// Calls test(i, j) for the triangle pairs of leaves a and b (positions in the hierarchy's
/// order) where each triangle meets the other leaf: a_meets(i) for a's triangles,
/// b_meets(j) for b's.
template <typename AMeets, typename BMeets, typename Test>
void for_each_pruned_leaf_pair(const SubspaceBvh::Node& a, const SubspaceBvh::Node& b, AMeets a_meets, BMeets b_meets,
                               Test test) {
  std::array<int, kMaxLeafTriangles> from_b;
  int count_b = 0;
  for (int j = b.triangle_begin; j < b.triangle_end; ++j) {
    if (b_meets(j)) from_b[count_b++] = j;
  }
  for (int i = a.triangle_begin; i < a.triangle_end && count_b > 0; ++i) {
    if (!a_meets(i)) continue;
    for (int k = 0; k < count_b; ++k) test(i, from_b[k]);
  }
}

}  // namespace sscc::detail
