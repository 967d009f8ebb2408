#include "exact/projected_decider.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <vector>

#include "exact/dyadic_root.hpp"

namespace sscc::ccd {

namespace {

using exact_stage::DyadicRoot;
using exact_stage::FixedInt;
using exact_stage::get_d_2exp;
using exact_stage::IntegerPolynomial;
template <class Int>
using PolyVec3 = std::array<IntegerPolynomial<Int>, 3>;

/// A non-zero double as m 2^e with an odd integer m (|m| < 2^53).
struct OddMantissa {
  long m;
  int e;
};
OddMantissa odd_mantissa(double x) {
  int e = 0;
  // x = f 2^e with f in [0.5, 1): f 2^53 is an integer; its trailing zeros go to e.
  long m = static_cast<long>(std::ldexp(std::frexp(x, &e), 53));
  const int zeros = __builtin_ctzl(static_cast<unsigned long>(m));
  return {m >> zeros, e - 53 + zeros};
}

/// The motion's coordinates as integers: each double is m 2^e with an odd integer m, so
/// multiplying all coordinates along one axis by 2^-(their smallest e) makes every one an
/// integer, exactly, and the smallest they can be (grid coordinates stay a few bits wide).
/// Contact does not change under a positive scaling of each axis (an invertible linear map
/// maps triangles, segments and linear motions to the same, and keeps their intersections),
/// so a tiny offset along one axis (a subnormal z on an otherwise flat query) does not
/// widen the integers of the others.
template <class Int>
std::array<PolyVec3<Int>, 4> integer_trajectories(const FourPointMotion& motion) {
  int smallest[3] = {INT_MAX, INT_MAX, INT_MAX};
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 3; ++k) {
      if (motion.t0[i][k] != 0.0) smallest[k] = std::min(smallest[k], odd_mantissa(motion.t0[i][k]).e);
      if (motion.t1[i][k] != 0.0) smallest[k] = std::min(smallest[k], odd_mantissa(motion.t1[i][k]).e);
    }
  }
  const auto to_integer = [&](double x, int k) {
    if (x == 0.0) return Int(0);
    const OddMantissa odd = odd_mantissa(x);
    return Int(Int(odd.m) << static_cast<unsigned long>(odd.e - smallest[k]));
  };
  std::array<PolyVec3<Int>, 4> x;
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 3; ++k) {
      const Int start = to_integer(motion.t0[i][k], k);
      x[i][k].c[0] = start;
      x[i][k].c[1] = to_integer(motion.t1[i][k], k) - start;
      x[i][k].trim();
    }
  }
  return x;
}

template <class Int>
PolyVec3<Int> operator-(const PolyVec3<Int>& a, const PolyVec3<Int>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

template <class Int>
PolyVec3<Int> cross(const PolyVec3<Int>& a, const PolyVec3<Int>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// 2D dot product of x and y in the coordinate plane that drops `axis`.
template <class Int>
IntegerPolynomial<Int> planar_dot(const PolyVec3<Int>& x, const PolyVec3<Int>& y, int axis) {
  const int i = (axis + 1) % 3;
  const int j = (axis + 2) % 3;
  return x[i] * y[i] + x[j] * y[j];
}

/// The sign conditions of contact in one coordinate plane.
template <class Int>
struct PlaneConditions {
  std::vector<IntegerPolynomial<Int>> orientations;  // see four_point_motion.hpp for their order
};

template <class Int>
struct Conditions {
  PrimitivePair pair;
  std::array<PolyVec3<Int>, 4> x;  ///< the trajectories, for between_conditions
  IntegerPolynomial<Int> coplanarity;
  std::array<PlaneConditions<Int>, 3> planes;
  /// The primitives' normal: the triangle's (vertex-face) or edge a x edge b (edge-edge).
  PolyVec3<Int> normal;
  /// Axes by decreasing size of the normal's component at the ends of the step: only an
  /// order of trial.
  std::array<int, 3> plane_order;
};

/// The axes by decreasing bit length of the normal's components at t = 0 and t = 1.
template <class Int>
std::array<int, 3> plane_order(const PolyVec3<Int>& normal) {
  long size[3] = {0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    const std::array<Int, exact_stage::kMaxDegree + 1>& c = normal[k].c;
    for (const Int& value : {c[0], Int(c[0] + c[1] + c[2] + c[3])}) {
      long bits = 0;
      get_d_2exp(bits, value);  // the bit length of |value| (0 for zero)
      size[k] = std::max(size[k], bits);
    }
  }
  std::array<int, 3> order = {0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int a, int b) { return size[a] > size[b]; });
  return order;
}

/// In the coordinate plane that drops axis k, polynomials <= 0 where a point lies between
/// two others on their line. Only planes whose orientations all vanish need them, so they
/// are built on demand.
template <class Int>
std::vector<IntegerPolynomial<Int>> between_conditions(const Conditions<Int>& c, int k) {
  // "p between q and r" on a line: (p - q) . (p - r) <= 0.
  const auto between = [&](int p, int q, int r) { return planar_dot(c.x[p] - c.x[q], c.x[p] - c.x[r], k); };
  if (c.pair == PrimitivePair::kVertexFace) return {between(3, 0, 1), between(3, 1, 2), between(3, 2, 0)};
  return {between(2, 0, 1), between(3, 0, 1), between(0, 2, 3), between(1, 2, 3)};
}

template <class Int>
Conditions<Int> build_conditions(const FourPointMotion& motion) {
  Conditions<Int> c{motion.pair, integer_trajectories<Int>(motion), {}, {}, {}, {0, 1, 2}};
  const std::array<PolyVec3<Int>, 4>& x = c.x;
  const PolyVec3<Int> e1 = x[1] - x[0];
  const PolyVec3<Int> e2 = x[2] - x[0];
  const PolyVec3<Int> e3 = x[3] - x[0];
  const PolyVec3<Int> k12 = cross(e1, e2);
  const PolyVec3<Int> k13 = cross(e1, e3);
  const PolyVec3<Int> k23 = cross(e2, e3);
  c.coplanarity = k12[0] * e3[0] + k12[1] * e3[1] + k12[2] * e3[2];
  c.normal = motion.pair == PrimitivePair::kVertexFace ? k12 : k13 - k12;  // e1 x (e3 - e2) for edge-edge
  c.plane_order = plane_order(c.normal);
  for (int k = 0; k < 3; ++k) {
    PlaneConditions<Int>& plane = c.planes[k];
    const IntegerPolynomial<Int> mixed = k12[k] + k23[k] - k13[k];
    if (motion.pair == PrimitivePair::kVertexFace) {
      plane.orientations = {k13[k], mixed, -k23[k]};
    } else {
      plane.orientations = {k12[k], k13[k], k23[k], mixed};
    }
  }
  return c;
}

template <class Int>
bool any_between(const Conditions<Int>& c, int k, DyadicRoot<Int>& t) {
  for (const IntegerPolynomial<Int>& b : between_conditions(c, k)) {
    if (exact_stage::sign_at_root(b, t) <= 0) return true;
  }
  return false;
}

template <class Int>
bool touch_in_plane(const Conditions<Int>& c, int k, DyadicRoot<Int>& t) {
  const PlaneConditions<Int>& plane = c.planes[k];
  // Signs in order, stopping as soon as they separate the primitives in this plane.
  int s[4] = {0, 0, 0, 0};
  const auto sign = [&](int i) { return s[i] = exact_stage::sign_at_root(plane.orientations[i], t); };
  if (c.pair == PrimitivePair::kVertexFace) {
    bool has_positive = false;
    bool has_negative = false;
    for (int i = 0; i < 3; ++i) {
      const int si = sign(i);
      has_positive = has_positive || si > 0;
      has_negative = has_negative || si < 0;
      if (has_positive && has_negative) return false;
    }
  } else {
    if (sign(0) * sign(1) > 0) return false;
    if (sign(2) * sign(3) > 0) return false;
  }
  const bool all_zero = s[0] == 0 && s[1] == 0 && s[2] == 0 && s[3] == 0;
  return all_zero ? any_between(c, k, t) : true;  // all zero: everything on one line in this plane
}

template <class Int>
bool touch_at(const Conditions<Int>& c, DyadicRoot<Int>& t) {
  // A plane whose axis the normal is not perpendicular to projects the primitives' common
  // plane one-to-one (the four points are coplanar at t), so its test alone decides.
  for (int k : c.plane_order) {
    if (exact_stage::sign_at_root(c.normal[k], t) != 0) return touch_in_plane(c, k, t);
  }
  // Degenerate primitives or parallel edges: every projection is a necessary condition,
  // and together they are sufficient.
  for (int k = 0; k < 3; ++k) {
    if (!touch_in_plane(c, k, t)) return false;
  }
  return true;
}

template <class Int>
std::optional<DyadicRoot<Int>> first_contact_root(const Conditions<Int>& c) {
  if (!c.coplanarity.is_zero()) {
    // Contact needs coplanarity, so it can only happen at the cubic's roots, which come
    // in increasing order: the first that touches is the answer.
    for (DyadicRoot<Int>& t : exact_stage::roots_in_unit_interval(c.coplanarity)) {
      if (touch_at(c, t)) return t;
    }
    return std::nullopt;
  }
  // Motion that stays coplanar: contact at the start settles it (the common case of
  // resting contact) before any root is isolated.
  DyadicRoot<Int> start = exact_stage::exact_root(exact_stage::Dyadic<Int>{0, 0});
  if (touch_at(c, start)) return start;
  // Where one projection is one-to-one on the common plane over the whole step (the
  // normal's component along its axis never vanishes in [0, 1]), contact is that plane's
  // test alone, on its orientations alone (they cannot all vanish there), so the contact
  // set can only begin at their roots.
  int one_to_one = -1;
  for (int k : c.plane_order) {
    if (!c.normal[k].is_zero() && exact_stage::roots_in_unit_interval(c.normal[k]).empty()) {
      one_to_one = k;
      break;
    }
  }
  // Each distinct polynomial once (up to sign and scale, the same roots): projections onto
  // planes the motion is perpendicular to repeat one another.
  std::vector<IntegerPolynomial<Int>> distinct;
  for (int k = 0; k < 3; ++k) {
    if (one_to_one >= 0 && k != one_to_one) continue;
    const std::vector<IntegerPolynomial<Int>> between =
        one_to_one >= 0 ? std::vector<IntegerPolynomial<Int>>() : between_conditions(c, k);
    for (const auto* list : {&c.planes[k].orientations, &between}) {
      for (const IntegerPolynomial<Int>& p : *list) {
        if (p.degree <= 0) continue;
        const IntegerPolynomial<Int> q = exact_stage::primitive_positive(p);
        if (std::none_of(distinct.begin(), distinct.end(), [&](const IntegerPolynomial<Int>& d) { return d == q; })) {
          distinct.push_back(q);
        }
      }
    }
  }
  std::vector<DyadicRoot<Int>> candidates;
  for (const IntegerPolynomial<Int>& p : distinct) {
    for (DyadicRoot<Int>& r : exact_stage::roots_in_unit_interval(p)) candidates.push_back(std::move(r));
  }
  std::optional<DyadicRoot<Int>> first;
  for (DyadicRoot<Int>& t : candidates) {
    if (first && exact_stage::compare(t, *first) >= 0) continue;
    if (touch_at(c, t)) first = t;
  }
  return first;
}

template <class Int>
std::optional<double> first_contact(const FourPointMotion& motion, double toi_tolerance) {
  std::optional<DyadicRoot<Int>> first = first_contact_root(build_conditions<Int>(motion));
  if (!first) return std::nullopt;
  return exact_stage::lower_bound_within(*first, toi_tolerance);
}

}  // namespace

std::optional<double> exact_first_contact(const FourPointMotion& motion, double toi_tolerance) {
  // Fixed-size integers decide most queries without allocating; the few whose numbers
  // outgrow them (exponents far apart, roots separated only deep down) start over unbounded.
  try {
    return first_contact<FixedInt>(motion, toi_tolerance);
  } catch (const exact_stage::FixedIntOverflow&) {
    return first_contact<mpz_class>(motion, toi_tolerance);
  }
}

}  // namespace sscc::ccd
