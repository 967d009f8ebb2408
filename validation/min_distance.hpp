// Reference for the minimum-separation mode: the smallest distance between the primitives
// over the step, bracketed by a branch-and-bound on t alone.
//
// At each sampled t the distance between the primitives is computed directly (long double):
// the smallest of the candidate closest points of the parameter domain, its vertices, the
// clamped projections onto its edges and the interior stationary point when it lies inside.
// Over t the distance is Lipschitz with constant L, the largest relative displacement over
// the step of two points of the primitives (a domain vertex's, by convexity), so over
// [a, b] it stays above (d(a) + d(b)) / 2 - L (b - a) / 2; intervals whose bound cannot
// improve the best sample by more than the requested precision are dropped.
//
// Independent of the kernels' search (which bounds along separating directions in double
// arithmetic with rounding-error bounds); slow (thousands of distance evaluations near a
// minimum), for tests and validation only.
#pragma once

#include "query.hpp"

namespace sscc::validation {

struct DistanceBracket {
  double lower = 0.0;  ///< <= the true minimum distance over the step
  double upper = 0.0;  ///< >= the true minimum distance (the distance at some sampled t)
};

struct BracketOptions {
  /// The bracket's width: at most max(relative * minimum, absolute), plus rounding
  /// (relative to the coordinates' magnitude, which also floors the width). absolute > 0.
  double relative = 1e-6;
  double absolute = 1e-12;
  /// The part of the step searched, 0 <= t_begin <= t_end <= 1.
  double t_begin = 0.0;
  double t_end = 1.0;
  /// When >= 0, only whether the minimum is at most this is asked: the search stops at the
  /// first sample at or below it and refines no interval whose bound exceeds it, so that
  /// either upper <= threshold or lower > threshold (unless the evaluations run out).
  double threshold = -1.0;
  /// Distance evaluations allowed. Past them the bracket is still valid, only wider: a
  /// distance nearly constant over a long stretch while the points move fast needs many.
  long max_evaluations = 200'000;
};

/// The minimum distance over t in [t_begin, t_end].
DistanceBracket min_distance_bracket(const Query& q, const BracketOptions& options = {});

}  // namespace sscc::validation
