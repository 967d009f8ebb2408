#include "exact/projected_decider.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <vector>

#include "exact/dyadic_root.hpp"

namespace sscc::ccd {

namespace {

using exact_stage::DyadicRoot;
using exact_stage::IntegerPolynomial;
using PolyVec3 = std::array<IntegerPolynomial, 3>;

/// The motion's coordinates as integers: each double is m 2^e with an integer |m| < 2^53,
/// so multiplying all of them by 2^-(smallest e) makes every one an integer, exactly.
/// Contact does not change under a common positive scaling.
std::array<PolyVec3, 4> integer_trajectories(const FourPointMotion& motion) {
  int smallest = INT_MAX;
  const auto exponent_of = [](double x) {
    int e = 0;
    std::frexp(x, &e);  // x = f 2^e, f in [0.5, 1): m = f 2^53 is an integer
    return e - 53;
  };
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 3; ++k) {
      if (motion.t0[i][k] != 0.0) smallest = std::min(smallest, exponent_of(motion.t0[i][k]));
      if (motion.t1[i][k] != 0.0) smallest = std::min(smallest, exponent_of(motion.t1[i][k]));
    }
  }
  const auto to_integer = [&](double x) {
    mpz_class n;
    if (x == 0.0) return n;
    const int e = exponent_of(x);
    int unused = 0;
    n = static_cast<long>(std::ldexp(std::frexp(x, &unused), 53));
    mpz_mul_2exp(n.get_mpz_t(), n.get_mpz_t(), static_cast<unsigned long>(e - smallest));
    return n;
  };
  std::array<PolyVec3, 4> x;
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 3; ++k) {
      const mpz_class start = to_integer(motion.t0[i][k]);
      x[i][k].c[0] = start;
      x[i][k].c[1] = to_integer(motion.t1[i][k]) - start;
      x[i][k].trim();
    }
  }
  return x;
}

PolyVec3 operator-(const PolyVec3& a, const PolyVec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

PolyVec3 cross(const PolyVec3& a, const PolyVec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// 2D dot product of x and y in the coordinate plane that drops `axis`.
IntegerPolynomial planar_dot(const PolyVec3& x, const PolyVec3& y, int axis) {
  const int i = (axis + 1) % 3;
  const int j = (axis + 2) % 3;
  return x[i] * y[i] + x[j] * y[j];
}

/// The sign conditions of contact in one coordinate plane.
struct PlaneConditions {
  std::vector<IntegerPolynomial> orientations;  // see four_point_motion.hpp for their order
  std::vector<IntegerPolynomial> between;       // <= 0 when a point lies between two others
};

struct Conditions {
  PrimitivePair pair;
  IntegerPolynomial coplanarity;
  std::array<PlaneConditions, 3> planes;
};

Conditions build_conditions(const FourPointMotion& motion) {
  const std::array<PolyVec3, 4> x = integer_trajectories(motion);
  const PolyVec3 e1 = x[1] - x[0];
  const PolyVec3 e2 = x[2] - x[0];
  const PolyVec3 e3 = x[3] - x[0];
  const PolyVec3 k12 = cross(e1, e2);
  const PolyVec3 k13 = cross(e1, e3);
  const PolyVec3 k23 = cross(e2, e3);
  Conditions c{motion.pair, k12[0] * e3[0] + k12[1] * e3[1] + k12[2] * e3[2], {}};
  for (int k = 0; k < 3; ++k) {
    PlaneConditions& plane = c.planes[k];
    const IntegerPolynomial mixed = k12[k] + k23[k] - k13[k];
    // "p between q and r" on a line: (p - q) . (p - r) <= 0.
    const auto between = [&](int p, int q, int r) { return planar_dot(x[p] - x[q], x[p] - x[r], k); };
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

bool any_between(const PlaneConditions& plane, DyadicRoot& t) {
  for (const IntegerPolynomial& b : plane.between) {
    if (exact_stage::sign_at_root(b, t) <= 0) return true;
  }
  return false;
}

bool touch_in_plane(PrimitivePair pair, const PlaneConditions& plane, DyadicRoot& t) {
  int s[4] = {0, 0, 0, 0};
  bool all_zero = true;
  for (std::size_t i = 0; i < plane.orientations.size(); ++i) {
    s[i] = exact_stage::sign_at_root(plane.orientations[i], t);
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

bool touch_at(const Conditions& c, DyadicRoot& t) {
  for (const PlaneConditions& plane : c.planes) {
    if (!touch_in_plane(c.pair, plane, t)) return false;
  }
  return true;
}

std::optional<DyadicRoot> first_contact_root(const Conditions& c) {
  if (!c.coplanarity.is_zero()) {
    // Contact needs coplanarity, so it can only happen at the cubic's roots, which come
    // in increasing order: the first that touches is the answer.
    for (DyadicRoot& t : exact_stage::roots_in_unit_interval(c.coplanarity)) {
      if (touch_at(c, t)) return t;
    }
    return std::nullopt;
  }
  // Motion that stays coplanar: contact at the start settles it (the common case of
  // resting contact) before any root is isolated.
  DyadicRoot start = exact_stage::exact_root({0, 0});
  if (touch_at(c, start)) return start;
  // Each distinct polynomial once (up to sign and scale, the same roots): projections onto
  // planes the motion is perpendicular to repeat one another.
  std::vector<IntegerPolynomial> distinct;
  for (const PlaneConditions& plane : c.planes) {
    for (const auto* list : {&plane.orientations, &plane.between}) {
      for (const IntegerPolynomial& p : *list) {
        if (p.degree <= 0) continue;
        const IntegerPolynomial q = exact_stage::primitive_positive(p);
        if (std::none_of(distinct.begin(), distinct.end(), [&](const IntegerPolynomial& d) { return d == q; })) {
          distinct.push_back(q);
        }
      }
    }
  }
  std::vector<DyadicRoot> candidates;
  for (const IntegerPolynomial& p : distinct) {
    for (DyadicRoot& r : exact_stage::roots_in_unit_interval(p)) candidates.push_back(std::move(r));
  }
  std::optional<DyadicRoot> first;
  for (DyadicRoot& t : candidates) {
    if (first && exact_stage::compare(t, *first) >= 0) continue;
    if (touch_at(c, t)) first = t;
  }
  return first;
}

}  // namespace

std::optional<double> exact_first_contact(const FourPointMotion& motion, double toi_tolerance) {
  std::optional<DyadicRoot> first = first_contact_root(build_conditions(motion));
  if (!first) return std::nullopt;
  return exact_stage::lower_bound_within(*first, toi_tolerance);
}

}  // namespace sscc::ccd
