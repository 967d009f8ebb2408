// Minimum-separation mode (d > 0): does the distance between the primitives fall to d at
// some t in [0, 1]?
//
// Guarantee: conservative. Never a false negative; "contact" may be reported when the
// distance only comes within d (1 + kSeparationRelativeTolerance), or when the box budget
// kSeparationMaxBoxes runs out. The reported time is never later than the first time the
// distance reaches d.
//
// Method: the difference between a point of one primitive and a point of the other,
// F(t, u, v) = A(t) + u B(t) + v C(t), is multilinear in (t, u, v), so over a box of
// parameters each coordinate of F lies between its values at the eight corners. Boxes are
// taken earliest t first; a box is excluded when the corner bounds (with rounding-error
// bounds) keep |F| above d, per coordinate or along the box's mean direction, and accepted
// when it is narrower in t than the time-of-impact tolerance and one of its corners lies
// within d (1 + kSeparationRelativeTolerance).
#pragma once

#include "four_point_motion.hpp"
#include "sscc/ccd/ccd_types.hpp"

namespace sscc::ccd {

CcdResult separation_search(const FourPointMotion& motion, double minimum_separation, double toi_tolerance);

}  // namespace sscc::ccd
