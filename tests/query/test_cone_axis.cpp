// The direction a set of triangles is proven along (cone_axis.hpp): the axis of a nearly
// smallest cone around the normals, independent of their order and lengths, on the normals'
// side where they fit in a cone well inside a half-space though their mean normal does not.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "query/cone_axis.hpp"

namespace {

using Eigen::Vector3d;

double smallest_cosine(const Vector3d& d, const std::vector<Vector3d>& normals) {
  double smallest = 1.0;
  for (const Vector3d& n : normals) smallest = std::min(smallest, d.dot(n.normalized()));
  return smallest;
}

/// A random unit vector.
Vector3d random_direction(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  return Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
}

/// `count` normals of random lengths within `half_angle` of `axis`, crowded on one side: most
/// near the cone's rim on one side, one on the opposite rim, so that their mean leans far off.
std::vector<Vector3d> lopsided_cone(std::mt19937_64& rng, const Vector3d& axis, double half_angle, int count) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const Vector3d side = axis.unitOrthogonal();
  const Vector3d other = axis.cross(side);
  std::vector<Vector3d> normals;
  for (int i = 0; i < count; ++i) {
    const double angle = half_angle * (i == 0 ? -1.0 : 0.8 + 0.2 * uniform(rng));
    const double spin = 0.3 * (uniform(rng) - 0.5);
    const Vector3d across = std::cos(spin) * side + std::sin(spin) * other;
    normals.push_back((0.1 + uniform(rng)) * (std::cos(angle) * axis + std::sin(angle) * across));
  }
  return normals;
}

}  // namespace

TEST_CASE("cone axis: every normal on its side where they fit in a cone, though their mean leans past some",
          "[cone_axis]") {
  std::mt19937_64 rng(29);
  int mean_failed = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Vector3d axis = random_direction(rng);
    const double half_angle = (60.0 + 25.0 * (trial % 5) / 4.0) * M_PI / 180.0;  // 60 to 85 degrees
    const std::vector<Vector3d> normals = lopsided_cone(rng, axis, half_angle, 40);
    Vector3d mean = Vector3d::Zero();
    for (const Vector3d& n : normals) mean += n;
    mean.normalize();
    INFO("trial " << trial << ", half-angle " << half_angle);
    const Vector3d found = sscc::detail::cone_axis(normals);
    REQUIRE(std::abs(found.norm() - 1.0) < 1e-15);
    CHECK(smallest_cosine(found, normals) > 0.0);
    mean_failed += smallest_cosine(mean, normals) <= 0.0;
    // axis_to_try offers the axis where the mean leans more than kLargestCosineForAxis allows.
    const Vector3d offered = sscc::detail::axis_to_try(mean, normals);
    if (smallest_cosine(mean, normals) < sscc::detail::kLargestCosineForAxis) {
      CHECK(offered == found);
    } else {
      CHECK(offered.isZero());
    }
  }
  CHECK(mean_failed > 50);  // the cases the axis is for
}

TEST_CASE("cone axis: the same axis for the normals in any order, zero vectors skipped", "[cone_axis]") {
  std::mt19937_64 rng(31);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Vector3d> normals = lopsided_cone(rng, random_direction(rng), 1.2, 25);
    const Vector3d axis = sscc::detail::cone_axis(normals);
    std::shuffle(normals.begin(), normals.end(), rng);
    normals.insert(normals.begin() + trial % normals.size(), Vector3d::Zero());
    CHECK(sscc::detail::cone_axis(normals) == axis);
  }
}

TEST_CASE("cone axis: none for normals all around, and none offered where it gains nothing", "[cone_axis]") {
  const std::vector<Vector3d> all_around = {Vector3d::UnitX(),  -Vector3d::UnitX(), Vector3d::UnitY(),
                                            -Vector3d::UnitY(), Vector3d::UnitZ(),  -Vector3d::UnitZ()};
  CHECK(sscc::detail::cone_axis(all_around).isZero());
  CHECK(sscc::detail::cone_axis({}).isZero());
  CHECK(sscc::detail::cone_axis({Vector3d::Zero()}).isZero());
  const Vector3d mean = Vector3d(0.0, 0.0, 1.0);
  CHECK(sscc::detail::axis_to_try(mean, all_around).isZero());
  // Normals on both sides of a wedge with an obtuse mean tilt: the axis splits the wedge, and
  // it is offered; the same normals about the axis itself offer none (no gain).
  const std::vector<Vector3d> wedge = {Vector3d(1.0, 0.0, 0.2), Vector3d(-1.0, 0.0, 0.2)};
  const Vector3d tilted = Vector3d(1.0, 0.0, 0.1).normalized();
  const Vector3d offered = sscc::detail::axis_to_try(tilted, wedge);
  CHECK(offered.dot(Vector3d::UnitZ()) > 0.999);
  CHECK(smallest_cosine(offered, wedge) > 0.19);
  CHECK(sscc::detail::axis_to_try(offered, wedge).isZero());
}
