// The box-box bound of the precomputation (DESIGN.md, soundness notes): the smallest norm
// of the scaled coordinates at which the subspace boxes of two nodes can meet. Private to
// the library.
//
// Guarantee: a lower bound. Along axis D the centres' gap g_D closes at rate at most
// ||(C_a - C_b)_D||_2 per unit ||q_hat|| (Cauchy-Schwarz: the paper's smallest single-mode
// |q_i| bounds motion along one mode only) and the half extents grow at rate_a,D + rate_b,D;
// the boxes meet only when every axis has closed, so the largest g_D / rate_D bounds them.
// The result is shrunk by kBoxBoxRoundingShrink to cover its own rounding.
#pragma once

#include "sscc/bvh/subspace_bvh.hpp"

namespace sscc::detail {

/// Relative shrink of the box-box radius: its gap, rates and quotient each round by a few
/// units of 2^-53 (relative), far below this, so the shrunk radius never exceeds the exact
/// one. Smaller (towards 1e-15) risks a radius rounded above the true one, which could
/// certify a pair that touches; larger only culls a little less.
inline constexpr double kBoxBoxRoundingShrink = 1e-9;

/// Smallest ||q_hat|| at which the subspace boxes (SubspaceBvh::box) of nodes a and b can
/// meet; 0 when they already do, infinity when nothing moves them closer.
double box_box_radius(const SubspaceBvh& bvh, int a, int b);

}  // namespace sscc::detail
