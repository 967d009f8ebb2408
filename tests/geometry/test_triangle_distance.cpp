#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <random>

#include "sscc/ccd/kernels.hpp"
#include "sscc/geometry/triangle_distance.hpp"

namespace {

using Triangle3 = std::array<Eigen::Vector3d, 3>;

Eigen::Vector3d at(const Triangle3& t, const Eigen::Vector3d& w) { return w[0] * t[0] + w[1] * t[1] + w[2] * t[2]; }

/// Smallest distance between points of a barycentric grid on each triangle: at least the
/// true distance.
double sampled_distance(const Triangle3& a, const Triangle3& b, int grid) {
  double best = INFINITY;
  for (int i = 0; i <= grid; ++i) {
    for (int j = 0; i + j <= grid; ++j) {
      const Eigen::Vector3d pa = at(a, Eigen::Vector3d(double(i), double(j), double(grid - i - j)) / grid);
      for (int k = 0; k <= grid; ++k) {
        for (int l = 0; k + l <= grid; ++l) {
          best =
              std::min(best, (pa - at(b, Eigen::Vector3d(double(k), double(l), double(grid - k - l)) / grid)).norm());
        }
      }
    }
  }
  return best;
}

}  // namespace

TEST_CASE("triangle distance: achieved by the returned points and no larger than any sampled pair", "[geometry]") {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal;
  const auto random_point = [&](double spread) {
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k) p[k] = spread * normal(rng);
    return p;
  };
  int tested = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Triangle3 a{random_point(1), random_point(1), random_point(1)};
    Triangle3 b{random_point(1), random_point(1), random_point(1)};
    if (trial % 4 == 1) b = {a[0] + random_point(1e-3), a[1] + random_point(1e-3), a[2] + random_point(1e-3)};
    if (trial % 4 == 2) b = {a[1] + random_point(0.3), a[2] + random_point(0.3), a[2] + random_point(1e-6)};  // needle
    if (trial % 4 == 3) {  // parallel, offset along the normal
      const Eigen::Vector3d normal_a = (a[1] - a[0]).cross(a[2] - a[0]).normalized();
      const Eigen::Vector3d shift = 0.1 * normal_a + random_point(0.5).cross(normal_a);
      b = {a[0] + shift, a[1] + shift, a[2] + shift};
    }
    if (sscc::ccd::triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2])) continue;
    ++tested;
    const sscc::TriangleClosestPoints c = sscc::closest_points_disjoint_triangles(a, b);
    INFO("trial " << trial);
    for (const Eigen::Vector3d* w : {&c.first_weights, &c.second_weights}) {
      REQUIRE(w->minCoeff() >= 0.0);
      REQUIRE(w->sum() == Approx(1.0).margin(1e-12));
    }
    REQUIRE((at(a, c.first_weights) - at(b, c.second_weights)).norm() == Approx(c.distance).margin(1e-12));
    REQUIRE(c.distance <= sampled_distance(a, b, 24) + 1e-12);
  }
  REQUIRE(tested > 200);
}
