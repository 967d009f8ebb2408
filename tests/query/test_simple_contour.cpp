// The general contour test (simple_contour.hpp) against exact arithmetic: a loop it accepts is
// a simple polygon in projection at every sampled rational time of the step, checked with
// rationals on the same doubles; loops that cross themselves, fold or touch are refused.
#include <catch2/catch.hpp>

#include <gmpxx.h>

#include <cmath>
#include <random>

#include "query/simple_contour.hpp"

namespace {

using Eigen::Vector3d;
using sscc::detail::DirectedEdge;

std::vector<DirectedEdge> cycle(int n) {
  std::vector<DirectedEdge> chain;
  for (int i = 0; i < n; ++i) chain.push_back({i, (i + 1) % n});
  return chain;
}

/// A jagged closed loop in the plane z = 0: angles advancing by one turn, radius alternating
/// between an inner and an outer value (a star polygon, not star-shaped about its vertex mean
/// once shifted), then every vertex moved off centre by `offset` in x.
std::vector<Vector3d> jagged_loop(int n, double inner, double offset, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  std::vector<Vector3d> x;
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * M_PI * i / n + jitter(rng);
    const double r = (i % 2 == 0 ? 1.0 : inner) + jitter(rng);
    x.emplace_back(r * std::cos(angle) + offset, r * std::sin(angle), jitter(rng));
  }
  return x;
}

using Point = std::array<mpq_class, 2>;

mpq_class orientation(const Point& a, const Point& b, const Point& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

bool on_segment(const Point& p, const Point& a, const Point& b) {
  return orientation(a, b, p) == 0 && std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) &&
         std::min(a[1], b[1]) <= p[1] && p[1] <= std::max(a[1], b[1]);
}

bool segments_meet(const Point& a, const Point& b, const Point& c, const Point& d) {
  const int o1 = sgn(orientation(a, b, c)), o2 = sgn(orientation(a, b, d));
  const int o3 = sgn(orientation(c, d, a)), o4 = sgn(orientation(c, d, b));
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return on_segment(c, a, b) || on_segment(d, a, b) || on_segment(a, c, d) || on_segment(b, c, d);
}

/// Exact: the loop projected along z at time t is a simple polygon (distinct vertices, edges
/// meeting only at consecutive shared ends, consecutive edges not folded onto each other).
bool exactly_simple(const std::vector<Vector3d>& x0, const std::vector<Vector3d>& x1, const mpq_class& t) {
  const int n = static_cast<int>(x0.size());
  std::vector<Point> p(n);
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < 2; ++k) p[i][k] = mpq_class(x0[i][k]) + t * (mpq_class(x1[i][k]) - mpq_class(x0[i][k]));
  }
  for (int i = 0; i < n; ++i) {
    const Point &a = p[i], &b = p[(i + 1) % n];
    for (int j = i + 1; j < n; ++j) {
      const Point &c = p[j], &d = p[(j + 1) % n];
      const bool consecutive = j == i + 1 || (i == 0 && j == n - 1);
      if (!consecutive && segments_meet(a, b, c, d)) return false;
      if (consecutive) {
        // The shared vertex is b (j = i + 1) or a (the wrap): the far ends must stay off.
        const Point& far_own = j == i + 1 ? a : b;
        const Point& far_other = j == i + 1 ? d : c;
        const Point& shared = j == i + 1 ? b : a;
        if (on_segment(far_other, a, b) || on_segment(far_own, c, d) || far_own == shared) return false;
      }
    }
  }
  return true;
}

}  // namespace

TEST_CASE("simple contour: accepted loops are simple in projection at every sampled time", "[contour]") {
  // Also with the positions times powers of two (exact; simplicity does not change): at
  // 2^-280 and 2^-400 the products in the predicates are near 1e-169 and 1e-241, their squares
  // subnormal or 0; at 2^300 near 1e180, their squares infinite. At 2^-500 the products fall
  // near 1e-301, below the certified signs' absolute allowance: refusals there only lose culls.
  const std::vector<double> scales{0x1p-280, 0x1p-400, 0x1p-500, 0x1p250, 0x1p300};
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Vector3d up(0, 0, 1);
  int accepted = 0, refused = 0;
  std::vector<int> accepted_scaled(scales.size(), 0);
  for (int trial = 0; trial < 400; ++trial) {
    const int n = 6 + 2 * (trial % 12);
    const std::vector<Vector3d> x0 = jagged_loop(n, 0.4 + 0.5 * (trial % 5) / 5.0, 0.3 * (trial % 3), rng);
    std::vector<Vector3d> x1 = x0;
    const double motion = trial % 4 == 0 ? 0.8 : 0.15;  // large motions make some loops cross
    for (Vector3d& p : x1) p += motion * Vector3d(unit(rng), unit(rng), unit(rng));
    INFO("trial " << trial);
    const bool passes = sscc::detail::stays_simple_in_projection(up, cycle(n), x0, x1);
    bool passes_scaled = false;
    for (std::size_t i = 0; i < scales.size(); ++i) {
      std::vector<Vector3d> y0 = x0, y1 = x1;
      for (Vector3d& p : y0) p *= scales[i];
      for (Vector3d& p : y1) p *= scales[i];
      const bool scaled = sscc::detail::stays_simple_in_projection(up, cycle(n), y0, y1);
      accepted_scaled[i] += scaled;
      passes_scaled = passes_scaled || scaled;
    }
    if (passes || passes_scaled) {
      // The exact answer is the same at every scale: checked on the unscaled positions.
      for (int k = 0; k <= 64; ++k) REQUIRE(exactly_simple(x0, x1, mpq_class(k, 64)));
    }
    (passes ? accepted : refused) += 1;
  }
  CHECK(accepted > 100);
  CHECK(refused > 30);
  for (std::size_t i = 0; i < scales.size(); ++i) {
    INFO("positions times " << scales[i] << ": " << accepted_scaled[i] << " accepted of " << accepted);
    if (scales[i] != 0x1p-500) CHECK(accepted_scaled[i] == accepted);
  }
}

TEST_CASE("simple contour: loops that cross, fold, touch or collapse are refused", "[contour]") {
  const Vector3d up(0, 0, 1);
  // A bow tie: edges (1, 2) and (3, 0) cross at the origin.
  const std::vector<Vector3d> bow_tie{{-1, -1, 0}, {1, 1, 0}, {1, -1, 0}, {-1, 1, 0}};
  CHECK_FALSE(sscc::detail::stays_simple_in_projection(up, cycle(4), bow_tie, bow_tie));
  // A square seen along +z or -z: simple either way (orientation is not part of the test).
  const std::vector<Vector3d> square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  CHECK(sscc::detail::stays_simple_in_projection(up, cycle(4), square, square));
  CHECK(sscc::detail::stays_simple_in_projection(-up, cycle(4), square, square));
  // Seen edge-on (along +x) the square collapses to a segment.
  CHECK_FALSE(sscc::detail::stays_simple_in_projection(Vector3d(1, 0, 0), cycle(4), square, square));
  // A dart whose notch vertex is pushed through the base edge during the step: it lies on
  // that edge at t = 1/2.
  const std::vector<Vector3d> arrow0{{0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, 0.5, 0}};
  std::vector<Vector3d> arrow1 = arrow0;
  arrow1[3] = {1, -0.5, 0};
  CHECK(sscc::detail::stays_simple_in_projection(up, cycle(4), arrow0, arrow0));
  CHECK_FALSE(sscc::detail::stays_simple_in_projection(up, cycle(4), arrow0, arrow1));
  // Two vertices meeting at t = 1: the loop pinches shut.
  std::vector<Vector3d> pinch0{{0, 0, 0}, {1, -0.2, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1.2, 0}, {0, 1, 0}};
  std::vector<Vector3d> pinch1 = pinch0;
  pinch1[1] = {1, 0.5, 0};
  pinch1[4] = {1, 0.5, 0};
  CHECK(sscc::detail::stays_simple_in_projection(up, cycle(6), pinch0, pinch0));
  CHECK_FALSE(sscc::detail::stays_simple_in_projection(up, cycle(6), pinch0, pinch1));
}
