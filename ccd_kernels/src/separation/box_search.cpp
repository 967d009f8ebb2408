#include "separation/box_search.hpp"

#include <algorithm>
#include <array>
#include <queue>
#include <vector>

#include "separation/bounded.hpp"

namespace sscc::ccd {

namespace {

using separation::Bounded;
using BVec3 = std::array<Bounded, 3>;

/// Margin on the distance comparisons covering the rounding of sums of squares and norms.
constexpr double kSquaredDistanceSlack = 1.0 + 1e-12;

struct Box {
  double lo[3];  // t, u, v
  double hi[3];
};

struct EarlierFirst {
  bool operator()(const Box& a, const Box& b) const { return a.lo[0] > b.lo[0]; }
};

BVec3 difference(const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
  BVec3 d;
  for (int k = 0; k < 3; ++k) d[k] = Bounded::exact(x[k]) - Bounded::exact(y[k]);
  return d;
}

/// F(t, u, v) = A(t) + u B(t) + v C(t), each of A, B, C linear in t.
struct Difference {
  BVec3 a[2], b[2], c[2];  // at t = 0 and t = 1

  explicit Difference(const FourPointMotion& m) {
    const auto& x0 = m.t0;
    const auto& x1 = m.t1;
    if (m.pair == PrimitivePair::kVertexFace) {
      // v - (f0 + u (f1 - f0) + v (f2 - f0))
      a[0] = difference(x0[3], x0[0]), a[1] = difference(x1[3], x1[0]);
      b[0] = difference(x0[0], x0[1]), b[1] = difference(x1[0], x1[1]);
      c[0] = difference(x0[0], x0[2]), c[1] = difference(x1[0], x1[2]);
    } else {
      // (a0 + u (a1 - a0)) - (b0 + v (b1 - b0))
      a[0] = difference(x0[0], x0[2]), a[1] = difference(x1[0], x1[2]);
      b[0] = difference(x0[1], x0[0]), b[1] = difference(x1[1], x1[0]);
      c[0] = difference(x0[2], x0[3]), c[1] = difference(x1[2], x1[3]);
    }
  }

  Bounded at(int k, double t, double u, double v) const {
    const Bounded s = Bounded::exact(1.0 - t);  // t is a dyadic in [0, 1]: exact
    const Bounded tt = Bounded::exact(t);
    const Bounded ak = a[0][k] * s + a[1][k] * tt;
    const Bounded bk = b[0][k] * s + b[1][k] * tt;
    const Bounded ck = c[0][k] * s + c[1][k] * tt;
    return ak + Bounded::exact(u) * bk + Bounded::exact(v) * ck;
  }
};

/// F at the eight corners of a box, with error bounds.
struct Corners {
  Bounded f[8][3];

  Corners(const Difference& diff, const Box& box) {
    for (int corner = 0; corner < 8; ++corner) {
      const double t = (corner & 1) ? box.hi[0] : box.lo[0];
      const double u = (corner & 2) ? box.hi[1] : box.lo[1];
      const double v = (corner & 4) ? box.hi[2] : box.lo[2];
      for (int k = 0; k < 3; ++k) f[corner][k] = diff.at(k, t, u, v);
    }
  }
};

/// |F| > d on the whole box, proven two ways: per coordinate, F_k lies between its
/// corner values; and along a direction n (the mean corner value), n . F is multilinear
/// too, so |F| >= min over corners of n . F / |n|.
bool certainly_farther(const Corners& c, double d) {
  double squared = 0.0;
  double n[3] = {0.0, 0.0, 0.0};
  for (int k = 0; k < 3; ++k) {
    double lo = INFINITY;
    double hi = -INFINITY;
    for (int corner = 0; corner < 8; ++corner) {
      lo = std::min(lo, c.f[corner][k].value - c.f[corner][k].error);
      hi = std::max(hi, c.f[corner][k].value + c.f[corner][k].error);
      n[k] += 0.125 * c.f[corner][k].value;
    }
    const double gap = std::max({0.0, lo, -hi});
    squared += gap * gap;
  }
  if (squared > d * d * kSquaredDistanceSlack) return true;
  const double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(norm > 0.0)) return false;
  double lowest = INFINITY;
  for (int corner = 0; corner < 8; ++corner) {
    Bounded along = Bounded::exact(0.0);
    for (int k = 0; k < 3; ++k) along = along + Bounded::exact(n[k]) * c.f[corner][k];
    lowest = std::min(lowest, along.value - along.error);
  }
  return lowest > d * norm * kSquaredDistanceSlack;  // NaN never excludes
}

/// A corner at distance at most `reach` (in floating point), or -1.
int corner_within(const Corners& c, double reach) {
  for (int corner = 0; corner < 8; ++corner) {
    const double squared = c.f[corner][0].value * c.f[corner][0].value + c.f[corner][1].value * c.f[corner][1].value +
                           c.f[corner][2].value * c.f[corner][2].value;
    if (squared <= reach * reach) return corner;
  }
  return -1;
}

}  // namespace

CcdResult box_separation_search(const FourPointMotion& motion, double minimum_separation, double toi_tolerance) {
  const Difference f(motion);
  const bool triangle_domain = motion.pair == PrimitivePair::kVertexFace;
  const double reach = (1.0 + kSeparationRelativeTolerance) * minimum_separation;
  std::priority_queue<Box, std::vector<Box>, EarlierFirst> queue;
  queue.push(Box{{0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}});
  CcdResult result;
  result.decided_by = DecidedBy::kSeparationSearch;
  for (int examined = 0; !queue.empty(); ++examined) {
    const Box box = queue.top();
    if (examined >= kSeparationMaxBoxes) {
      result.hit = true;  // out of budget: the earliest box not excluded, conservatively
      result.toi = box.lo[0];
      return result;
    }
    queue.pop();
    if (triangle_domain && box.lo[1] + box.lo[2] > 1.0) continue;
    const Corners corners(f, box);
    if (certainly_farther(corners, minimum_separation)) continue;
    const bool t_narrow = box.hi[0] - box.lo[0] <= toi_tolerance;
    const int near = t_narrow ? corner_within(corners, reach) : -1;
    if (near >= 0) {
      result.hit = true;
      result.toi = box.lo[0];
      result.params[0] = (near & 2) ? box.hi[1] : box.lo[1];
      result.params[1] = (near & 4) ? box.hi[2] : box.lo[2];
      return result;
    }
    int axis = t_narrow ? 1 : 0;
    for (int i = 1; i < 3; ++i) {
      if (box.hi[i] - box.lo[i] > box.hi[axis] - box.lo[axis]) axis = i;
    }
    const double mid = 0.5 * (box.lo[axis] + box.hi[axis]);
    Box left = box;
    Box right = box;
    left.hi[axis] = mid;
    right.lo[axis] = mid;
    queue.push(left);
    queue.push(right);
  }
  return result;
}

}  // namespace sscc::ccd
