#include "separation/separation_search.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "separation/bounded.hpp"
#include "separation/box_search.hpp"

namespace sscc::ccd {

namespace {

using separation::Bounded;
using BVec3 = std::array<Bounded, 3>;

/// Upper bound on |n| / sqrt(fl(n . n)) for a double vector n: three products, two sums and
/// a square root round by at most about 3 units in the last place relative; 1e-14 is ~45.
constexpr double kNormSlack = 1.0 + 1e-14;

/// F(t, u, v) = A(t) + u B(t) + v C(t) over the parameter domain (the triangle u, v >= 0,
/// u + v <= 1 for vertex-face, the unit square for edge-edge): the difference between a
/// point of the first primitive and a point of the second (vertex-face: v minus a point of
/// the face; edge-edge: a point of edge a minus a point of edge b). Only differences of the
/// input points are used, so that rounding scales with the primitives' extent and motion,
/// not with their distance from the origin.
struct Motion {
  bool triangle_domain;
  int vertices;  // of the domain: 3 or 4
  /// F at the domain's vertices (u, v) = (0, 0), (1, 0), (0, 1) [, (1, 1)], at t = 0 and
  /// t = 1, with rounding-error bounds: vertex-face v - f0, v - f1, v - f2; edge-edge
  /// a0 - b0, a1 - b0, a0 - b1, a1 - b1.
  BVec3 corner[2][4];

  explicit Motion(const FourPointMotion& m)
      : triangle_domain(m.pair == PrimitivePair::kVertexFace), vertices(triangle_domain ? 3 : 4) {
    for (int c = 0; c < vertices; ++c) {
      const int first = triangle_domain ? 3 : (c & 1);
      const int second = triangle_domain ? c : 2 + (c >> 1);
      for (int k = 0; k < 3; ++k) {
        corner[0][c][k] = Bounded::exact(m.t0[first][k]) - Bounded::exact(m.t0[second][k]);
        corner[1][c][k] = Bounded::exact(m.t1[first][k]) - Bounded::exact(m.t1[second][k]);
      }
    }
  }

  /// The domain's vertices' F at time t, in floating point (for the closest point, not for
  /// any bound).
  Eigen::Vector3d corner_at(int c, double t) const {
    Eigen::Vector3d f;
    for (int k = 0; k < 3; ++k) f[k] = (1.0 - t) * corner[0][c][k].value + t * corner[1][c][k].value;
    return f;
  }
};

/// |x|, scaled first so that neither a tiny nor a huge x under- or overflows in the squares.
double scaled_norm(const Eigen::Vector3d& x) {
  const double largest = x.cwiseAbs().maxCoeff();
  return largest > 0.0 ? largest * (x / largest).norm() : 0.0;
}

/// A point of the domain and its F.
struct Candidate {
  double u, v;
  Eigen::Vector3d f;
};

/// The point of the segment F = p + s e, s in [0, 1], nearest the origin; (u, v) =
/// (u0, v0) + s (du, dv). Inside the segment F is made orthogonal to e a second time: the
/// first pass leaves a component along e of the rounding of p (relative to |p|, not to the
/// far smaller |F|), which would tilt the direction of closest approach by |p| / |F| ulps
/// and loosen the bound along it by the segment's length times that tilt. Orthogonal to e,
/// the direction's remaining error costs only its square.
Candidate closest_on_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& e, double u0, double v0, double du,
                             double dv) {
  const double ee = e.squaredNorm();
  const double s = ee > 0.0 ? std::clamp(-p.dot(e) / ee, 0.0, 1.0) : 0.0;
  Eigen::Vector3d f = p + s * e;
  if (s > 0.0 && s < 1.0) f -= (f.dot(e) / ee) * e;
  return {u0 + s * du, v0 + s * dv, f};
}

/// The closest point of the domain at one time, and the direction to bound along.
struct Closest {
  Candidate nearest;          // the domain point where |F| is smallest (floating point)
  Eigen::Vector3d direction;  // along which the domain's vertices stay farthest (not normalised)
};

/// The closest point, in floating point. F is affine in (u, v), so |F|^2 is a convex
/// quadratic: its minimum over the domain is the unconstrained one when that lies inside,
/// and otherwise lies on the boundary, a few segments.
///
/// The unconstrained one is the foot of the perpendicular to the plane of the domain's
/// image, taken along the normal b x c: the direction then stays accurate for long, thin
/// domains (nearly parallel edges), where solving the normal equations would tilt it by
/// their condition number times the rounding.
///
/// On the boundary, the direction is the segment candidate along which the smallest vertex
/// projection is largest: in exact arithmetic that is the nearest one's, but where a vertex
/// and the adjacent segment tie to rounding, the vertex's direction can be tilted by the
/// segment's distance over its length, which a long segment turns into a loss in the bound
/// far larger than the distance's own rounding.
Closest closest_point(const Motion& m, double t) {
  Eigen::Vector3d k[4];
  for (int c = 0; c < m.vertices; ++c) k[c] = m.corner_at(c, t);
  const Eigen::Vector3d a = k[0], b = k[1] - k[0], c = k[2] - k[0];
  const Eigen::Vector3d normal = b.cross(c);
  const double nn = normal.squaredNorm();
  if (nn > 0.0) {
    // a + u b + v c is normal to the plane: cross with c, then with b, and dot with b x c.
    const double u = -a.cross(c).dot(normal) / nn;
    const double v = a.cross(b).dot(normal) / nn;
    const bool inside = u >= 0.0 && v >= 0.0 && (m.triangle_domain ? u + v <= 1.0 : u <= 1.0 && v <= 1.0);
    if (inside) {
      const Eigen::Vector3d foot = normal * (a.dot(normal) / nn);
      return {{u, v, foot}, foot};
    }
  }
  std::array<Candidate, 4> edges;
  int count = 0;
  edges[count++] = closest_on_segment(k[0], b, 0, 0, 1, 0);
  edges[count++] = closest_on_segment(k[0], c, 0, 0, 0, 1);
  if (m.triangle_domain) {
    edges[count++] = closest_on_segment(k[1], k[2] - k[1], 1, 0, -1, 1);
  } else {
    edges[count++] = closest_on_segment(k[1], k[3] - k[1], 1, 0, 0, 1);
    edges[count++] = closest_on_segment(k[2], k[3] - k[2], 0, 1, 1, 0);
  }
  Closest closest{edges[0], edges[0].f};
  double best_support = -INFINITY;
  for (int e = 0; e < count; ++e) {
    const double length = scaled_norm(edges[e].f);
    if (length < scaled_norm(closest.nearest.f)) closest.nearest = edges[e];
    if (!(length > 0.0)) continue;
    double support = INFINITY;
    for (int v = 0; v < m.vertices; ++v) support = std::min(support, k[v].dot(edges[e].f) / length);
    if (support > best_support) best_support = support, closest.direction = edges[e].f;
  }
  return closest;
}

/// The primitives at one time: the separating direction there and the domain's vertices.
struct Sample {
  double t = 0.0;
  double distance = 0.0;  // |F| at (u, v), in floating point: the closest distance at t
  double params[2] = {0.0, 0.0};
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  // F / |F| there, or zero
  double norm_bound = 0.0;                              // >= |direction|
  BVec3 corner[4];                                      // F at the domain's vertices at t

  Sample(const Motion& m, double time) : t(time) {
    const Closest closest = closest_point(m, t);
    params[0] = closest.nearest.u, params[1] = closest.nearest.v;
    distance = scaled_norm(closest.nearest.f);
    const double length = scaled_norm(closest.direction);
    if (length > 0.0 && std::isfinite(length)) {
      direction = closest.direction / length;
      norm_bound = direction.norm() * kNormSlack;
    }
    const Bounded s = Bounded::exact(1.0) - Bounded::exact(t);
    const Bounded tt = Bounded::exact(t);
    for (int c = 0; c < m.vertices; ++c) {
      for (int k = 0; k < 3; ++k) corner[c][k] = m.corner[0][c][k] * s + m.corner[1][c][k] * tt;
    }
  }
};

Bounded dot(const BVec3& f, const Eigen::Vector3d& n) {
  return f[0] * Bounded::exact(n[0]) + f[1] * Bounded::exact(n[1]) + f[2] * Bounded::exact(n[2]);
}

/// Whether the distance stays above d on all of [lo.t, hi.t]. With the direction
/// n(s) = (1 - s) n_lo + s n_hi at t = lo.t + s (hi.t - lo.t), every point of the domain
/// is at least min over the domain of F . n(s) / |n(s)| from the origin (Cauchy-Schwarz).
/// At fixed s, F . n(s) is affine in (u, v), so its minimum is at a domain vertex; there it
/// is a quadratic in s (F and n are both linear in s), whose minimum on [0, 1] is at least
/// its smallest Bernstein coefficient. |n(s)| <= max(|n_lo|, |n_hi|) by convexity. The
/// directions are the exact closest directions at the ends, so the bound is tight there and
/// its error within the interval shrinks with the square of the interval's width.
bool certainly_farther(const Sample& lo, const Sample& hi, int vertices, double d) {
  const double norm = std::max(lo.norm_bound, hi.norm_bound);
  double lowest = INFINITY;
  for (int c = 0; c < vertices; ++c) {
    const Bounded b0 = dot(lo.corner[c], lo.direction);
    const Bounded b1 = separation::scaled(dot(lo.corner[c], hi.direction) + dot(hi.corner[c], lo.direction), 0.5);
    const Bounded b2 = dot(hi.corner[c], hi.direction);
    lowest = std::min({lowest, b0.value - b0.error, b1.value - b1.error, b2.value - b2.error});
  }
  return lowest > d * norm;  // NaN never excludes; a zero direction never does either
}

struct Interval {
  Sample lo, hi;
};

CcdResult contact(const Sample& at, double toi) {
  CcdResult result;
  result.decided_by = DecidedBy::kSeparationSearch;
  result.hit = true;
  result.toi = toi;
  result.params[0] = at.params[0];
  result.params[1] = at.params[1];
  return result;
}

}  // namespace

CcdResult separation_search(const FourPointMotion& motion, double minimum_separation, double toi_tolerance) {
  const Motion m(motion);
  const double reach = (1.0 + kSeparationRelativeTolerance) * minimum_separation;
  // Depth first, earlier half first: intervals are examined in order of time, so every
  // interval before the one reported was excluded.
  std::vector<Interval> stack;
  stack.push_back({Sample(m, 0.0), Sample(m, 1.0)});
  for (int examined = 0; !stack.empty(); ++examined) {
    const Interval interval = stack.back();
    stack.pop_back();
    const Sample& lo = interval.lo;
    const Sample& hi = interval.hi;
    // Out of budget, or too narrow to halve, with no sample within reach: the directions were
    // too poor for the bound here (exactly parallel edges far from the origin), and the box
    // search, which needs none, decides from the start (box_search.hpp).
    const double mid = 0.5 * (lo.t + hi.t);
    if (examined >= kSeparationMaxBoxes || !(lo.t < mid && mid < hi.t)) {
      return box_separation_search(motion, minimum_separation, toi_tolerance);
    }
    if (certainly_farther(lo, hi, m.vertices, minimum_separation)) continue;
    if (lo.distance <= reach) return contact(lo, lo.t);
    if (hi.t - lo.t <= toi_tolerance && hi.distance <= reach) return contact(hi, lo.t);
    const Sample middle(m, mid);
    stack.push_back({middle, hi});
    stack.push_back({lo, middle});
  }
  CcdResult result;
  result.decided_by = DecidedBy::kSeparationSearch;
  return result;
}

}  // namespace sscc::ccd
