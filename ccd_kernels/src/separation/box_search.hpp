// The minimum-separation mode's fallback (separation_search.hpp): a search over boxes of all
// three parameters, slower than the search over t, but independent of the directions of
// closest approach that one relies on, so it decides the configurations (exactly parallel
// edges far from the origin) where those directions are too poor for its bound.
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

CcdResult box_separation_search(const FourPointMotion& motion, double minimum_separation, double toi_tolerance);

}  // namespace sscc::ccd
