#include "contact_params.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <initializer_list>
#include <utility>

#include <Eigen/Geometry>

namespace sscc::ccd {

namespace {

using Eigen::Vector3d;

double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }

/// Parameter of the point of segment [a, b] closest to p.
double closest_on_segment(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
  const Vector3d d = b - a;
  const double dd = d.squaredNorm();
  return dd > 0.0 ? clamp01((p - a).dot(d) / dd) : 0.0;
}

/// Below this squared sine of the angle between two edges, closed-form closest points lose
/// most of their digits to cancellation.
constexpr double kNearlyParallelSine2 = 1e-8;

/// Minimiser over [0, 1] of a convex function that is evaluated accurately, to about 1e-16
/// (golden section; the ends are tried too, since the search never lands on them).
template <typename Convex>
double golden_minimum(const Convex& f, std::initializer_list<double> also_try) {
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = 0.0;
  double hi = 1.0;
  double x1 = hi - ratio * (hi - lo);
  double x2 = lo + ratio * (hi - lo);
  double f1 = f(x1);
  double f2 = f(x2);
  for (int i = 0; i < 78; ++i) {
    if (f1 <= f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - ratio * (hi - lo), f1 = f(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + ratio * (hi - lo), f2 = f(x2);
    }
  }
  double best_x = 0.5 * (lo + hi);
  double best = f(best_x);
  for (double x : also_try) {
    const double value = f(x);
    if (value < best) best = value, best_x = x;
  }
  return best_x;
}

/// A needle or sliver triangle: from the vertex opposite its shortest edge it is the union
/// over s of the segments [apex + s (q - apex), apex + s (r - apex)], and the distance to
/// that segment is convex in s (a partial minimum of a convex function over a convex set).
void sliver_params(const Vector3d& p, const Vector3d& a, const Vector3d& b, const Vector3d& c, double params[2]) {
  const Vector3d* x[3] = {&a, &b, &c};
  const double opposite2[3] = {(c - b).squaredNorm(), (a - c).squaredNorm(), (b - a).squaredNorm()};
  const int apex = int(std::min_element(opposite2, opposite2 + 3) - opposite2);
  const Vector3d& o = *x[apex];
  const Vector3d& q = *x[(apex + 1) % 3];
  const Vector3d& r = *x[(apex + 2) % 3];
  const auto cross_section = [&](double s) {
    const Vector3d from = o + s * (q - o);
    const Vector3d to = o + s * (r - o);
    return std::make_pair(from, to);
  };
  const auto distance = [&](double s) {
    const auto [from, to] = cross_section(s);
    return (from + closest_on_segment(p, from, to) * (to - from) - p).squaredNorm();
  };
  const double s = golden_minimum(distance, {0.0, 1.0});
  const auto [from, to] = cross_section(s);
  const double w = closest_on_segment(p, from, to);
  double weight[3];  // barycentric weights of a, b, c
  weight[apex] = 1.0 - s;
  weight[(apex + 1) % 3] = s * (1.0 - w);
  weight[(apex + 2) % 3] = s * w;
  params[0] = weight[1];
  params[1] = weight[2];
}

void triangle_params(const Vector3d& p, const Vector3d& a, const Vector3d& b, const Vector3d& c, double params[2]) {
  // Candidates: the projection into the face (ill-conditioned when the triangle is nearly
  // degenerate) and the closest point on each edge; the nearest one wins.
  double best[2] = {0.0, 0.0};
  double best_distance = INFINITY;
  const auto consider = [&](double u, double v) {
    const double d = (a + u * (b - a) + v * (c - a) - p).squaredNorm();
    if (d < best_distance) {
      best_distance = d;
      best[0] = u;
      best[1] = v;
    }
  };
  const Vector3d n = (b - a).cross(c - a);
  const double nn = n.squaredNorm();
  const double longest2 = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  if (nn <= kNearlyParallelSine2 * longest2 * longest2 && longest2 > 0.0) {
    sliver_params(p, a, b, c, params);
    return;
  }
  if (nn > 0.0) {
    // Clamped into the triangle rather than dropped: a contact next to an edge may round
    // just outside.
    const double u = std::max(0.0, (p - a).cross(c - a).dot(n) / nn);  // weight of b
    const double v = std::max(0.0, (b - a).cross(p - a).dot(n) / nn);  // weight of c
    const double excess = std::max(1.0, u + v);
    consider(u / excess, v / excess);
  }
  const double s_ab = closest_on_segment(p, a, b);
  const double s_bc = closest_on_segment(p, b, c);
  const double s_ca = closest_on_segment(p, c, a);
  consider(s_ab, 0.0);
  consider(1.0 - s_bc, s_bc);
  consider(0.0, 1.0 - s_ca);
  params[0] = best[0];
  params[1] = best[1];
}

void segment_params(const Vector3d& a0, const Vector3d& a1, const Vector3d& b0, const Vector3d& b1, double params[2]) {
  const Vector3d da = a1 - a0;
  const Vector3d db = b1 - b0;
  const Vector3d w = a0 - b0;
  const double aa = da.squaredNorm();
  const double bb = db.squaredNorm();
  const double ab = da.dot(db);
  const double denom = aa * bb - ab * ab;
  if (aa == 0.0 || bb == 0.0) {  // a point: its projection on the other edge
    params[0] = aa == 0.0 ? 0.0 : closest_on_segment(b0, a0, a1);
    params[1] = aa == 0.0 ? closest_on_segment(a0, b0, b1) : 0.0;
    return;
  }
  if (denom > kNearlyParallelSine2 * aa * bb) {
    double s = clamp01((ab * db.dot(w) - bb * da.dot(w)) / denom);
    double u = (ab * s + db.dot(w)) / bb;
    if (u < 0.0 || u > 1.0) {
      u = clamp01(u);
      s = clamp01((ab * u - da.dot(w)) / aa);
    }
    params[0] = s;
    params[1] = u;
    return;
  }
  // Nearly parallel: the distance from a0 + s da to edge b is convex in s and evaluated
  // accurately, so a golden-section search finds s where the formula cannot.
  const auto distance = [&](double s) {
    const Vector3d p = a0 + s * da;
    return (p - (b0 + closest_on_segment(p, b0, b1) * db)).squaredNorm();
  };
  params[0] = golden_minimum(distance, {0.0, 1.0, closest_on_segment(b0, a0, a1), closest_on_segment(b1, a0, a1)});
  params[1] = closest_on_segment(a0 + params[0] * da, b0, b1);
}

/// Scales the points by the power of two that brings their largest coordinate magnitude
/// to [0.5, 1): exact (coordinates far below the largest may underflow, which moves them
/// by less than 2^-1074 of it). Each coordinate is scaled on its own, since the factor
/// itself, 2^-exponent, overflows when the largest magnitude is subnormal.
double largest_magnitude(const Vector3d* x, int count) {
  double magnitude = 0.0;
  for (int i = 0; i < count; ++i) magnitude = std::max(magnitude, x[i].cwiseAbs().maxCoeff());
  return magnitude;
}

void normalize_scale(Vector3d* x, int count) {
  const double magnitude = largest_magnitude(x, count);
  if (magnitude == 0.0) return;
  int exponent = 0;
  std::frexp(magnitude, &exponent);
  if (exponent > DBL_MIN_EXP) {  // 2^-exponent is a double: one exact product per coordinate
    const double factor = std::ldexp(1.0, -exponent);
    for (int i = 0; i < count; ++i) x[i] *= factor;
    return;
  }
  for (int i = 0; i < count; ++i) {
    x[i] = x[i].unaryExpr([exponent](double c) { return std::ldexp(c, -exponent); });
  }
}

/// Below this largest coordinate magnitude the interpolation (1 - t) x0 + t x1 may lose
/// digits to subnormal products, so the end points are scaled up first.
constexpr double kInterpolationUnderflowRisk = 0x1p-900;

}  // namespace

void contact_params_at(const FourPointMotion& motion, double t, double params[2]) {
  // The parameters depend neither on position nor on scale. Scaled first, so that the
  // interpolation below keeps its digits for subnormal inputs; then centred on x[0] and
  // scaled again, so that squared cross products can neither overflow nor vanish.
  Vector3d ends[8];
  for (int i = 0; i < 4; ++i) {
    ends[i] = motion.t0[i];
    ends[i + 4] = motion.t1[i];
  }
  if (largest_magnitude(ends, 8) < kInterpolationUnderflowRisk) normalize_scale(ends, 8);
  Vector3d x[4];
  for (int i = 0; i < 4; ++i) x[i] = (1.0 - t) * ends[i] + t * ends[i + 4];
  for (int i = 1; i < 4; ++i) x[i] -= x[0];
  x[0].setZero();
  normalize_scale(x + 1, 3);
  if (motion.pair == PrimitivePair::kVertexFace) {
    triangle_params(x[3], x[0], x[1], x[2], params);
  } else {
    segment_params(x[0], x[1], x[2], x[3], params);
  }
}

}  // namespace sscc::ccd
