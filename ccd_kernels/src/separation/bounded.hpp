// A double with a proven bound on its distance from the exact real value it stands for.
//
// Invariant: |exact - value| <= error. Every operation keeps it, under IEEE 754 binary64
// round-to-nearest, for finite values:
// - an operation's rounding is at most u |r| / (1 - u) for its rounded result r (u = 2^-53),
//   and a product that underflows adds at most 2^-1075 absolutely (sums never do);
// - the error terms are themselves summed in floating point, which loses at most a
//   relative k u for k roundings; each new error is therefore multiplied by 1 + 2^-48
//   (covering k up to 30), and the result's own rounding is counted as 2u |r|.
// Overflow gives an infinite or NaN value or error; every sign test below then answers
// "unknown", so a caller falls back to exact arithmetic rather than deciding wrongly.
#pragma once

#include <cfloat>
#include <cmath>

namespace sscc::ccd::separation {

inline constexpr double kUnitRoundoff = 0x1p-53;
inline constexpr double kErrorSumSlack = 1.0 + 0x1p-48;
inline constexpr double kUnderflowError = DBL_MIN;  // generous cover for 2^-1075

struct Bounded {
  double value = 0.0;
  double error = 0.0;

  static Bounded exact(double x) { return {x, 0.0}; }
};

inline double rounding_of(double r) { return 2.0 * kUnitRoundoff * std::fabs(r); }

inline Bounded operator+(const Bounded& a, const Bounded& b) {
  const double r = a.value + b.value;
  return {r, (a.error + b.error + rounding_of(r)) * kErrorSumSlack};
}

inline Bounded operator-(const Bounded& a, const Bounded& b) {
  const double r = a.value - b.value;
  return {r, (a.error + b.error + rounding_of(r)) * kErrorSumSlack};
}

inline Bounded operator-(const Bounded& a) { return {-a.value, a.error}; }

inline Bounded operator*(const Bounded& a, const Bounded& b) {
  const double r = a.value * b.value;
  const double propagated = std::fabs(a.value) * b.error + std::fabs(b.value) * a.error + a.error * b.error;
  return {r, (propagated + rounding_of(r) + kUnderflowError) * kErrorSumSlack};
}

/// Multiplication by an exact power of two in [2^-8, 2^8] (0.5 for midpoints): exact
/// unless the result underflows.
inline Bounded scaled(const Bounded& a, double power_of_two) {
  return {a.value * power_of_two, (a.error * power_of_two + kUnderflowError) * kErrorSumSlack};
}

/// Division by a positive exact double.
inline Bounded divided(const Bounded& a, double d) {
  const double r = a.value / d;
  return {r, (a.error / d + rounding_of(r) + kUnderflowError) * kErrorSumSlack};
}

/// +1 or -1 when the exact value's sign is certain, 0 when it is not.
inline int certain_sign(const Bounded& a) {
  if (a.value > a.error) return 1;
  if (-a.value > a.error) return -1;
  return 0;
}

}  // namespace sscc::ccd::separation
