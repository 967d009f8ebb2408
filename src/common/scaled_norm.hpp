// The 2-norm of a sequence scaled by its largest magnitude, as Eigen's stableNorm: a plain sum
// of squares underflows to 0 for entries near 1e-154 and below, and a bound built on it (a box's
// growth rate, a cone's radius) would then ignore motions that coordinates near 1e154 make
// real. Private to the library.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sscc::detail {

/// sqrt(value(0)^2 + ... + value(count - 1)^2), within (count + 4) units of roundoff relative
/// (plus an absolute error near 2^-1074 when the result is subnormal); value(k) is called twice.
template <typename Value>
double scaled_norm(int count, Value value) {
  double largest = 0.0;
  for (int k = 0; k < count; ++k) largest = std::max(largest, std::abs(value(k)));
  if (!(largest > 0.0) || !std::isfinite(largest)) return largest;
  double sum = 0.0;
  for (int k = 0; k < count; ++k) {
    const double scaled = value(k) / largest;
    sum += scaled * scaled;
  }
  return largest * std::sqrt(sum);
}

/// sqrt(x^2 + y^2 + z^2) for hot loops: the plain sum of squares when the largest magnitude
/// lies within 2^-450..2^450 (no square can then overflow, and squares that underflow add
/// errors below 2^-1074 to a sum of at least 2^-900: within a few units of roundoff, as
/// scaled_norm), else scaled_norm.
inline double length3(double x, double y, double z) {
  const double largest = std::max({std::abs(x), std::abs(y), std::abs(z)});
  if (largest >= 0x1p-450 && largest <= 0x1p450) return std::sqrt(x * x + y * y + z * z);
  const double v[3] = {x, y, z};
  return scaled_norm(3, [&](int k) { return v[k]; });
}

/// v.stableNorm() as Eigen 3.4 computes it for a vector aligned to its packets (one block:
/// the largest magnitude m, then m sqrt of the sum of (v_i (1 / m))^2 in index order), inline
/// and the same wherever v lies: stableNorm splits a vector at another address into two
/// blocks, with other roundings. Where m is not a normal number stableNorm answers, on an
/// aligned copy. Bit for bit with Eigen's 16-byte packets and no FMA contraction (the project's
/// baseline x86-64 build, and its AVX2 clones: Eigen picks its packets at compile time). The
/// precomputation's 1D bound calls it for every pair it screens (the call was a few percent
/// of its time), and its certificate files stay the same only while the values do.
inline double stable_norm3(const Eigen::Vector3d& v) {
  const double largest = v.cwiseAbs().maxCoeff();
  if (!(largest >= std::numeric_limits<double>::min() && largest <= std::numeric_limits<double>::max())) {
    alignas(64) double copy[3] = {v[0], v[1], v[2]};
    return Eigen::Map<const Eigen::Vector3d, Eigen::AlignedMax>(copy).stableNorm();
  }
  const double inverse = 1.0 / largest;
  const double x = v[0] * inverse, y = v[1] * inverse, z = v[2] * inverse;
  return largest * std::sqrt((x * x + y * y) + z * z);
}

}  // namespace sscc::detail
