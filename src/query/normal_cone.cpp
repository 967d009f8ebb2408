#include "query/normal_cone.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/scaled_norm.hpp"

namespace sscc::detail {

namespace {

using Eigen::Vector3d;

/// The cross product e x f and, per component, the sum of the absolute values of its two
/// products.
struct CrossWithMagnitude {
  Vector3d value, magnitude;
};

CrossWithMagnitude cross_with_magnitude(const Vector3d& e, const Vector3d& f) {
  const Vector3d ae = e.cwiseAbs();
  const Vector3d af = f.cwiseAbs();
  return {e.cross(f), Vector3d(ae.y() * af.z() + ae.z() * af.y(), ae.z() * af.x() + ae.x() * af.z(),
                               ae.x() * af.y() + ae.y() * af.x())};
}

/// The error bound of a coefficient whose products sum (in absolute value) to `magnitude`.
Vector3d error_of(const Vector3d& magnitude) {
  return (kErrorFactor * kUnitRoundoff * magnitude).array() + kUnderflowAllowance;
}

/// The certified sign of d . (e x f) from the cross product and its magnitudes.
int certified_sign(const Vector3d& d, const CrossWithMagnitude& cross) {
  const Vector3d error = error_of(cross.magnitude);
  if (certainly_positive(d, cross.value, error)) return 1;
  if (certainly_positive(-d, cross.value, error)) return -1;
  return 0;
}

}  // namespace

BernsteinNormals bernstein_normals(const Vector3d& a0, const Vector3d& b0, const Vector3d& c0, const Vector3d& a1,
                                   const Vector3d& b1, const Vector3d& c1) {
  const Vector3d e1_0 = b0 - a0, e2_0 = c0 - a0;
  const Vector3d e1_1 = b1 - a1, e2_1 = c1 - a1;
  const CrossWithMagnitude n0 = cross_with_magnitude(e1_0, e2_0);
  const CrossWithMagnitude n2 = cross_with_magnitude(e1_1, e2_1);
  const CrossWithMagnitude mixed_01 = cross_with_magnitude(e1_0, e2_1);
  const CrossWithMagnitude mixed_10 = cross_with_magnitude(e1_1, e2_0);
  BernsteinNormals n;
  n.value[0] = n0.value;
  n.value[1] = 0.5 * (mixed_01.value + mixed_10.value);
  n.value[2] = n2.value;
  n.error[0] = error_of(n0.magnitude);
  n.error[1] = error_of(0.5 * (mixed_01.magnitude + mixed_10.magnitude));
  n.error[2] = error_of(n2.magnitude);
  return n;
}

int certified_orientation(const Vector3d& d, const Vector3d& p, const Vector3d& a, const Vector3d& b) {
  return certified_sign(d, cross_with_magnitude(a - p, b - p));  // N0 of a triangle at rest
}

int certified_sign_of_triple(const Vector3d& d, const Vector3d& w, const Vector3d& p, const Vector3d& c) {
  return certified_sign(d, cross_with_magnitude(w, p - c));
}

}  // namespace sscc::detail

namespace sscc::detail {

namespace {

/// Coefficients whose angle to the axis has a tangent above this (within 2^-900 radians of
/// perpendicular) give no cone: such a cone would not fit in a half-space anyway, and the
/// tangent's quotient stays finite below it (the test scales `across` down by a power of two,
/// which cannot overflow).
constexpr double kSteepestTangent = 0x1p900;

/// |v| without the underflow or overflow of a plain sum of squares (common/scaled_norm.hpp):
/// coefficient vectors of triangles with coordinates near 1e-80 have entries whose squares
/// vanish, and a cone's widths and error bounds computed from them came out too narrow.
double length(const Eigen::Vector3d& v) { return length3(v.x(), v.y(), v.z()); }

bool normalised(const Eigen::Vector3d& v, Eigen::Vector3d& out) {
  // Below the smallest normal double the scaled norm is no longer within a few units of
  // roundoff (a subnormal axis could come out up to sqrt(2) long), and the cones' error terms
  // assume a unit axis: such axes give no cone.
  const double size = length(v);
  if (!(size >= std::numeric_limits<double>::min()) || !std::isfinite(size)) return false;
  out = v / size;
  return true;
}

}  // namespace

double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(length(a.cross(b)), a.dot(b));
}

NormalCone cone_of(const Eigen::Vector3d& axis, const BernsteinNormals* begin, const BernsteinNormals* end) {
  // For an exact N within |E| of the computed one, |d x N| <= |d x N_c| + |E| and
  // d . N >= d . N_c - |E| (|d| = 1), so while the latter is positive the angle between d and
  // N is at most atan(tangent), tangent = (|d x N_c| + |E|) / (d . N_c - |E|). The largest
  // tangent is kept (one rounding each: an angle within an ulp of the largest). A quotient,
  // not products of the two sides: those of coefficients near 1e-160 underflow to 0 and
  // compared nothing.
  NormalCone cone;
  if (!normalised(axis, cone.axis)) return cone;
  double widest = 0.0;
  for (const BernsteinNormals* n = begin; n != end; ++n) {
    for (int k = 0; k < 3; ++k) {
      const double error = length(n->error[k]);
      const double along = cone.axis.dot(n->value[k]) - error;
      const double across = length(cone.axis.cross(n->value[k])) + error;
      // NaN fails too; so does a tangent above kSteepestTangent (the quotient stays finite).
      if (!(along > 0.0) || !(along > across * (1.0 / kSteepestTangent))) return cone;
      widest = std::max(widest, across / along);
    }
  }
  cone.half_angle = std::atan(widest) + kAngleSlack;
  return cone;
}

NormalCone merged_cone(const Eigen::Vector3d& axis, const NormalCone* begin, const NormalCone* end) {
  NormalCone cone;
  if (!normalised(axis, cone.axis)) return cone;
  double widest = 0.0;
  for (const NormalCone* part = begin; part != end; ++part) {
    widest = std::max(widest, angle_between(cone.axis, part->axis) + part->half_angle + kAngleSlack);
  }
  cone.half_angle = widest;
  return cone;
}

}  // namespace sscc::detail
