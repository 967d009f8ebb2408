#include "sscc/geometry/triangle_distance.hpp"

#include <algorithm>
#include <cmath>

namespace sscc {

namespace {

/// Barycentric weights of the point of triangle (a, b, c) closest to p, by Voronoi region
/// of the triangle's features (vertices, edges, interior).
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {1.0, 0.0, 0.0};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {0.0, 1.0, 0.0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return {1.0 - v, v, 0.0};
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {0.0, 0.0, 1.0};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return {1.0 - w, 0.0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0.0, 1.0 - w, w};
  }
  const double denominator = va + vb + vc;
  if (!(denominator > 0.0)) {
    // Degenerate (collinear) triangle: its closest point lies on one of its edges.
    Eigen::Vector3d best(1.0, 0.0, 0.0);
    double best_distance = ap.squaredNorm();
    const std::array<std::pair<int, int>, 3> edges{{{0, 1}, {1, 2}, {2, 0}}};
    const std::array<const Eigen::Vector3d*, 3> corner{&a, &b, &c};
    for (const auto& [i, j] : edges) {
      const Eigen::Vector3d e = *corner[j] - *corner[i];
      const double length = e.squaredNorm();
      const double t = length > 0.0 ? std::clamp(e.dot(p - *corner[i]) / length, 0.0, 1.0) : 0.0;
      const double d = (*corner[i] + t * e - p).squaredNorm();
      if (d < best_distance) {
        best_distance = d;
        best.setZero();
        best[i] = 1.0 - t;
        best[j] = t;
      }
    }
    return best;
  }
  const double v = vb / denominator, w = vc / denominator;
  return {1.0 - v - w, v, w};
}

/// Parameters (s, t) in [0, 1]^2 of the closest points of segments p0 + s (p1 - p0) and
/// q0 + t (q1 - q0): the unconstrained minimiser clamped, then each parameter re-solved
/// against the other and clamped (exact for the convex quadratic on the square).
std::pair<double, double> closest_on_segments(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                              const Eigen::Vector3d& q0, const Eigen::Vector3d& q1) {
  const Eigen::Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  if (a <= 0.0 && e <= 0.0) return {0.0, 0.0};
  if (a <= 0.0) return {0.0, std::clamp(f / e, 0.0, 1.0)};
  const double c = d1.dot(r);
  if (e <= 0.0) return {std::clamp(-c / a, 0.0, 1.0), 0.0};
  const double b = d1.dot(d2);
  const double denominator = a * e - b * b;
  double s = denominator > 0.0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0.0) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1.0) {
    t = 1.0;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return {s, t};
}

Eigen::Vector3d combine(const std::array<Eigen::Vector3d, 3>& t, const Eigen::Vector3d& w) {
  return w[0] * t[0] + w[1] * t[1] + w[2] * t[2];
}

}  // namespace

TriangleClosestPoints closest_points_disjoint_triangles(const std::array<Eigen::Vector3d, 3>& a,
                                                        const std::array<Eigen::Vector3d, 3>& b) {
  TriangleClosestPoints best;
  double best_squared = INFINITY;
  const auto consider = [&](const Eigen::Vector3d& wa, const Eigen::Vector3d& wb) {
    const double squared = (combine(a, wa) - combine(b, wb)).squaredNorm();
    if (squared < best_squared) {
      best_squared = squared;
      best.first_weights = wa;
      best.second_weights = wb;
    }
  };
  for (int i = 0; i < 3; ++i) {
    consider(Eigen::Vector3d::Unit(i), closest_on_triangle(a[i], b[0], b[1], b[2]));
    consider(closest_on_triangle(b[i], a[0], a[1], a[2]), Eigen::Vector3d::Unit(i));
  }
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3;
      const auto [s, t] = closest_on_segments(a[i], a[i1], b[j], b[j1]);
      Eigen::Vector3d wa = Eigen::Vector3d::Zero(), wb = Eigen::Vector3d::Zero();
      wa[i] = 1.0 - s;
      wa[i1] = s;
      wb[j] = 1.0 - t;
      wb[j1] = t;
      consider(wa, wb);
    }
  }
  best.distance = std::sqrt(best_squared);
  return best;
}

}  // namespace sscc
