// Minimum-separation mode (d > 0): does the distance between the primitives fall to d at
// some t in [0, 1]?
//
// Guarantee: conservative. Never a false negative; "contact" may be reported when the
// distance only comes within d (1 + kSeparationRelativeTolerance). Where the budget
// kSeparationMaxBoxes runs out or an interval of t can no longer be halved in doubles before a
// sample comes within that band (the directions too poor for the bound: exactly parallel edges
// far from the origin), the box search of box_search.hpp decides instead, from the start;
// "contact" when its own budget runs out. Rounding limits the band: the bound's own error
// is a few units in the last place of the primitives' extent (their sizes and motion), and
// the directions it uses carry a little more; for d below about 1e-8 of the extent, seen on
// near-degenerate queries, a contact may be reported for a distance somewhat beyond the band
// (never a missed one). The reported time is never later than the first time the
// distance reaches d.
//
// Method: the difference between a point of one primitive and a point of the other,
// F(t, u, v) = A(t) + u B(t) + v C(t), is affine in (u, v) at each t, so the distance at t
// is that of the origin from a triangle or parallelogram, and along any direction n the
// smallest n . F over the domain is at one of its 3 or 4 vertices. The search subdivides t
// alone, earliest first. At each sampled t it finds the closest point (floating point), and
// with it the direction of closest approach; an interval is excluded when, along the
// directions at its ends blended linearly, the vertices' Bernstein bounds (with
// rounding-error bounds) keep the distance above d. That bound is exact at the ends and its
// error shrinks with the square of the interval's width, so few intervals are examined. An
// interval is accepted when the sampled distance at its start, or at its end if it is
// narrower than the time-of-impact tolerance, is within d (1 + kSeparationRelativeTolerance).
#pragma once

#include "four_point_motion.hpp"
#include "sscc/ccd/ccd_types.hpp"

namespace sscc::ccd {

CcdResult separation_search(const FourPointMotion& motion, double minimum_separation, double toi_tolerance);

}  // namespace sscc::ccd
