#include "demo/spring_mesh.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace sscc::validation {

namespace {

/// Points of the loop's centre line before smoothing, per unit of length of the helices.
constexpr int kDenseSamplesPerTurn = 400;
/// Moving-average passes (window of kSmoothingWindow points) that round the joints.
constexpr int kSmoothingPasses = 6;
constexpr int kSmoothingWindow = 25;

std::vector<Eigen::Vector3d> raw_loop(const SpringShape& s) {
  const double height = s.pitch * s.turns;
  const int per_helix = kDenseSamplesPerTurn * s.turns;
  std::vector<Eigen::Vector3d> points;
  const auto helix = [&](double theta, double theta_start) {
    return Eigen::Vector3d(s.coil_radius * std::cos(theta), s.coil_radius * std::sin(theta),
                           s.pitch * (theta - theta_start) / (2 * M_PI));
  };
  const auto bridge = [&](const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
    const int n = kDenseSamplesPerTurn / 3;
    for (int i = 1; i < n; ++i) points.push_back(from + (to - from) * (static_cast<double>(i) / n));
  };
  for (int i = 0; i <= per_helix; ++i) points.push_back(helix(2 * M_PI * s.turns * i / per_helix, 0.0));
  bridge(points.back(), Eigen::Vector3d(-s.coil_radius, 0.0, height));
  for (int i = per_helix; i >= 0; --i) points.push_back(helix(M_PI + 2 * M_PI * s.turns * i / per_helix, M_PI));
  bridge(points.back(), points.front());
  return points;
}

std::vector<Eigen::Vector3d> smoothed(std::vector<Eigen::Vector3d> p) {
  const int n = static_cast<int>(p.size());
  for (int pass = 0; pass < kSmoothingPasses; ++pass) {
    std::vector<Eigen::Vector3d> q(n, Eigen::Vector3d::Zero());
    for (int i = 0; i < n; ++i) {
      for (int k = -kSmoothingWindow / 2; k <= kSmoothingWindow / 2; ++k) q[i] += p[(i + k + n) % n];
      q[i] /= kSmoothingWindow;
    }
    p.swap(q);
  }
  return p;
}

/// `count` points evenly spaced by arc length along the closed polyline.
std::vector<Eigen::Vector3d> resampled(const std::vector<Eigen::Vector3d>& p, int count) {
  const int n = static_cast<int>(p.size());
  std::vector<double> length(n + 1, 0.0);
  for (int i = 0; i < n; ++i) length[i + 1] = length[i] + (p[(i + 1) % n] - p[i]).norm();
  std::vector<Eigen::Vector3d> out;
  int segment = 0;
  for (int k = 0; k < count; ++k) {
    const double target = length[n] * k / count;
    while (length[segment + 1] < target) ++segment;
    const double f = (target - length[segment]) / (length[segment + 1] - length[segment]);
    out.push_back(p[segment] + f * (p[(segment + 1) % n] - p[segment]));
  }
  return out;
}

}  // namespace

TriangleMesh double_helix_spring(const SpringShape& s) {
  if (!(s.tube_radius > 0.0) || !(s.tube_radius < s.pitch / 4) || s.turns < 1 || s.rings < 8 || s.segments < 3 ||
      !(s.coil_radius > 2 * s.tube_radius)) {
    throw std::invalid_argument(
        "double_helix_spring: need 0 < tube radius < pitch / 4, tube radius < coil radius / 2, turns >= 1, "
        "rings >= 8, segments >= 3");
  }
  const std::vector<Eigen::Vector3d> centre = resampled(smoothed(raw_loop(s)), s.rings);
  const int n = s.rings;
  std::vector<Eigen::Vector3d> tangent(n);
  for (int i = 0; i < n; ++i) tangent[i] = (centre[(i + 1) % n] - centre[(i + n - 1) % n]).normalized();
  // Rotation-minimising frames by parallel transport, then the closing twist spread out.
  std::vector<Eigen::Vector3d> normal(n);
  Eigen::Vector3d seed = tangent[0].cross(Eigen::Vector3d::UnitZ());
  if (seed.norm() < 1e-6) seed = tangent[0].cross(Eigen::Vector3d::UnitX());
  normal[0] = seed.normalized();
  for (int i = 1; i <= n; ++i) {
    const Eigen::Vector3d& t = tangent[i % n];
    const Eigen::Vector3d transported = Eigen::Quaterniond::FromTwoVectors(tangent[i - 1], t) * normal[i - 1];
    if (i < n) normal[i] = (transported - transported.dot(t) * t).normalized();
    if (i == n) {
      const double twist = std::atan2(tangent[0].dot(transported.cross(normal[0])), transported.dot(normal[0]));
      for (int k = 0; k < n; ++k) normal[k] = Eigen::AngleAxisd(twist * k / n, tangent[k]) * normal[k];
    }
  }
  std::vector<Eigen::Vector3d> vertices;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d binormal = tangent[i].cross(normal[i]);
    for (int j = 0; j < s.segments; ++j) {
      const double a = 2 * M_PI * j / s.segments;
      vertices.push_back(centre[i] + s.tube_radius * (std::cos(a) * normal[i] + std::sin(a) * binormal));
    }
  }
  std::vector<Triangle> triangles;
  const auto at = [&](int i, int j) { return (i % n) * s.segments + (j % s.segments); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < s.segments; ++j) {
      // Ring i to ring i + 1, outward normals (the angle runs counter-clockwise about t).
      triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
      triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
    }
  }
  return TriangleMesh(std::move(vertices), std::move(triangles));
}

}  // namespace sscc::validation
