#include "exact/projected_decider.hpp"

#include <vector>

namespace sscc::ccd {

namespace {

using exact::Polynomial;
using exact::PolyVec3;
using exact::RealRoot;

/// 2D dot product of x and y in the coordinate plane that drops `axis`.
Polynomial planar_dot(const PolyVec3& x, const PolyVec3& y, int axis) {
  const int i = (axis + 1) % 3;
  const int j = (axis + 2) % 3;
  return x[i] * y[i] + x[j] * y[j];
}

/// The sign conditions of contact in one coordinate plane.
struct PlaneConditions {
  std::vector<Polynomial> orientations;  // see four_point_motion.hpp for their order
  std::vector<Polynomial> between;       // <= 0 when a point lies between two others
};

struct Conditions {
  PrimitivePair pair;
  Polynomial coplanarity;
  std::array<PlaneConditions, 3> planes;
};

Conditions build_conditions(const FourPointMotion& motion) {
  std::array<PolyVec3, 4> x;
  for (int i = 0; i < 4; ++i) {
    x[i] = exact::linear_trajectory(
        exact::to_rational(motion.t0[i][0], motion.t0[i][1], motion.t0[i][2]),
        exact::to_rational(motion.t1[i][0], motion.t1[i][1], motion.t1[i][2]));
  }
  const PolyVec3 e1 = x[1] - x[0];
  const PolyVec3 e2 = x[2] - x[0];
  const PolyVec3 e3 = x[3] - x[0];
  const PolyVec3 k12 = exact::cross(e1, e2);
  const PolyVec3 k13 = exact::cross(e1, e3);
  const PolyVec3 k23 = exact::cross(e2, e3);
  Conditions c{motion.pair, exact::dot(k12, e3), {}};
  for (int k = 0; k < 3; ++k) {
    PlaneConditions& plane = c.planes[k];
    const Polynomial mixed = k12[k] + k23[k] - k13[k];
    // "p between q and r" on a line: (p - q) . (p - r) <= 0.
    const auto between = [&](int p, int q, int r) {
      return planar_dot(x[p] - x[q], x[p] - x[r], k);
    };
    if (motion.pair == PrimitivePair::kVertexFace) {
      plane.orientations = {k13[k], mixed, -k23[k]};
      plane.between = {between(3, 0, 1), between(3, 1, 2), between(3, 2, 0)};
    } else {
      plane.orientations = {k12[k], k13[k], k23[k], mixed};
      plane.between = {between(2, 0, 1), between(3, 0, 1), between(0, 2, 3), between(1, 2, 3)};
    }
  }
  return c;
}

bool any_between(const PlaneConditions& plane, RealRoot& t) {
  for (const Polynomial& b : plane.between) {
    if (exact::sign_at_root(b, t) <= 0) return true;
  }
  return false;
}

bool touch_in_plane(PrimitivePair pair, const PlaneConditions& plane, RealRoot& t) {
  int s[4] = {0, 0, 0, 0};
  bool all_zero = true;
  for (std::size_t i = 0; i < plane.orientations.size(); ++i) {
    s[i] = exact::sign_at_root(plane.orientations[i], t);
    all_zero = all_zero && s[i] == 0;
  }
  if (all_zero) return any_between(plane, t);  // everything on one line in this plane
  if (pair == PrimitivePair::kVertexFace) {
    const bool has_positive = s[0] > 0 || s[1] > 0 || s[2] > 0;
    const bool has_negative = s[0] < 0 || s[1] < 0 || s[2] < 0;
    return !(has_positive && has_negative);
  }
  return s[0] * s[1] <= 0 && s[2] * s[3] <= 0;
}

bool touch_at(const Conditions& c, RealRoot& t) {
  for (const PlaneConditions& plane : c.planes) {
    if (!touch_in_plane(c.pair, plane, t)) return false;
  }
  return true;
}

void append_roots(const Polynomial& p, std::vector<RealRoot>& candidates) {
  if (p.is_zero()) return;
  for (RealRoot& r : exact::roots_in_unit_interval(p)) candidates.push_back(std::move(r));
}

}  // namespace

std::optional<RealRoot> exact_first_contact(const FourPointMotion& motion) {
  const Conditions c = build_conditions(motion);
  std::vector<RealRoot> candidates;
  if (!c.coplanarity.is_zero()) {
    // Contact needs coplanarity, so it can only happen at the cubic's roots, which come
    // in increasing order: the first that touches is the answer.
    for (RealRoot& t : exact::roots_in_unit_interval(c.coplanarity)) {
      if (touch_at(c, t)) return t;
    }
    return std::nullopt;
  }
  candidates.push_back({Polynomial::linear(0, 1), 0, 0});
  for (const PlaneConditions& plane : c.planes) {
    for (const Polynomial& p : plane.orientations) append_roots(p, candidates);
    for (const Polynomial& p : plane.between) append_roots(p, candidates);
  }
  std::optional<RealRoot> first;
  for (RealRoot& t : candidates) {
    if (first && exact::compare(t, *first) >= 0) continue;
    if (touch_at(c, t)) first = t;
  }
  return first;
}

}  // namespace sscc::ccd
