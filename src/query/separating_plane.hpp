// A moving triangle's own plane as a separating plane over a time step: when every vertex of
// triangle B stays strictly on one side of triangle A's plane for every t in [0, 1], the two
// never touch. The triangle-pair cull of the normal-cone queries (self_ccd.cpp), tested
// before the features' kernels. Private to the library.
//
// For a point p and a triangle (a, b, c), all moving linearly, f(t) = (p - a)(t) . n(t) with
// n the normal of normal_cone.hpp (Bernstein coefficients N0, N1, N2) is a cubic: with D0, D1
// the coefficients of (p - a)(t), the product of a linear and a quadratic polynomial in
// Bernstein form has the coefficients
//   F0 = D0.N0,  F1 = (2 D0.N1 + D1.N0) / 3,  F2 = (D0.N2 + 2 D1.N1) / 3,  F3 = D1.N2.
// The Bernstein basis is non-negative and sums to 1, so four coefficients of one strict sign
// give f that sign on all of [0, 1] (and n(t) != 0 there).
//
// GUARANTEE (conservative, exact for the positions as given): plane_separates() returns
// true only if, for the doubles passed, every vertex of B has one strict sign of f at every t.
// Then every point of B(t), a convex combination of its vertices, has (x - a) . n(t) of that
// sign, while every point of A(t) has 0: A and B never touch, nor does any feature of one
// touch any feature of the other. It proves no distance: queries with a minimum separation
// do not use it.
//
// ERROR ANALYSIS (u = 2^-53). bernstein_normals gives computed N^_k with componentwise bounds
// E_k >= |N^_k - N_k| (E_k >= 16 u P_k + 1e-300, P_k the products' absolute sum, which bounds
// |N^_k| within a factor 1.0001). D^ = fl(p - a) differs from the exact D by at most
// u/(1 - u) |D^| per component. So for a dot product x = D.N computed as x^ = fl(D^.N^):
//   |x^ - x| <= sum |D^_i| (E_i (1 + u) + (u/(1 - u) + gamma_3) |N^_i|) + 3 * 2^-1075
//            <= 1.26 sum |D^_i| E_i + 3 * 2^-1075
// (the second term is at most 4.01 u * 1.0001 P_i <= 0.251 E_i; the last covers subnormal
// products). Its bound is taken as B = fl(2 sum |D^_i| E_i) + kPlaneUnderflowAllowance, at least
// 1.99 sum |D^_i| E_i as computed (three roundings of non-negative terms) plus the allowance,
// which also covers subnormal roundings of that sum. The coefficients are formed without the
// division by 3: G1 = 2 x01 + x10 and G2 = x02 + 2 x11 (the x's the dots above, the doubling
// exact), one more rounding each, at most u (2 |x^01| + |x^10|) (1 + u), and u |x^| is at most
// u * 1.0002 sum |D^_i| P_i <= 0.063 sum |D^_i| E_i. So |G^1 - G1| <= 1.33 (2 S01 + S10) (S the
// E-sums) plus the subnormal terms, below the computed 2 B01 + B10 (rounded twice more, still
// >= 1.98 (2 S01 + S10) plus the allowances); likewise G2, F0 and F3 (a single dot each).
// Overflow: with every coordinate of the two triangles within kLargestPlaneCoordinate
// (within_plane_range), differences stay below 2^301, the normals' coefficients below 2^604
// and every dot product below 2^910: nothing overflows (nor raises the overflow flag). Past
// that range the pair is not tested.
#pragma once

#include <Eigen/Core>

#include <cmath>

#include "query/normal_cone.hpp"
#include "sscc/mesh/triangle_mesh.hpp"

namespace sscc::detail {

/// Absolute allowance of a dot product's bound for subnormal roundings (each at most 2^-1075;
/// a few per dot, and the E-sum's own): far above them, and far below any product of
/// coordinates the queries meet (1e-300 is about (1e-100)^3). Smaller than a few times 2^-1074
/// could certify a sign that underflow made up; larger only certifies fewer tiny triangles.
inline constexpr double kPlaneUnderflowAllowance = 1e-300;

/// The largest coordinate magnitude at which a pair is tested (header, overflow): 2^300. Larger
/// could overflow the cubic's products; smaller only tests fewer pairs of far-flung models.
inline constexpr double kLargestPlaneCoordinate = 0x1p300;

/// Whether every coordinate of triangles a and b, at both ends of the step, is within
/// kLargestPlaneCoordinate: the precondition of plane_separates. (A NaN coordinate may pass
/// here, cwiseMax ignoring it; every comparison of plane_separates then fails: no cull.)
inline bool within_plane_range(const Eigen::Vector3d* x0, const Eigen::Vector3d* x1, const Triangle& a,
                               const Triangle& b) {
  Eigen::Vector3d largest = Eigen::Vector3d::Zero();
  for (const Triangle* t : {&a, &b}) {
    for (const int v : *t) largest = largest.cwiseMax(x0[v].cwiseAbs()).cwiseMax(x1[v].cwiseAbs());
  }
  return largest.maxCoeff() <= kLargestPlaneCoordinate;
}

/// A dot product D.N of the cubic above, as computed, with its bound (header).
struct BoundedDot {
  double value, bound;
};

inline BoundedDot bounded_dot(const Eigen::Vector3d& d, const Eigen::Vector3d& value, const Eigen::Vector3d& error) {
#ifdef SSCC_MUTANT_PLANE_NO_BOUND
  return {d.dot(value), 0.0};
#endif
  return {d.dot(value),
          2.0 * (std::abs(d.x()) * error.x() + std::abs(d.y()) * error.y() + std::abs(d.z()) * error.z()) +
              kPlaneUnderflowAllowance};
}

/// +1 or -1 when g (as computed, with its bound) certainly has that sign; 0 otherwise.
inline int certain_sign_of(double g, double bound) {
  if (g > bound) return 1;
  if (-g > bound) return -1;
  return 0;
}

/// The certain sign of (p - a)(t) . n(t) on all of [0, 1] (+1 or -1), or 0: p moves from p0
/// to p1, the triangle's first vertex from a0 to a1, n its normal's coefficients.
inline int certain_side(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& a0,
                        const Eigen::Vector3d& a1, const BernsteinNormals& n) {
  const Eigen::Vector3d d0 = p0 - a0;
  const Eigen::Vector3d d1 = p1 - a1;
  const BoundedDot f0 = bounded_dot(d0, n.value[0], n.error[0]);
  const int sign = certain_sign_of(f0.value, f0.bound);
  if (sign == 0) return 0;
  const BoundedDot f3 = bounded_dot(d1, n.value[2], n.error[2]);
  if (certain_sign_of(f3.value, f3.bound) != sign) return 0;
  const BoundedDot x01 = bounded_dot(d0, n.value[1], n.error[1]);
  const BoundedDot x10 = bounded_dot(d1, n.value[0], n.error[0]);
  if (certain_sign_of(2.0 * x01.value + x10.value, 2.0 * x01.bound + x10.bound) != sign) return 0;
  const BoundedDot x02 = bounded_dot(d0, n.value[2], n.error[2]);
  const BoundedDot x11 = bounded_dot(d1, n.value[1], n.error[1]);
  if (certain_sign_of(x02.value + 2.0 * x11.value, x02.bound + 2.0 * x11.bound) != sign) return 0;
  return sign;
}

/// Whether every vertex of triangle `other` stays strictly on one side of the moving plane of
/// `triangle` (whose normal's coefficients are n) over the whole step: the two never touch.
/// x0, x1: the positions at t = 0 and t = 1, by vertex; the two triangles within_plane_range.
inline bool plane_separates(const Eigen::Vector3d* x0, const Eigen::Vector3d* x1, const Triangle& triangle,
                            const BernsteinNormals& n, const Triangle& other) {
  const Eigen::Vector3d& a0 = x0[triangle[0]];
  const Eigen::Vector3d& a1 = x1[triangle[0]];
  const int side = certain_side(x0[other[0]], x1[other[0]], a0, a1, n);
  return side != 0 && certain_side(x0[other[1]], x1[other[1]], a0, a1, n) == side &&
         certain_side(x0[other[2]], x1[other[2]], a0, a1, n) == side;
}

}  // namespace sscc::detail
