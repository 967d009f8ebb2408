// Certified signs of d . n(t) for the normal n(t) = (b - a)(t) x (c - a)(t) of a triangle whose
// vertices move linearly over t in [0, 1]: the predicate under the normal-cone cull
// (query/patch_cull.hpp). Private to the library.
//
// n(t) is quadratic in t with Bernstein coefficients
//   N0 = e1(0) x e2(0),  N1 = (e1(0) x e2(1) + e1(1) x e2(0)) / 2,  N2 = e1(1) x e2(1)
// (e1 = b - a, e2 = c - a), so d . n(t) = sum_k B_k(t) d . N_k with B_k >= 0 summing to 1:
// d . N_k > 0 for k = 0, 1, 2 implies d . n(t) > 0 for every t in [0, 1] (for the fixed d).
//
// Guarantee: certainly_positive() returns true only if d . N_k > 0 holds for the N_k of the
// positions exactly as given (doubles), whatever the rounding of the computation. d itself
// needs no exactness: it is whatever double vector is passed. Error analysis (u = 2^-53,
// gamma_k = k u / (1 - k u), standard model fl(x op y) = (x op y)(1 + delta), |delta| <= u):
// - e = fl(b - a) = (b - a)(1 + delta): one rounding relative to the exact difference.
// - A component of N0 or N2, fl(fl(e1_j e2_k) - fl(e1_k e2_j)), carries at most 4 roundings
//   per term relative to the exact differences' products (two differences, product,
//   subtraction); of N1 at most 5 (one more addition; halving is exact). So
//   |N_computed,i - N_exact,i| <= gamma_5 P_exact,i with P_i the sum of the absolute values
//   of the component's products. P computed from the computed differences in floating point
//   (at most 4 roundings, all terms non-negative) underestimates P_exact by at most a factor
//   (1 - u)^6, so the bound is <= 5.0001 u P_i.
// - fl(d . N_computed) differs from d . N_computed by <= gamma_3 sum |d_i| |N_computed,i|
//   <= 3.001 u sum |d_i| P_i.
// Together |fl(d . N_computed) - d . N_exact| <= 8.01 u sum_i |d_i| P_i. The stored error is
// kErrorFactor u P_i with kErrorFactor = 16 (a power of two: the scaling is exact); the
// test sum |d_i| err_i, computed with 3 roundings of non-negative terms, is then still above
// 8.01 u sum |d_i| P_i. Underflow: every rounding above may instead make an absolute error of
// at most 2^-1074 per operation when a result is subnormal; kUnderflowAllowance covers a few
// dozen of those for |d_i| <= 1 (callers pass unit-length d). Overflow gives infinities or
// NaN, for which no comparison below is true: never certified.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

#include <array>
#include <cmath>

namespace sscc::detail {

/// 2^-53, the unit roundoff of doubles.
inline constexpr double kUnitRoundoff = 0x1p-53;
/// Multiple of u times the absolute-value products that bounds every rounding error (header):
/// 8.01 is what the analysis needs, 16 leaves a factor 2. Smaller than 8.01 could certify a
/// sign rounding made up; larger only certifies fewer near-degenerate triangles.
inline constexpr double kErrorFactor = 16.0;
/// Absolute allowance for subnormal rounding (each such rounding errs by at most 2^-1074 =
/// 4.9e-324). Only triangles with products below ~1e-290 are affected.
inline constexpr double kUnderflowAllowance = 1e-300;

/// A quadratic's Bernstein coefficient vectors N0, N1, N2 as computed, each with a
/// componentwise bound on its distance from the exact one.
struct BernsteinNormals {
  std::array<Eigen::Vector3d, 3> value;
  std::array<Eigen::Vector3d, 3> error;
};

/// The normal's Bernstein coefficients of triangle (a, b, c) moving linearly from the
/// positions at t = 0 (a0, b0, c0) to those at t = 1 (a1, b1, c1).
BernsteinNormals bernstein_normals(const Eigen::Vector3d& a0, const Eigen::Vector3d& b0, const Eigen::Vector3d& c0,
                                   const Eigen::Vector3d& a1, const Eigen::Vector3d& b1, const Eigen::Vector3d& c1);

/// Whether d . N is certainly positive for the exact N that `value` and `error` bound.
inline bool certainly_positive(const Eigen::Vector3d& d, const Eigen::Vector3d& value, const Eigen::Vector3d& error) {
  const double dot = d.dot(value);
  const double bound = std::abs(d.x()) * error.x() + std::abs(d.y()) * error.y() + std::abs(d.z()) * error.z();
  return dot > bound;
}

/// Whether d . n(t) > 0 for every t in [0, 1] (d of length at most 1 per component).
inline bool certainly_positive(const Eigen::Vector3d& d, const BernsteinNormals& n) {
  return certainly_positive(d, n.value[0], n.error[0]) && certainly_positive(d, n.value[2], n.error[2]) &&
         certainly_positive(d, n.value[1], n.error[1]);
}

/// The certified sign of d . ((a - p) x (b - p)) for points given exactly: +1 or -1 when
/// certain, 0 when rounding could change it (or it is 0).
int certified_orientation(const Eigen::Vector3d& d, const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                          const Eigen::Vector3d& b);

/// The certified sign of d . (w x v) for a vector w given exactly and v = fl(p - c) for
/// doubles p, c: +1 or -1 when certain, 0 when rounding could change it.
int certified_sign_of_triple(const Eigen::Vector3d& d, const Eigen::Vector3d& w, const Eigen::Vector3d& p,
                             const Eigen::Vector3d& c);

}  // namespace sscc::detail

namespace sscc::detail {

/// Slack added to every angle computed in floating point below (radians). Each computed angle
/// is an atan2(y, x), or an atan of the rounded quotient y / x (one more rounding: at most u/2
/// radians), whose arguments err by at most a few u times sqrt(x^2 + y^2) (cross products'
/// norms, dot products and error bounds of vectors; normalisation), so it is within 1e-14 of
/// the angle of the exact arguments (atan and atan2 themselves err by an ulp). 1e-9 leaves five
/// orders of magnitude; smaller than 1e-14 could certify a cone rounding made up, larger
/// only gives up cones within 1e-9 of 90 degrees.
inline constexpr double kAngleSlack = 1e-9;

/// A cone of directions: every vector it holds makes an angle of at most half_angle with
/// axis (a unit vector as computed; the bound is about that double vector).
struct NormalCone {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  double half_angle = 4.0;  ///< above pi: holds everything (an empty or unknown cone)
  /// Whether every vector held has a strictly positive dot product with the axis.
  bool within_half_space() const { return half_angle < 0.5 * M_PI - kAngleSlack; }
};

/// The angle between two vectors, from atan2 (accurate near 0 and pi, unlike acos).
double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

/// A cone about `axis` (normalised here) holding the exact coefficients N0, N1, N2 of every
/// triangle in [begin, end); the whole space when one may point away from the axis.
NormalCone cone_of(const Eigen::Vector3d& axis, const BernsteinNormals* begin, const BernsteinNormals* end);

/// A cone about `axis` (normalised here) holding the cones given (each axis's angle to it plus
/// its half-angle, with slack).
NormalCone merged_cone(const Eigen::Vector3d& axis, const NormalCone* begin, const NormalCone* end);

}  // namespace sscc::detail
