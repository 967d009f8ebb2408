#include "min_distance.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <stdexcept>
#include <vector>

namespace sscc::validation {

namespace {

using LVec = Eigen::Matrix<long double, 3, 1>;

/// Rounding allowance of a long double distance (64-bit significand) relative to the
/// coordinates' magnitude: a few hundred units in its last place.
constexpr long double kRoundingAllowance = 1e-16L;
/// The bracket is never asked to be narrower than this many rounding allowances.
constexpr long double kRoundingSteps = 4;

/// The primitives' difference F(u, v) = p + u e1 + v e2 at one time; the domain is the
/// triangle u, v >= 0, u + v <= 1 (vertex-face) or the unit square (edge-edge).
struct Slice {
  LVec p, e1, e2;
  bool triangle;
};

Slice slice_at(const Query& q, long double t) {
  std::array<LVec, 4> x;
  for (int i = 0; i < 4; ++i) {
    x[i] = (1.0L - t) * q.points[i].cast<long double>() + t * q.points[i + 4].cast<long double>();
  }
  if (q.kind == Kind::kVertexFace) return {x[0] - x[1], x[1] - x[2], x[1] - x[3], true};  // v - face point
  return {x[0] - x[2], x[1] - x[0], x[2] - x[3], false};                                  // a point - b point
}

/// Smallest |F| over the domain: the minimum of a convex quadratic over a polygon is at
/// one of its vertices, at a clamped stationary point on one of its edges, or at the
/// interior stationary point; every candidate is evaluated and the smallest kept.
long double distance_in(const Slice& s) {
  using Uv = std::array<long double, 2>;
  static constexpr Uv kSquare[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // in order around the boundary
  static constexpr Uv kTriangle[3] = {{0, 0}, {1, 0}, {0, 1}};
  const Uv* corners = s.triangle ? kTriangle : kSquare;
  const int count = s.triangle ? 3 : 4;
  const auto at = [&](const Uv& c) { return LVec(s.p + c[0] * s.e1 + c[1] * s.e2); };
  long double best = INFINITY;
  for (int i = 0; i < count; ++i) {
    const LVec start = at(corners[i]);
    const LVec along = at(corners[(i + 1) % count]) - start;
    best = std::min(best, start.norm());
    const long double length2 = along.squaredNorm();
    if (length2 == 0) continue;
    const long double w = -start.dot(along) / length2;
    if (w > 0 && w < 1) best = std::min(best, (start + w * along).norm());
  }
  const long double g11 = s.e1.squaredNorm(), g12 = s.e1.dot(s.e2), g22 = s.e2.squaredNorm();
  const long double det = g11 * g22 - g12 * g12;
  if (det > 0) {
    const long double r1 = -s.p.dot(s.e1), r2 = -s.p.dot(s.e2);
    const long double u = (r1 * g22 - r2 * g12) / det;
    const long double v = (r2 * g11 - r1 * g12) / det;
    if (u > 0 && v > 0 && (s.triangle ? u + v < 1 : u < 1 && v < 1)) best = std::min(best, at({u, v}).norm());
  }
  return best;
}

struct Span {
  long double a, b, da, db;
  /// Distances are never negative: a bound below zero is raised to it.
  long double bound(long double lipschitz) const {
    return std::max<long double>(0, (da + db) / 2 - lipschitz * (b - a) / 2);
  }
};

}  // namespace

DistanceBracket min_distance_bracket(const Query& q, const BracketOptions& options) {
  if (!(options.absolute > 0) || !(options.relative >= 0) || !(0 <= options.t_begin) ||
      !(options.t_begin <= options.t_end) || !(options.t_end <= 1)) {
    throw std::invalid_argument("min_distance_bracket: absolute precision must be > 0 and the range within [0, 1]");
  }
  long double magnitude = 0;
  for (const auto& p : q.points) magnitude = std::max(magnitude, static_cast<long double>(p.cwiseAbs().maxCoeff()));
  const long double rounding = kRoundingAllowance * std::max(magnitude, 1e-300L);
  // The domain vertices' displacements over the step: F(1) - F(0) at each.
  const Slice s0 = slice_at(q, 0), s1 = slice_at(q, 1);
  long double lipschitz = 0;
  for (long double u : {0.0L, 1.0L}) {
    for (long double v : {0.0L, 1.0L}) {
      if (s0.triangle && u + v > 1) continue;
      const LVec move = (s1.p + u * s1.e1 + v * s1.e2) - (s0.p + u * s0.e1 + v * s0.e2);
      lipschitz = std::max(lipschitz, move.norm());
    }
  }
  lipschitz *= 1 + kRoundingAllowance;
  const auto distance = [&](long double t) { return distance_in(slice_at(q, t)); };
  const auto lower_first = [&](const Span& x, const Span& y) { return x.bound(lipschitz) > y.bound(lipschitz); };
  std::priority_queue<Span, std::vector<Span>, decltype(lower_first)> open(lower_first);
  Span whole{options.t_begin, options.t_end, distance(options.t_begin), distance(options.t_end)};
  const auto precision = [&](long double best) {
    return std::max({options.relative * best, static_cast<long double>(options.absolute), kRoundingSteps * rounding});
  };
  long double best = std::min(whole.da, whole.db);
  long double lowest_dropped = INFINITY;
  const bool deciding = options.threshold >= 0;
  const auto settled = [&](const Span& span) {
    const long double bound = span.bound(lipschitz);
    return bound >= best - precision(best) || (deciding && bound > options.threshold);
  };
  open.push(whole);
  for (long evaluations = 2; !open.empty(); ++evaluations) {
    if (deciding && best <= options.threshold) break;
    const Span span = open.top();
    if (evaluations > options.max_evaluations) break;
    open.pop();
    if (settled(span)) {
      lowest_dropped = std::min(lowest_dropped, span.bound(lipschitz));
      continue;
    }
    const long double mid = (span.a + span.b) / 2;
    const long double dm = distance(mid);
    best = std::min(best, dm);
    open.push({span.a, mid, span.da, dm});
    open.push({mid, span.b, dm, span.db});
  }
  // What is still open bounds the minimum from below too.
  if (!open.empty()) lowest_dropped = std::min(lowest_dropped, open.top().bound(lipschitz));
  const long double lower = std::min(best, lowest_dropped) - rounding;
  return {static_cast<double>(std::max(0.0L, lower)), static_cast<double>(best + rounding)};
}

}  // namespace sscc::validation
