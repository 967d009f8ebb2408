// The certified sign of a moving triangle's normal against a direction, held against exact
// rational arithmetic on the same doubles (GMP), on random and near-degenerate triangles.
#include <catch2/catch.hpp>

#include <gmpxx.h>

#include <array>
#include <random>

#include "query/normal_cone.hpp"
#include "support/exact_vectors.hpp"

namespace {

using Eigen::Vector3d;
using namespace sscc::test;  // the exact vectors (support/exact_vectors.hpp)

/// d . n(t) in exact arithmetic for the positions as given, at rational t.
mpq_class exact_normal_dot(const Vector3d& d, const std::array<Vector3d, 6>& x, const mpq_class& t) {
  const Exact3 a = lerp(exact(x[0]), exact(x[3]), t);
  const Exact3 b = lerp(exact(x[1]), exact(x[4]), t);
  const Exact3 c = lerp(exact(x[2]), exact(x[5]), t);
  return dot(exact(d), cross(minus(b, a), minus(c, a)));
}

/// The exact Bernstein coefficients d . N_k.
std::array<mpq_class, 3> exact_coefficients(const Vector3d& d, const std::array<Vector3d, 6>& x) {
  const std::array<Exact3, 3> n = sscc::test::exact_normal_coefficients(x[0], x[1], x[2], x[3], x[4], x[5]);
  const Exact3 D = exact(d);
  return {dot(D, n[0]), dot(D, n[1]), dot(D, n[2])};
}

/// A triangle and its motion: random, nearly collinear (c on the line ab plus a tiny offset),
/// far from the origin, or tiny, as `kind` says.
std::array<Vector3d, 6> random_moving_triangle(std::mt19937_64& rng, int kind) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto random_vector = [&] { return Vector3d(unit(rng), unit(rng), unit(rng)); };
  const double scale = kind == 3 ? 1e-7 : 1.0;
  const Vector3d offset = kind == 2 ? Vector3d(1e6 * random_vector()) : Vector3d::Zero();
  std::array<Vector3d, 6> x;
  for (int end = 0; end < 2; ++end) {
    const Vector3d a = random_vector(), b = random_vector();
    Vector3d c = random_vector();
    if (kind == 1)
      c = a + unit(rng) * (b - a) + std::pow(10.0, -4.0 - 12.0 * (unit(rng) + 1.0) / 2.0) * random_vector();
    x[3 * end + 0] = offset + scale * a;
    x[3 * end + 1] = offset + scale * b;
    x[3 * end + 2] = offset + scale * c;
  }
  if (kind != 1) {  // small motions keep the triangle facing one way, so many are positive
    for (int k = 0; k < 3; ++k) x[3 + k] = x[k] + 0.2 * scale * random_vector();
  }
  return x;
}

}  // namespace

TEST_CASE("normal cone: a certified positive normal is positive in exact arithmetic, for every t", "[normal_cone]") {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int certified = 0, refused_positive = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const int kind = trial % 4;
    const std::array<Vector3d, 6> x = random_moving_triangle(rng, kind);
    const sscc::detail::BernsteinNormals n = sscc::detail::bernstein_normals(x[0], x[1], x[2], x[3], x[4], x[5]);
    // Directions along the normal, and nearly orthogonal to it (where the sign is fragile).
    Vector3d d = n.value[0].normalized();
    if (trial % 3 == 1)
      d = (d.cross(Vector3d(unit(rng), unit(rng), unit(rng))).normalized() + 1e-9 * unit(rng) * d).normalized();
    if (trial % 3 == 2) d = Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
    const std::array<mpq_class, 3> coefficients = exact_coefficients(d, x);
    const bool all_positive = coefficients[0] > 0 && coefficients[1] > 0 && coefficients[2] > 0;
    INFO("trial " << trial);
    if (sscc::detail::certainly_positive(d, n)) {
      ++certified;
      REQUIRE(all_positive);
      for (int k = 0; k <= 16; ++k) REQUIRE(exact_normal_dot(d, x, mpq_class(k, 16)) > 0);
    } else if (all_positive) {
      ++refused_positive;
    }
  }
  CHECK(certified > 1000);      // the test decides most clear cases
  CHECK(refused_positive > 0);  // and refuses some positive ones it cannot prove
}

TEST_CASE("normal cone: a triangle that turns over during the step is never certified", "[normal_cone]") {
  // The normal flips from +z to -z through a degenerate instant: no direction can hold it.
  const Vector3d a(0, 0, 0), b(1, 0, 0), c0(0, 1, 0), c1(0, -1, 0);
  const sscc::detail::BernsteinNormals n = sscc::detail::bernstein_normals(a, b, c0, a, b, c1);
  for (const Vector3d& d : {Vector3d(0, 0, 1), Vector3d(0, 0, -1), Vector3d(0, 1, 0), Vector3d(1, 1, 1).normalized()}) {
    CHECK_FALSE(sscc::detail::certainly_positive(d, n));
  }
  // A degenerate triangle (zero area) has no certified sign either.
  const sscc::detail::BernsteinNormals flat = sscc::detail::bernstein_normals(a, b, 2 * b, a, b, 2 * b);
  CHECK_FALSE(sscc::detail::certainly_positive(Vector3d(0, 0, 1), flat));
}

TEST_CASE("normal cone: certified signs of triple products agree with exact arithmetic", "[normal_cone]") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int decided = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Vector3d d = Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
    const Vector3d w = d.cross(Vector3d(unit(rng), unit(rng), unit(rng)));
    const Vector3d c = (trial % 2 ? 1e5 : 1.0) * Vector3d(unit(rng), unit(rng), unit(rng));
    // Points near the plane of d and w through c, where the sign is fragile.
    const Vector3d p = c + unit(rng) * d + unit(rng) * w +
                       std::pow(10.0, -3.0 - 14.0 * (unit(rng) + 1.0) / 2.0) * d.cross(w).normalized() * unit(rng);
    const int sign = sscc::detail::certified_sign_of_triple(d, w, p, c);
    const mpq_class value = dot(exact(d), cross(exact(w), minus(exact(p), exact(c))));
    INFO("trial " << trial);
    if (sign != 0) {
      ++decided;
      REQUIRE(sgn(value) == sign);
    }
  }
  CHECK(decided > 2000);
}

namespace {

/// Whether the exact vector N lies within `cone` (angle to the axis at most its half-angle h),
/// decided in rationals: axis . N >= cos(h) |axis| |N|, squared with the signs in mind, with
/// the double cos(h) (the cones carry a slack of 1e-9 radians, far above its rounding).
bool exactly_within(const sscc::detail::NormalCone& cone, const Exact3& n) {
  const Exact3 axis = exact(cone.axis);
  const mpq_class along = dot(axis, n);
  const mpq_class c(std::cos(cone.half_angle));
  const mpq_class bound = c * c * dot(axis, axis) * dot(n, n);
  if (c >= 0) return along > 0 && along * along >= bound;
  return along >= 0 || along * along <= bound;
}

/// The exact Bernstein coefficient vectors of a moving triangle.
std::array<Exact3, 3> exact_coefficient_vectors(const std::array<Vector3d, 6>& x) {
  return sscc::test::exact_normal_coefficients(x[0], x[1], x[2], x[3], x[4], x[5]);
}

}  // namespace

TEST_CASE("normal cone: cones of coefficients and merged cones hold every exact coefficient", "[normal_cone]") {
  // Also with the positions times a power of two (exact): at 2^-280 the coefficient vectors'
  // entries are near 1e-169 and their squares underflow, at 2^270 they overflow; a cone's
  // widths and error bounds computed from plain sums of squares came out too narrow there.
  const double scale = GENERATE(1.0, 0x1p-280, 0x1p270);
  INFO("positions times " << scale);
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int narrow = 0;
  for (int trial = 0; trial < 300; ++trial) {
    // Four groups of four moving triangles facing roughly one way (some nearly degenerate).
    std::array<sscc::detail::NormalCone, 4> parts;
    std::vector<std::array<Exact3, 3>> exact_parts[4];
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    for (int g = 0; g < 4; ++g) {
      std::array<sscc::detail::BernsteinNormals, 4> normals;
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (int i = 0; i < 4; ++i) {
        std::array<Vector3d, 6> x = random_moving_triangle(rng, trial % 3 == 0 && i == 1 ? 1 : 0);
        for (Vector3d& p : x) p.z() *= 0.2;  // flattened: normals near the z axis
        if ((x[1] - x[0]).cross(x[2] - x[0]).z() < 0) std::swap(x[1], x[2]), std::swap(x[4], x[5]);
        for (Vector3d& p : x) p *= scale;
        normals[i] = sscc::detail::bernstein_normals(x[0], x[1], x[2], x[3], x[4], x[5]);
        sum += normals[i].value[0] + normals[i].value[1] + normals[i].value[2];
        exact_parts[g].push_back(exact_coefficient_vectors(x));
      }
      const Eigen::Vector3d axis = trial % 5 == 0 ? Eigen::Vector3d(unit(rng), unit(rng), unit(rng)) : sum;
      parts[g] = sscc::detail::cone_of(axis, normals.data(), normals.data() + 4);
      total += sum;
      INFO("trial " << trial << " group " << g);
      if (parts[g].half_angle > M_PI) continue;  // holds everything
      ++narrow;
      for (const auto& coefficients : exact_parts[g]) {
        for (const Exact3& n : coefficients) REQUIRE(exactly_within(parts[g], n));
      }
    }
    const sscc::detail::NormalCone merged = sscc::detail::merged_cone(total, parts.data(), parts.data() + 4);
    if (merged.half_angle > M_PI) continue;
    for (int g = 0; g < 4; ++g) {
      for (const auto& coefficients : exact_parts[g]) {
        for (const Exact3& n : coefficients) REQUIRE(exactly_within(merged, n));
      }
    }
  }
  CHECK(narrow > 400);
}

TEST_CASE("normal cone: an axis shorter than the smallest normal double gives no cone", "[normal_cone]") {
  // A subnormal axis normalises to a vector up to sqrt(2) long (its norm is no longer accurate
  // to a few units of roundoff), and the cones' error terms assume a unit axis; with these
  // coefficients it gave a cone within a half-space where the same direction at any normal
  // length gives none.
  sscc::detail::BernsteinNormals n;
  for (int k = 0; k < 3; ++k) {
    n.value[k] = Vector3d(0.95e-300, 0.95e-300, 0.0);
    n.error[k] = Vector3d::Constant(1e-300);
  }
  for (double length : {1.0, 1e-300}) {
    CHECK_FALSE(sscc::detail::cone_of(Vector3d(length, length, 0.0), &n, &n + 1).within_half_space());
  }
  const Vector3d subnormal(0x1p-1074, 0x1p-1074, 0.0);
  CHECK_FALSE(sscc::detail::cone_of(subnormal, &n, &n + 1).within_half_space());
  const Vector3d tiny_normal(0x1p-1000, 0x1p-1000, 0.0);
  CHECK(std::abs(sscc::detail::cone_of(tiny_normal, &n, &n + 1).axis.norm() - 1.0) < 1e-15);
}
