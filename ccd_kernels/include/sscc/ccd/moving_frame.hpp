// Contact (and distance) between moving objects is unchanged when one translation, linear
// in t, is applied to all of them: in the frame that moves with their mean displacement d,
// positions x(t) become x(t) - t d, still linear in t, and objects that move alike sweep
// small boxes there. Swept boxes disjoint in that frame prove no contact.
//
// Only the end positions x(1) - d need a subtraction, and it rounds. These bounds enclose
// the exact difference whatever the rounding, so a test on them stays conservative.
#pragma once

#include <cmath>

namespace sscc::ccd {

/// Relative widening of a shifted coordinate, 2^-51 (4u for the unit roundoff u = 2^-53): it
/// covers the rounding of x - c (at most 2^-53 |x - c|) and of the widening itself. Smaller
/// values could cut a touching pair apart by an ulp; larger ones only cull less.
inline constexpr double kShiftRoundingMargin = 0x1p-51;

/// A lower bound on the exact x - c.
inline double shifted_lower(double x, double c) {
#ifdef SSCC_MUTANT_NO_SHIFT_MARGIN
  return x - c;
#endif
  return (x - c) - kShiftRoundingMargin * (std::fabs(x) + std::fabs(c));
}
/// An upper bound on the exact x - c.
inline double shifted_upper(double x, double c) {
#ifdef SSCC_MUTANT_NO_SHIFT_MARGIN
  return x - c;
#endif
  return (x - c) + kShiftRoundingMargin * (std::fabs(x) + std::fabs(c));
}

}  // namespace sscc::ccd
