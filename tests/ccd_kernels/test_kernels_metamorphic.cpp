// Metamorphic checks: transformations that provably keep the contact decision must keep the
// kernels' decision, on integer-grid queries (the degenerate configurations: coplanar,
// collinear, parallel, touching at the ends of the step). Every transformation here is
// exact in double arithmetic, so the transformed query is the same geometric question.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "agreement.hpp"
#include "query_generators.hpp"
#include "sscc/ccd/kernels.hpp"

using sscc::validation::Kind;
using sscc::validation::Query;

namespace {

/// Grid queries checked; each gets one transformation, the families taken in turn.
constexpr int kGridQueries = 100000;

Query scaled(Query q, int exponent) {
  for (auto& p : q.points) p = p.unaryExpr([exponent](double x) { return std::ldexp(x, exponent); });
  return q;
}

Query translated(Query q, const Eigen::Vector3d& shift) {
  for (auto& p : q.points) p += shift;
  return q;
}

Query time_reversed(Query q) {
  for (int i = 0; i < 4; ++i) std::swap(q.points[i], q.points[i + 4]);
  return q;
}

/// A relabelling of the primitives' vertices that describes the same primitives: the
/// triangle's vertices in any order; either edge's ends swapped, and the edges swapped.
Query permuted(Query q, std::mt19937_64& rng) {
  int order[4] = {0, 1, 2, 3};
  if (q.kind == Kind::kVertexFace) {
    std::shuffle(order + 1, order + 4, rng);
  } else {
    if (rng() & 1) std::swap(order[0], order[1]);
    if (rng() & 1) std::swap(order[2], order[3]);
    if (rng() & 1) std::swap(order[0], order[2]), std::swap(order[1], order[3]);
  }
  Query r = q;
  for (int i = 0; i < 4; ++i) {
    r.points[i] = q.points[order[i]];
    r.points[i + 4] = q.points[order[i] + 4];
  }
  return r;
}

bool params_in_domain(const sscc::ccd::CcdResult& r, Kind kind) {
  const double u = r.params[0];
  const double v = r.params[1];
  if (!(std::isfinite(u) && std::isfinite(v) && u >= 0.0 && v >= 0.0)) return false;
  return kind == Kind::kVertexFace ? u + v <= 1.0 + 1e-12 : u <= 1.0 && v <= 1.0;
}

}  // namespace

TEST_CASE(
    "metamorphic: scalings by 2^k, grid translations, time reversal and relabelling "
    "keep the decision on 1e5 integer-grid queries",
    "[kernels][metamorphic]") {
  std::mt19937_64 rng(2024);
  std::uniform_int_distribution<int> exponent(-1070, 1000);
  std::uniform_int_distribution<int> shift(-64, 64);
  int hits = 0;
  int mismatches = 0;
  std::string first_mismatch;
  for (int i = 0; i < kGridQueries; ++i) {
    const Kind kind = i % 2 == 0 ? Kind::kVertexFace : Kind::kEdgeEdge;
    const Query q = sscc::validation::integer_grid_query(kind, rng);
    const sscc::ccd::CcdResult base = sscc::validation::run_kernel(q);
    Query transformed;
    switch ((i / 2) % 4) {
      case 0:
        transformed = scaled(q, exponent(rng));
        break;
      case 1:
        transformed = translated(q, Eigen::Vector3d(shift(rng), shift(rng), shift(rng)));
        break;
      case 2:
        transformed = time_reversed(q);
        break;
      default:
        transformed = permuted(q, rng);
        break;
    }
    const sscc::ccd::CcdResult other = sscc::validation::run_kernel(transformed);
    hits += base.hit ? 1 : 0;
    const bool params_ok = !other.hit || params_in_domain(other, kind);
    if (base.hit != other.hit || !params_ok) {
      if (++mismatches == 1) {
        first_mismatch = sscc::validation::describe(q) + " -> " + sscc::validation::describe(transformed);
      }
    }
  }
  CHECK(first_mismatch == "");
  CHECK(mismatches == 0);
  // The grid is degenerate enough that both answers are common.
  CHECK(hits > kGridQueries / 10);
  CHECK(hits < kGridQueries - kGridQueries / 10);
}

TEST_CASE("contact parameters at subnormal coordinates: finite and right", "[kernels][metamorphic]") {
  const double s = 0x1p-1070;
  const Eigen::Vector3d f0(0, 0, 0), f1(4 * s, 0, 0), f2(0, 4 * s, 0);
  // The vertex falls through the face at (s, s, 0), barycentrics (0.25, 0.25), at t = 1/2.
  const auto vf =
      sscc::ccd::vertex_face_ccd(Eigen::Vector3d(s, s, s), f0, f1, f2, Eigen::Vector3d(s, s, -s), f0, f1, f2);
  REQUIRE(vf.hit);
  CHECK(vf.params[0] == Approx(0.25).margin(1e-6));
  CHECK(vf.params[1] == Approx(0.25).margin(1e-6));
  // Edge a along x at z = s falls onto edge b along y; they cross at a's 1/4, b's 3/4.
  const Eigen::Vector3d a0(-s, 0, s), a1(3 * s, 0, s), b0(0, -3 * s, 0), b1(0, s, 0);
  const Eigen::Vector3d down(0, 0, -2 * s);
  const auto ee = sscc::ccd::edge_edge_ccd(a0, a1, b0, b1, a0 + down, a1 + down, b0, b1);
  REQUIRE(ee.hit);
  CHECK(ee.params[0] == Approx(0.25).margin(1e-6));
  CHECK(ee.params[1] == Approx(0.75).margin(1e-6));
  // Every hit among grid queries at that scale has parameters in their domains.
  std::mt19937_64 rng(7);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Kind kind = i % 2 == 0 ? Kind::kVertexFace : Kind::kEdgeEdge;
    const Query q = scaled(sscc::validation::integer_grid_query(kind, rng), -1070);
    const sscc::ccd::CcdResult r = sscc::validation::run_kernel(q);
    if (!r.hit) continue;
    ++hits;
    INFO(sscc::validation::describe(q));
    REQUIRE(params_in_domain(r, kind));
  }
  CHECK(hits > 100);
}
