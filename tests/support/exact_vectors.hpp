// Exact rational 3-vectors (GMP) for the tests that hold floating-point predicates against
// exact arithmetic on the same doubles: conversion, the vector operations, and the exact
// Bernstein coefficients of a moving triangle's normal (query/normal_cone.hpp).
#pragma once

#include <gmpxx.h>

#include <Eigen/Core>

#include <array>

namespace sscc::test {

using Exact3 = std::array<mpq_class, 3>;

inline Exact3 exact(const Eigen::Vector3d& x) { return {mpq_class(x.x()), mpq_class(x.y()), mpq_class(x.z())}; }
inline Exact3 minus(const Exact3& a, const Exact3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Exact3 cross(const Exact3& a, const Exact3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline mpq_class dot(const Exact3& a, const Exact3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
/// a + t (b - a).
inline Exact3 lerp(const Exact3& a, const Exact3& b, const mpq_class& t) {
  return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

/// The exact Bernstein coefficients N0, N1, N2 of the normal (b - a) x (c - a) of a triangle
/// moving linearly from (a0, b0, c0) to (a1, b1, c1): N1 is half the mixed cross products' sum.
inline std::array<Exact3, 3> exact_normal_coefficients(const Eigen::Vector3d& a0, const Eigen::Vector3d& b0,
                                                       const Eigen::Vector3d& c0, const Eigen::Vector3d& a1,
                                                       const Eigen::Vector3d& b1, const Eigen::Vector3d& c1) {
  const Exact3 e1_0 = minus(exact(b0), exact(a0)), e2_0 = minus(exact(c0), exact(a0));
  const Exact3 e1_1 = minus(exact(b1), exact(a1)), e2_1 = minus(exact(c1), exact(a1));
  const Exact3 m01 = cross(e1_0, e2_1), m10 = cross(e1_1, e2_0);
  return {cross(e1_0, e2_0), Exact3{(m01[0] + m10[0]) / 2, (m01[1] + m10[1]) / 2, (m01[2] + m10[2]) / 2},
          cross(e1_1, e2_1)};
}

}  // namespace sscc::test
