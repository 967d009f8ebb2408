// The separating-plane cull of triangle pairs (query/separating_plane.hpp) against exact
// rational arithmetic on the same doubles (GMP) and against the kernels on every feature
// pair: a certified side is the exact cubic's sign at every t, and a separated pair never
// touches. Random, nearly coplanar, crossing, tiny, far and huge pairs.
#include <catch2/catch.hpp>

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "brute_force.hpp"
#include "query/separating_plane.hpp"
#include "support/exact_vectors.hpp"

namespace {

using Eigen::Vector3d;
using namespace sscc::test;  // the exact vectors (support/exact_vectors.hpp)

/// A moving pair: x[0..2] triangle A at t = 0, x[3..5] B at t = 0, x[6..11] the same at t = 1.
using MovingPair = std::array<Vector3d, 12>;

/// (p - a)(t) . n_A(t) in exact arithmetic at rational t, for vertex k of B.
mpq_class exact_side(const MovingPair& x, int k, const mpq_class& t) {
  const Exact3 a = lerp(exact(x[0]), exact(x[6]), t);
  const Exact3 b = lerp(exact(x[1]), exact(x[7]), t);
  const Exact3 c = lerp(exact(x[2]), exact(x[8]), t);
  const Exact3 p = lerp(exact(x[3 + k]), exact(x[9 + k]), t);
  return dot(minus(p, a), cross(minus(b, a), minus(c, a)));
}

/// The exact Bernstein coefficients of that cubic (times 3 for the middle two).
std::array<mpq_class, 4> exact_cubic(const MovingPair& x, int k) {
  const std::array<Exact3, 3> n = sscc::test::exact_normal_coefficients(x[0], x[1], x[2], x[6], x[7], x[8]);
  const Exact3 d0 = minus(exact(x[3 + k]), exact(x[0])), d1 = minus(exact(x[9 + k]), exact(x[6]));
  return {dot(d0, n[0]), 2 * dot(d0, n[1]) + dot(d1, n[0]), dot(d0, n[2]) + 2 * dot(d1, n[1]), dot(d1, n[2])};
}

/// Pairs of the kinds the traversal meets and the hard ones: 0 B a little off A's plane and
/// moving a little (often separated), 1 B nearly in A's plane (within 1e-4 to 1e-16), 2 B
/// crossing A's plane during the step, 3 tiny (1e-7), 4 far from the origin (1e6), 5 at
/// 2^-300 (the cubic's coefficients near 1e-270), 6 at 2^295 (near the largest tested, its
/// products near 2^890), 7 at 2^-500 (they underflow).
MovingPair random_pair(std::mt19937_64& rng, int kind) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto random_vector = [&] { return Vector3d(unit(rng), unit(rng), unit(rng)); };
  MovingPair x;
  for (int k = 0; k < 3; ++k) x[k] = Vector3d(unit(rng), unit(rng), 0.0);
  const double height = kind == 1 ? std::pow(10.0, -4.0 - 12.0 * (unit(rng) + 1.0) / 2.0) : 0.3;
  const double side = unit(rng) > 0 ? 1.0 : -1.0;
  for (int k = 0; k < 3; ++k) {
    x[3 + k] = Vector3d(unit(rng), unit(rng), side * height * (1.0 + unit(rng)) * 0.5 + (kind == 1 ? 0.0 : 0.01));
  }
  const double motion = kind == 1 ? 1e-3 : 0.1;
  for (int k = 0; k < 6; ++k) x[6 + k] = x[k] + motion * random_vector();
  if (kind == 2) {
    for (int k = 3; k < 6; ++k) x[6 + k].z() = -x[k].z();
  }
  const Vector3d tilt = random_vector();  // a general orientation: tilt the whole pair
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(3.0 * unit(rng), tilt.normalized()).toRotationMatrix();
  const double scale = kind == 3 ? 1e-7 : kind == 5 ? 0x1p-300 : kind == 6 ? 0x1p295 : kind == 7 ? 0x1p-500 : 1.0;
  const Vector3d offset = kind == 4 ? Vector3d(1e6 * random_vector()) : Vector3d::Zero();
  for (Vector3d& p : x) p = offset + scale * (rotation * p);
  return x;
}

}  // namespace

TEST_CASE("separating plane: a certified side is the exact cubic's sign on the whole step", "[separating_plane]") {
  std::mt19937_64 rng(41);
  int certified = 0, refused_exact = 0, small_certified = 0, large_certified = 0, underflow_certified = 0;
  for (int trial = 0; trial < 8000; ++trial) {
    const int kind = trial % 8;
    const MovingPair x = random_pair(rng, kind);
    const sscc::detail::BernsteinNormals n = sscc::detail::bernstein_normals(x[0], x[1], x[2], x[6], x[7], x[8]);
    INFO("trial " << trial << " kind " << kind);
    const sscc::Triangle a{0, 1, 2}, b{3, 4, 5};
    REQUIRE(sscc::detail::within_plane_range(x.data(), x.data() + 6, a, b));
    for (int k = 0; k < 3; ++k) {
      const int side = sscc::detail::certain_side(x[3 + k], x[9 + k], x[0], x[6], n);
      const std::array<mpq_class, 4> cubic = exact_cubic(x, k);
      const bool all_positive = cubic[0] > 0 && cubic[1] > 0 && cubic[2] > 0 && cubic[3] > 0;
      const bool all_negative = cubic[0] < 0 && cubic[1] < 0 && cubic[2] < 0 && cubic[3] < 0;
      if (side != 0) {
        ++certified;
        small_certified += kind == 5;
        large_certified += kind == 6;
        underflow_certified += kind == 7;
        REQUIRE((side > 0 ? all_positive : all_negative));
        for (int j = 0; j <= 8; ++j) REQUIRE(sgn(exact_side(x, k, mpq_class(j) / 8)) == side);
      } else if (all_positive || all_negative) {
        ++refused_exact;
      }
    }
  }
  CHECK(certified > 6000);          // most clear cases are decided
  CHECK(small_certified > 1000);    // also at 2^-300
  CHECK(large_certified > 1000);    // and at 2^295
  CHECK(refused_exact > 0);         // some exact signs too close to call are refused
  CHECK(underflow_certified == 0);  // underflowing products never certify
}

TEST_CASE("separating plane: a pair it separates has no touching feature pair", "[separating_plane]") {
  std::mt19937_64 rng(43);
  const sscc::Triangle a{0, 1, 2}, b{3, 4, 5};
  int separated = 0, touching = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const MovingPair x = random_pair(rng, trial % 5);
    const std::vector<Vector3d> x0(x.begin(), x.begin() + 6), x1(x.begin() + 6, x.end());
    const sscc::detail::BernsteinNormals na = sscc::detail::bernstein_normals(x0[0], x0[1], x0[2], x1[0], x1[1], x1[2]);
    const sscc::detail::BernsteinNormals nb = sscc::detail::bernstein_normals(x0[3], x0[4], x0[5], x1[3], x1[4], x1[5]);
    const bool culled = sscc::detail::plane_separates(x0.data(), x1.data(), a, na, b) ||
                        sscc::detail::plane_separates(x0.data(), x1.data(), b, nb, a);
    const bool touches = sscc::validation::triangle_pair_first_contact(x0, x1, a, b) <= 1.0;
    INFO("trial " << trial);
    if (culled) {
      ++separated;
      REQUIRE_FALSE(touches);
    }
    touching += touches;
  }
  CHECK(separated > 1000);
  CHECK(touching > 100);  // the crossing pairs do touch, and were never separated
}

TEST_CASE("separating plane: pairs beyond 2^300 are out of range", "[separating_plane]") {
  const sscc::Triangle a{0, 1, 2}, b{3, 4, 5};
  std::vector<Vector3d> x = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 5}, {1, 0, 5}, {0, 1, 5}};
  CHECK(sscc::detail::within_plane_range(x.data(), x.data(), a, b));
  for (Vector3d& p : x) p *= 0x1p298;  // coordinates up to 5 * 2^298 > 2^300
  CHECK_FALSE(sscc::detail::within_plane_range(x.data(), x.data(), a, b));
}

TEST_CASE("separating plane: a triangle that turns over, or is degenerate, separates nothing", "[separating_plane]") {
  // A's normal flips from +z to -z through a degenerate instant; B stays high above.
  const sscc::Triangle a{0, 1, 2}, b{3, 4, 5};
  const std::vector<Vector3d> x0 = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 5}, {1, 0, 5}, {0, 1, 5}};
  std::vector<Vector3d> x1 = x0;
  x1[2] = Vector3d(0, -1, 0);
  const auto n = [](const std::vector<Vector3d>& p0, const std::vector<Vector3d>& p1) {
    return sscc::detail::bernstein_normals(p0[0], p0[1], p0[2], p1[0], p1[1], p1[2]);
  };
  CHECK_FALSE(sscc::detail::plane_separates(x0.data(), x1.data(), a, n(x0, x1), b));
  // Fixed, A separates B (and B, parallel above, separates A).
  CHECK(sscc::detail::plane_separates(x0.data(), x0.data(), a, n(x0, x0), b));
  // A degenerate A (its third vertex on its first edge) has no plane.
  std::vector<Vector3d> flat = x0;
  flat[2] = Vector3d(0.5, 0, 0);
  CHECK_FALSE(sscc::detail::plane_separates(flat.data(), flat.data(), a, n(flat, flat), b));
}

TEST_CASE("separating plane: a vertex in the triangle's plane throughout, or reaching it at t = 1, is not certified",
          "[separating_plane]") {
  // Integer lattices times powers of two: b = a + 2u, c = a + 4w and p = a + u + w at both
  // ends, each exact, so p(t) lies in the plane of (a, b, c)(t) for every t and the cubic is
  // exactly 0, while its products (near 2^61 times the scale's cube) round.
  std::mt19937_64 rng(47);
  std::uniform_int_distribution<long> coordinate(-(1L << 22), 1L << 22), offset(-(1L << 20), 1L << 20);
  const auto lattice = [&](std::uniform_int_distribution<long>& d) {
    return Vector3d(static_cast<double>(d(rng)), static_cast<double>(d(rng)), static_cast<double>(d(rng)));
  };
  int static_rounded = 0;
  for (const double scale : {0x1p-200, 0x1p-30, 1.0, 0x1p40, 0x1p250}) {
    for (int trial = 0; trial < 400; ++trial) {
      std::array<Vector3d, 4> ends[2];  // a, b, c, p
      for (int end = 0; end < 2; ++end) {
        const Vector3d a = lattice(coordinate), u = lattice(offset), w = lattice(offset);
        ends[end] = {a, a + 2 * u, a + 4 * w, a + u + w};
        for (Vector3d& x : ends[end]) x *= scale;
      }
      if (trial % 2 == 0) ends[1] = ends[0];  // at rest: the four coefficients one rounded value
      const sscc::detail::BernsteinNormals n =
          sscc::detail::bernstein_normals(ends[0][0], ends[0][1], ends[0][2], ends[1][0], ends[1][1], ends[1][2]);
      INFO("scale " << scale << " trial " << trial);
      REQUIRE(sscc::detail::certain_side(ends[0][3], ends[1][3], ends[0][0], ends[1][0], n) == 0);
      const Vector3d d = ends[0][3] - ends[0][0];
      static_rounded += trial % 2 == 0 && d.dot(n.value[0]) != 0.0;
    }
  }
  CHECK(static_rounded > 100);  // the computed cubic was not 0: only the bound refused it

  // B comes down onto A: its first vertex lands on A's interior at t = 1.
  const sscc::Triangle a{0, 1, 2}, b{3, 4, 5};
  const std::vector<Vector3d> x0 = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, 1}, {2, 0, 1.5}, {0, 2, 1.5}};
  const std::vector<Vector3d> x1 = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, 0}, {2, 0, 0.5}, {0, 2, 0.5}};
  const auto normals = [&](const sscc::Triangle& t) {
    return sscc::detail::bernstein_normals(x0[t[0]], x0[t[1]], x0[t[2]], x1[t[0]], x1[t[1]], x1[t[2]]);
  };
  CHECK_FALSE(sscc::detail::plane_separates(x0.data(), x1.data(), a, normals(a), b));
  CHECK_FALSE(sscc::detail::plane_separates(x0.data(), x1.data(), b, normals(b), a));
  CHECK(sscc::validation::triangle_pair_first_contact(x0, x1, a, b) <= 1.0);
}
