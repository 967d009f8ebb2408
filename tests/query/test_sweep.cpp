// The sweeps' test (query/sweep.hpp) against the kernels on every feature pair: two triangles
// it holds apart never come within the separation, at d = 0 and d > 0; it culls every pair
// the swept boxes' test culls in any frame moving linearly, and pairs moving together
// across a large distance, which the swept boxes do not.
#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <array>
#include <random>
#include <vector>

#include "brute_force.hpp"
#include "query/sweep.hpp"

namespace {

using Eigen::Vector3d;
using sscc::detail::Sweep;

const sscc::Triangle kA{0, 1, 2}, kB{3, 4, 5};

/// Triangles A (vertices 0..2) and B (3..5) at both ends of a step.
struct MovingPair {
  std::vector<Vector3d> x0, x1;
  Sweep sweep(const sscc::Triangle& t) const { return {sscc::detail::box_at(x0, t), sscc::detail::box_at(x1, t)}; }
};

/// Pairs the traversal meets and the hard ones: 0 near each other (often touching), each
/// moving on its own; 1 the same moving together by up to 100 times their gap (the swept boxes
/// overlap); 2 one passing through the other's place during the step, apart at both ends on
/// opposite sides; 3 a vertex of each meeting at t = 1.
MovingPair random_pair(std::mt19937_64& rng, int kind) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto random_vector = [&] { return Vector3d(unit(rng), unit(rng), unit(rng)); };
  MovingPair p{std::vector<Vector3d>(6), std::vector<Vector3d>(6)};
  const double gap = -0.2 + 0.25 * (unit(rng) + 1.0);  // -0.2 to 0.3 between the two halves
  for (int k = 0; k < 3; ++k) {
    p.x0[k] = 0.5 * random_vector();
    p.x0[3 + k] = 0.5 * random_vector() + Vector3d(0.0, 0.0, 0.5 + gap);
  }
  const Vector3d shared = kind == 1 ? Vector3d(100.0 * gap * random_vector()) : Vector3d::Zero();
  for (int k = 0; k < 6; ++k) p.x1[k] = p.x0[k] + shared + 0.3 * random_vector();
  if (kind == 2) {
    for (int k = 3; k < 6; ++k) p.x1[k].z() = -p.x0[k].z();  // B ends below A's place
  }
  if (kind == 3) {
    p.x1[3] = p.x1[0];  // B's vertex lands on A's at t = 1
  }
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(3.0 * unit(rng), random_vector().normalized()).toRotationMatrix();
  for (Vector3d& x : p.x0) x = rotation * x;
  for (Vector3d& x : p.x1) x = rotation * x;
  return p;
}

/// Whether the swept boxes of the step, both ends' boxes shifted at t = 1 by -c (the frame
/// moving with velocity c), stay farther than d apart along some axis.
bool apart_in_frame(const Sweep& a, const Sweep& b, const Vector3d& c, double d) {
  for (int k = 0; k < 3; ++k) {
    const double a_lo = std::min(a.start.lo[k], a.end.lo[k] - c[k]), a_hi = std::max(a.start.hi[k], a.end.hi[k] - c[k]);
    const double b_lo = std::min(b.start.lo[k], b.end.lo[k] - c[k]), b_hi = std::max(b.start.hi[k], b.end.hi[k] - c[k]);
    if (b_lo - a_hi > d || a_lo - b_hi > d) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("sweep: a pair held apart never comes within the separation", "[sweep]") {
  std::mt19937_64 rng(53);
  for (const double d : {0.0, 0.02}) {
    sscc::ccd::CcdOptions options;
    // The kernels may report pairs up to d (1 + 1e-3) apart (ccd_types.hpp,
    // kSeparationRelativeTolerance): asked at 0.99 d, they never report a pair held beyond d.
    options.minimum_separation = 0.99 * d;
    std::array<int, 4> culled{}, touching{};
    for (int trial = 0; trial < 4000; ++trial) {
      const int kind = trial % 4;
      const MovingPair p = random_pair(rng, kind);
      const bool may_touch = sscc::detail::sweeps_may_touch(p.sweep(kA), p.sweep(kB), d);
      const bool touches = sscc::validation::triangle_pair_first_contact(p.x0, p.x1, kA, kB, options) <= 1.0;
      INFO("d " << d << " trial " << trial << " kind " << kind);
      if (!may_touch) REQUIRE_FALSE(touches);
      culled[kind] += !may_touch;
      touching[kind] += touches;
    }
    INFO("culled " << culled[0] << " " << culled[1] << " touching " << touching[0] << " " << touching[1] << " "
                   << touching[2] << " " << touching[3]);
    CHECK(culled[0] > 300);    // many pairs apart,
    CHECK(culled[1] > 300);    // also those moving far together;
    CHECK(touching[0] > 100);  // many touching,
    CHECK(touching[2] > 100);  // those passing through too,
    CHECK(touching[3] > 900);  // and those meeting at t = 1, all kept
  }
}

TEST_CASE("sweep: as tight as the swept boxes in every frame moving linearly", "[sweep]") {
  std::mt19937_64 rng(59);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int apart_at_rest = 0, apart_only_moving = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const MovingPair p = random_pair(rng, trial % 2);
    const Sweep a = p.sweep(kA), b = p.sweep(kB);
    const Vector3d c = (p.x1[0] - p.x0[0]) + Vector3d(unit(rng), unit(rng), unit(rng));
    const double d = trial % 3 == 0 ? 0.0 : 0.01;
    INFO("trial " << trial);
    if (apart_in_frame(a, b, Vector3d::Zero(), d)) {
      ++apart_at_rest;
      REQUIRE_FALSE(sscc::detail::sweeps_may_touch(a, b, d));
    }
    if (apart_in_frame(a, b, c, d)) {
      apart_only_moving += !apart_in_frame(a, b, Vector3d::Zero(), d);
      REQUIRE_FALSE(sscc::detail::sweeps_may_touch(a, b, d));
    }
  }
  INFO("at rest " << apart_at_rest << " moving " << apart_only_moving);
  CHECK(apart_at_rest > 2000);
  CHECK(apart_only_moving > 600);  // pairs only a moving frame's swept boxes hold apart
}

TEST_CASE("sweep: boxes touching at an end, or exactly d apart there, may touch", "[sweep]") {
  const Sweep below{{Vector3d(0, 0, 0), Vector3d(1, 1, 1)}, {Vector3d(0, 0, 5), Vector3d(1, 1, 6)}};
  const Sweep above_at_start{{Vector3d(0, 0, 3), Vector3d(1, 1, 4)}, {Vector3d(0, 0, 6), Vector3d(1, 1, 7)}};
  CHECK(sscc::detail::sweeps_may_touch(below, above_at_start, 0.0));  // faces meet at t = 1
  Sweep lifted = above_at_start;
  lifted.end.lo.z() = 6.5;
  lifted.end.hi.z() = 7.5;
  CHECK_FALSE(sscc::detail::sweeps_may_touch(below, lifted, 0.0));  // 2 apart at t = 0, 0.5 at t = 1
  CHECK(sscc::detail::sweeps_may_touch(below, lifted, 0.5));        // exactly d apart at t = 1
  CHECK_FALSE(sscc::detail::sweeps_may_touch(below, lifted, 0.49));
}
