#include "sscc/scene/contact_geometry.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sscc {

namespace {

/// Below this squared length (relative to the squared size of the features) a normal is
/// taken as undefined: a sliver triangle or nearly parallel edges give no direction.
constexpr double kDegenerateNormal = 1e-24;

/// Barycentrics of the point of triangle (a, b, c) closest to p (Ericson, Real-Time
/// Collision Detection, 5.1.5).
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const double denominator = 1.0 / (va + vb + vc);
  const double v = vb * denominator, w = vc * denominator;
  return {1 - v - w, v, w};
}

/// Parameters (s, u) of the closest points of segments p0 p1 and q0 q1 (Ericson, 5.1.9).
std::array<double, 2> closest_on_segments(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                          const Eigen::Vector3d& q0, const Eigen::Vector3d& q1) {
  const Eigen::Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  if (a <= 0 && e <= 0) return {0, 0};
  if (a <= 0) return {0, std::clamp(f / e, 0.0, 1.0)};
  const double c = d1.dot(r);
  if (e <= 0) return {std::clamp(-c / a, 0.0, 1.0), 0};
  const double b = d1.dot(d2), denominator = a * e - b * b;
  double s = denominator > 0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
  double u = (b * s + f) / e;
  if (u < 0) {
    u = 0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (u > 1) {
    u = 1;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return {s, u};
}

Eigen::Vector3d weighted(const std::array<double, 4>& w, const std::array<Eigen::Vector3d, 4>& x) {
  return w[0] * x[0] + w[1] * x[1] + w[2] * x[2] + w[3] * x[3];
}

}  // namespace

std::array<int, 4> contact_vertices(const TriangleMesh& first_mesh, const TriangleMesh& second_mesh, FeatureKind kind,
                                    int first, int second) {
  const auto check = [](int index, int count, const char* what) {
    if (index < 0 || index >= count) {
      throw std::out_of_range("contact_vertices: " + std::string(what) + " " + std::to_string(index) +
                              " out of range (" + std::to_string(count) + ")");
    }
  };
  if (kind == FeatureKind::kVertexFace) {
    check(first, first_mesh.vertex_count(), "vertex");
    check(second, second_mesh.triangle_count(), "triangle");
    const Triangle& t = second_mesh.triangles()[second];
    return {first, t[0], t[1], t[2]};
  }
  check(first, static_cast<int>(first_mesh.edges().size()), "edge");
  check(second, static_cast<int>(second_mesh.edges().size()), "edge");
  const Edge& a = first_mesh.edges()[first];
  const Edge& b = second_mesh.edges()[second];
  return {a[0], a[1], b[0], b[1]};
}

ContactFrame contact_frame(FeatureKind kind, const std::array<Eigen::Vector3d, 4>& start,
                           const std::array<Eigen::Vector3d, 4>& end, double toi) {
  std::array<Eigen::Vector3d, 4> at;
  for (int i = 0; i < 4; ++i) at[i] = (1 - toi) * start[i] + toi * end[i];
  ContactFrame frame;
  Eigen::Vector3d normal;
  if (kind == FeatureKind::kVertexFace) {
    const Eigen::Vector3d b = closest_on_triangle(at[0], at[1], at[2], at[3]);
    frame.weights = {1.0, -b[0], -b[1], -b[2]};
    normal = (at[2] - at[1]).cross(at[3] - at[1]);
  } else {
    const auto [s, u] = closest_on_segments(at[0], at[1], at[2], at[3]);
    frame.weights = {1 - s, s, -(1 - u), -u};
    normal = (at[1] - at[0]).cross(at[3] - at[2]);
  }
  double size = 0.0;
  for (int i = 1; i < 4; ++i) size = std::max(size, (at[i] - at[0]).squaredNorm());
  const Eigen::Vector3d separation = weighted(frame.weights, start);
  const Eigen::Vector3d approach = separation - weighted(frame.weights, end);
  if (normal.squaredNorm() <= kDegenerateNormal * size * size) {
    normal = separation.squaredNorm() > 0 ? separation : approach;
  }
  if (normal.squaredNorm() == 0) normal = Eigen::Vector3d::UnitZ();  // nothing moves: any direction
  normal.normalize();
  // The first side starts on the positive side; when it starts on the plane, it approaches
  // from the positive side.
  const double side = normal.dot(separation);
  if (side < 0 || (side == 0 && normal.dot(approach) < 0)) normal = -normal;
  frame.normal = normal;
  return frame;
}

double contact_gap(const ContactFrame& frame, const std::array<Eigen::Vector3d, 4>& x) {
  return frame.normal.dot(weighted(frame.weights, x));
}

}  // namespace sscc
