// The kernels' exact stage: decides contact of four linearly moving points (see
// four_point_motion.hpp) exactly, for any double input, in integer arithmetic (the
// coordinates along each axis scaled by one power of two; exact_stage's integer
// polynomials and dyadic roots), on fixed-size integers first and on GMP's when those
// overflow.
//
// Guarantee: exact. Contact at t means: the four points are coplanar (det(e1, e2, e3) = 0)
// and, in each of the three coordinate planes, the projected primitives touch. The second
// part is a sign condition on 2D orientations and, where all of them vanish (everything
// collinear in that plane), on 2D dot products; with coplanarity it is equivalent to
// contact in 3D, degenerate triangles and parallel edges included (some projection is
// one-to-one on the common plane, or on the common line). Where the primitives' normal (the
// triangle's, or edge a x edge b) has a non-zero component along an axis, that plane's
// projection is one-to-one on the common plane and its test alone decides.
// The contact set is closed, and its truth changes only at roots of those polynomials, so
// the first contact is either a root of the cubic (when the cubic is not identically
// zero) or, for motion that stays coplanar, t = 0 or a root of one of the polynomials.
#pragma once

#include <optional>

#include "four_point_motion.hpp"

namespace sscc::ccd {

/// The first contact time t*, rounded down to a double in [t* - toi_tolerance, t*], or
/// nothing when the primitives never touch in [0, 1]. toi_tolerance >= kMinToiTolerance.
std::optional<double> exact_first_contact(const FourPointMotion& motion, double toi_tolerance);

}  // namespace sscc::ccd
