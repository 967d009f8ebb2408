// The floating-point stages of the kernels. Every verdict other than kUndecided is proven:
// all signs it rests on are certified against proven rounding-error bounds.
//
// 1. The coplanarity cubic in Bernstein form on [0, 1]: a certain sign everywhere means
//    the four points are never coplanar, so no contact.
// 2. Root pieces: [0, 1] is bisected, left to right, into pieces on which the cubic may
//    vanish. On each piece the 2D orientations of the inside test (see four_point_motion.hpp)
//    are bounded in every coordinate plane. A piece is excluded when, in some plane, the
//    orientations certainly contradict contact over the whole piece; it is a contact when
//    the cubic certainly changes sign across it and, in some plane, the orientations
//    certainly put the projected point strictly inside (the plane's projection is then
//    one-to-one on the common plane). Anything else is bisected, down to a minimum width.
// Every sign is certified against an absolute rounding-error bound derived (in
// coplanar_filter.cpp) from the magnitudes of the edge vectors.
// 3. The time of impact is refined by bisection within the first contact piece.
#pragma once

#include "four_point_motion.hpp"
#include "sscc/ccd/ccd_types.hpp"

namespace sscc::ccd::filter {

/// Pieces narrower than this are not bisected further for a decision; the query goes to
/// exact arithmetic. Smaller means fewer exact fallbacks near double roots and tangential
/// contacts, at the price of deeper bisection before giving up.
inline constexpr double kMinDecisionPieceWidth = 0x1p-20;

enum class Verdict { kNoContact, kContact, kUndecided };

struct FilterOutcome {
  Verdict verdict = Verdict::kUndecided;
  DecidedBy stage = DecidedBy::kCoplanaritySign;
  double toi = 1.0;  ///< valid for kContact: never later than the first contact
};

/// Precondition: coordinates finite and of magnitude at most kFilterMaxMagnitude.
FilterOutcome run_coplanar_filter(const FourPointMotion& motion, double toi_tolerance);

/// Above this magnitude products of coordinate differences may overflow: such queries go
/// straight to exact arithmetic.
inline constexpr double kFilterMaxMagnitude = 1e100;

}  // namespace sscc::ccd::filter
