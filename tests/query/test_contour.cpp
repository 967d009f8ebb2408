// Boundary chains from connectivity and the continuous star-shaped contour test, against
// exact arithmetic on the same doubles.
#include <catch2/catch.hpp>

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "query/contour.hpp"
#include "support/parametric_meshes.hpp"

namespace {

using Eigen::Vector3d;
using sscc::detail::DirectedEdge;

std::vector<DirectedEdge> edges_of(const std::vector<sscc::Triangle>& triangles) {
  std::vector<DirectedEdge> edges;
  for (const sscc::Triangle& t : triangles) {
    for (int k = 0; k < 3; ++k) edges.push_back({t[k], t[(k + 1) % 3]});
  }
  return edges;
}

/// A closed loop of n vertices whose angles about the origin advance by `turns` full turns,
/// radius varying, in the plane z = height; edges (i, i + 1).
std::vector<Vector3d> loop(int n, int turns, double height, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> radius(0.5, 1.5);
  std::vector<Vector3d> x;
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * M_PI * turns * i / n;
    const double r = radius(rng);
    x.emplace_back(r * std::cos(angle), r * std::sin(angle), height);
  }
  return x;
}

std::vector<DirectedEdge> cycle(int n) {
  std::vector<DirectedEdge> chain;
  for (int i = 0; i < n; ++i) chain.push_back({i, (i + 1) % n});
  return chain;
}

mpq_class q(double x) { return mpq_class(x); }

/// Exact: every edge turns strictly counter-clockwise about c(t) seen along d at rational t,
/// and the angles sum to one turn (the crossings of the ray along +x from c(t), counted in
/// the plane z for d = z).
bool exactly_star_shaped_once(const std::vector<DirectedEdge>& chain, const std::vector<Vector3d>& x0,
                              const std::vector<Vector3d>& x1, const mpq_class& t) {
  // c as the implementation forms it: the double mean at each end.
  Vector3d c0 = Vector3d::Zero(), c1 = Vector3d::Zero();
  for (const DirectedEdge& e : chain) c0 += x0[e[0]], c1 += x1[e[0]];
  c0 /= double(chain.size());
  c1 /= double(chain.size());
  const mpq_class cx = q(c0.x()) + t * (q(c1.x()) - q(c0.x())), cy = q(c0.y()) + t * (q(c1.y()) - q(c0.y()));
  int crossings = 0;
  for (const DirectedEdge& e : chain) {
    const mpq_class ax = q(x0[e[0]].x()) + t * (q(x1[e[0]].x()) - q(x0[e[0]].x())) - cx;
    const mpq_class ay = q(x0[e[0]].y()) + t * (q(x1[e[0]].y()) - q(x0[e[0]].y())) - cy;
    const mpq_class bx = q(x0[e[1]].x()) + t * (q(x1[e[1]].x()) - q(x0[e[1]].x())) - cx;
    const mpq_class by = q(x0[e[1]].y()) + t * (q(x1[e[1]].y()) - q(x0[e[1]].y())) - cy;
    if (ax * by - ay * bx <= 0) return false;
    crossings += ay < 0 && by >= 0;  // counter-clockwise edges crossing the +x ray
  }
  return crossings == 1;
}

}  // namespace

TEST_CASE("contour: boundary chains cancel twins and keep same-orientation edges twice", "[contour]") {
  using sscc::detail::boundary_chain;
  using sscc::detail::is_simple_cycle;
  // A square of two triangles: the diagonal cancels, four edges remain, one cycle.
  const auto square = boundary_chain(edges_of({{0, 1, 2}, {0, 2, 3}}));
  CHECK(square == std::vector<DirectedEdge>{{0, 1}, {1, 2}, {2, 3}, {3, 0}});
  CHECK(is_simple_cycle(square));
  // A closed tetrahedron has no boundary.
  const auto closed = boundary_chain(edges_of({{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}));
  CHECK(closed.empty());
  CHECK_FALSE(is_simple_cycle(closed));
  // Inconsistent orientation: the shared edge (0, 2) stays, twice.
  const auto folded = boundary_chain(edges_of({{0, 1, 2}, {0, 3, 2}}));
  CHECK(std::count(folded.begin(), folded.end(), DirectedEdge{2, 0}) == 2);
  CHECK_FALSE(is_simple_cycle(folded));
  // Two triangles meeting at one vertex (a bow tie) and two apart: not one simple cycle.
  CHECK_FALSE(is_simple_cycle(boundary_chain(edges_of({{0, 1, 2}, {0, 3, 4}}))));
  CHECK_FALSE(is_simple_cycle(boundary_chain(edges_of({{0, 1, 2}, {3, 4, 5}}))));
  // A non-manifold fan: three triangles on edge (0, 1).
  CHECK_FALSE(is_simple_cycle(boundary_chain(edges_of({{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}))));
}

TEST_CASE("contour: a union of two simple cycles is accepted only as the one simple cycle of the sum", "[contour]") {
  using sscc::detail::boundary_chain;
  using sscc::detail::is_simple_cycle;
  // Patches grown on a 10 x 10 grid (a torus when wrapped): pairs that share one path, several
  // paths (an annulus), only a vertex, or nothing.
  std::mt19937_64 rng(5);
  int accepted = 0, refused = 0;
  for (const bool wrap : {false, true}) {
    const std::vector<sscc::Triangle> triangles = sscc::test::grid_triangles(10, 10, wrap, wrap);
    const int n = static_cast<int>(triangles.size());
    const auto shared_vertices = [&](int s, int t) {
      int count = 0;
      for (int v : triangles[s]) count += std::count(triangles[t].begin(), triangles[t].end(), v);
      return count;
    };
    // A random region of up to `size` triangles grown from `seed` through shared edges, and now
    // and then through a shared vertex only (so some are not discs), avoiding `taken`.
    const auto grow = [&](int seed, int size, const std::vector<char>& taken) {
      std::vector<int> region{seed};
      std::vector<char> in(n, 0);
      in[seed] = 1;
      for (int tries = 0; static_cast<int>(region.size()) < size && tries < 200 * size; ++tries) {
        const int from = region[std::uniform_int_distribution<int>(0, static_cast<int>(region.size()) - 1)(rng)];
        const int t = std::uniform_int_distribution<int>(0, n - 1)(rng);
        const int needed = tries % 17 == 0 ? 1 : 2;
        if (!in[t] && !taken[t] && shared_vertices(from, t) >= needed) in[t] = 1, region.push_back(t);
      }
      return region;
    };
    for (int trial = 0; trial < 3000; ++trial) {
      std::vector<char> taken(n, 0);
      const std::vector<int> a = grow(std::uniform_int_distribution<int>(0, n - 1)(rng), 1 + trial % 40, taken);
      for (int t : a) taken[t] = 1;
      // b starts beside a (an edge, or a vertex now and then) or anywhere.
      std::vector<int> beside;
      const int needed = trial % 5 == 0 ? 1 : 2;
      for (int t = 0; t < n; ++t) {
        for (int s : a) {
          if (!taken[t] && shared_vertices(s, t) >= needed) {
            beside.push_back(t);
            break;
          }
        }
      }
      if (trial % 11 == 0 || beside.empty()) beside.assign(1, std::uniform_int_distribution<int>(0, n - 1)(rng));
      const int seed_b = beside[std::uniform_int_distribution<int>(0, static_cast<int>(beside.size()) - 1)(rng)];
      if (taken[seed_b]) continue;
      const std::vector<int> b = grow(seed_b, 1 + (trial / 40) % 40, taken);
      std::vector<sscc::Triangle> ta, tb, both;
      for (int t : a) ta.push_back(triangles[t]), both.push_back(triangles[t]);
      for (int t : b) tb.push_back(triangles[t]), both.push_back(triangles[t]);
      const auto chain_a = boundary_chain(edges_of(ta));
      const auto chain_b = boundary_chain(edges_of(tb));
      if (!is_simple_cycle(chain_a) || !is_simple_cycle(chain_b)) continue;
      const auto reference = boundary_chain(edges_of(both));
      std::vector<DirectedEdge> sum;
      if (!sscc::detail::union_is_simple_cycle(chain_a, chain_b, sum)) {
        ++refused;
        continue;
      }
      ++accepted;
      INFO("trial " << trial << (wrap ? " (torus)" : ""));
      REQUIRE(is_simple_cycle(reference));
      std::sort(sum.begin(), sum.end());
      REQUIRE(sum == reference);
    }
  }
  CHECK(accepted > 200);
  CHECK(refused > 200);  // apart, meeting at vertices, or an annulus
}

TEST_CASE("contour: the union criterion holds on every pair of simple cycles over six vertices", "[contour]") {
  // Chains no mesh of the grid test yields: shared edges of one direction, cancelled edges in
  // several paths, cycles meeting only at vertices, 2-cycles. Accepted only when the sum is the
  // net chain of both and one simple cycle.
  using sscc::detail::boundary_chain;
  using sscc::detail::is_simple_cycle;
  constexpr int kVertices = 6;
  std::vector<std::vector<DirectedEdge>> cycles;
  for (int subset = 0; subset < (1 << kVertices); ++subset) {
    std::vector<int> order;
    for (int v = 0; v < kVertices; ++v) {
      if (subset >> v & 1) order.push_back(v);
    }
    if (order.size() < 2) continue;
    // Every cycle through the subset once: its smallest vertex first, the rest in each order.
    do {
      std::vector<DirectedEdge> chain;
      for (std::size_t k = 0; k < order.size(); ++k) chain.push_back({order[k], order[(k + 1) % order.size()]});
      std::sort(chain.begin(), chain.end());
      cycles.push_back(chain);
    } while (std::next_permutation(order.begin() + 1, order.end()));
  }
  REQUIRE(cycles.size() == 409);  // sum over k of C(6, k) (k - 1)!
  long accepted = 0;
  std::vector<DirectedEdge> sum;
  for (const auto& a : cycles) {
    for (const auto& b : cycles) {
      if (!sscc::detail::union_is_simple_cycle(a, b, sum)) continue;
      ++accepted;
      std::sort(sum.begin(), sum.end());
      REQUIRE(is_simple_cycle(sum));
      // boundary_chain nets a 2-cycle's own edges to nothing; no node's chain is one.
      if (a.size() == 2 || b.size() == 2) continue;
      std::vector<DirectedEdge> both = a;
      both.insert(both.end(), b.begin(), b.end());
      REQUIRE(sum == boundary_chain(both));
    }
  }
  CHECK(accepted > 10000);
}

TEST_CASE("contour: a loop winding twice, a reversed loop or a non-star loop is refused", "[contour]") {
  std::mt19937_64 rng(3);
  const Vector3d up(0, 0, 1);
  const std::vector<Vector3d> once = loop(12, 1, 0.0, rng);
  CHECK(sscc::detail::winds_once_star_shaped(up, cycle(12), once, once));
  CHECK_FALSE(sscc::detail::winds_once_star_shaped(-up, cycle(12), once, once));
  const std::vector<Vector3d> twice = loop(24, 2, 0.0, rng);  // star-shaped, two turns
  CHECK_FALSE(sscc::detail::winds_once_star_shaped(up, cycle(24), twice, twice));
  // A C shape: its vertex mean lies outside the region the whole loop can see.
  std::vector<Vector3d> c_shape;
  for (int i = 0; i <= 10; ++i) c_shape.emplace_back(std::cos(0.2 + 5.9 * i / 10), std::sin(0.2 + 5.9 * i / 10), 0);
  for (int i = 10; i >= 0; --i)
    c_shape.emplace_back(0.8 * std::cos(0.2 + 5.9 * i / 10), 0.8 * std::sin(0.2 + 5.9 * i / 10), 0);
  CHECK_FALSE(sscc::detail::winds_once_star_shaped(up, cycle(22), c_shape, c_shape));
}

TEST_CASE("contour: the star-shaped test against exact arithmetic on moving loops", "[contour]") {
  // Also with the positions times powers of two (exact: the mean c scales exactly too, and the
  // exact answer does not change): at 2^-280 and 2^-400 the products in the predicates are
  // near 1e-169 and 1e-241, their squares subnormal or 0; at 2^300 near 1e180, their squares
  // infinite. At 2^-500 the products fall near 1e-301, below the certified signs' absolute
  // allowance: refusals there only lose culls.
  const std::vector<double> scales{0x1p-280, 0x1p-400, 0x1p-500, 0x1p250, 0x1p300};
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int accepted = 0, refused = 0;
  std::vector<int> accepted_scaled(scales.size(), 0);
  for (int trial = 0; trial < 600; ++trial) {
    const int n = 5 + trial % 13;
    const std::vector<Vector3d> x0 = loop(n, 1 + (trial % 7 == 0), 0.0, rng);
    std::vector<Vector3d> x1 = x0;
    const double motion = trial % 3 == 0 ? 1.5 : 0.4;  // large motions fold some edges over
    for (Vector3d& p : x1) p += motion * Vector3d(unit(rng), unit(rng), unit(rng));
    const bool passes = sscc::detail::winds_once_star_shaped(Vector3d(0, 0, 1), cycle(n), x0, x1);
    bool passes_scaled = false;
    for (std::size_t i = 0; i < scales.size(); ++i) {
      std::vector<Vector3d> y0 = x0, y1 = x1;
      for (Vector3d& p : y0) p *= scales[i];
      for (Vector3d& p : y1) p *= scales[i];
      const bool scaled = sscc::detail::winds_once_star_shaped(Vector3d(0, 0, 1), cycle(n), y0, y1);
      accepted_scaled[i] += scaled;
      passes_scaled = passes_scaled || scaled;
    }
    INFO("trial " << trial);
    if (passes || passes_scaled) {
      // The exact answer is the same at every scale: checked on the unscaled positions.
      for (int k = 0; k <= 32; ++k) REQUIRE(exactly_star_shaped_once(cycle(n), x0, x1, mpq_class(k, 32)));
    }
    (passes ? accepted : refused) += 1;
  }
  CHECK(accepted > 100);
  CHECK(refused > 100);
  for (std::size_t i = 0; i < scales.size(); ++i) {
    INFO("positions times " << scales[i] << ": " << accepted_scaled[i] << " accepted of " << accepted);
    if (scales[i] != 0x1p-500) CHECK(accepted_scaled[i] == accepted);
  }
}
