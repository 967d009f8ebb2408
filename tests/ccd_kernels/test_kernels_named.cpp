#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "agreement.hpp"
#include "sscc/ccd/kernels.hpp"
#include "support/named_cases.hpp"

using sscc::validation::disagreement_with_reference;
using sscc::validation::Query;

namespace {

Query scaled(Query q, double scale, const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
  for (auto& p : q.points) p = p * scale + offset;
  return q;
}

bool is_power_of_two(double x) {
  int exponent = 0;
  return std::frexp(x, &exponent) == 0.5;
}

}  // namespace

TEST_CASE("named degenerate cases: exact answers", "[kernels]") {
  for (const auto& named : sscc::test::named_cases()) {
    INFO(named.name);
    const auto result = sscc::validation::run_kernel(named.query);
    CHECK(result.hit == !named.expected_toi.empty());
    CHECK(disagreement_with_reference(named.query) == "");
    if (result.hit) {
      const mpq_class expected(named.expected_toi);
      CHECK(mpq_class(result.toi) <= expected);
      CHECK(mpq_class(result.toi) >= expected - mpq_class(sscc::ccd::kDefaultToiTolerance));
    }
  }
}

TEST_CASE("named cases at coordinates from 1e-6 to 1e6 and beyond", "[kernels]") {
  for (const auto& named : sscc::test::named_cases()) {
    for (double scale : {1e-6, 0x1p-20, 3.0, 1e6, 0x1p+20, 1e120}) {
      INFO(named.name << " scaled by " << scale);
      const Query q = scaled(named.query, scale);
      CHECK(disagreement_with_reference(q) == "");
      // A power-of-two scale keeps every coordinate exact, so the answer cannot change.
      if (is_power_of_two(scale)) {
        CHECK(sscc::validation::run_kernel(q).hit == !named.expected_toi.empty());
      }
    }
    INFO(named.name << " translated");
    CHECK(disagreement_with_reference(scaled(named.query, 1.0, Eigen::Vector3d(1e3, -7, 0.1))) == "");
  }
}

TEST_CASE("sweeps of +-epsilon around the degenerate thresholds", "[kernels]") {
  // Each named contact case is pushed off its threshold by +-2^-k in every coordinate of
  // its first point at t0 and t1: the answers must match the exact reference.
  int checked = 0;
  for (const auto& named : sscc::test::named_cases()) {
    for (int k = 10; k <= 60; k += 5) {
      for (double sign : {-1.0, 1.0}) {
        for (int axis = 0; axis < 3; ++axis) {
          Query q = named.query;
          q.points[0][axis] += sign * std::ldexp(1.0, -k);
          q.points[4][axis] += sign * std::ldexp(1.0, -k);
          INFO(named.name << " offset " << sign << " * 2^-" << k << " on axis " << axis);
          CHECK(disagreement_with_reference(q) == "");
          ++checked;
        }
      }
    }
  }
  CHECK(checked > 1000);
}

TEST_CASE("time-of-impact tolerance is honoured from 1e-2 to 1e-12", "[kernels]") {
  for (const auto& named : sscc::test::named_cases()) {
    for (double tolerance : {1e-2, 1e-4, 1e-8, 1e-12}) {
      INFO(named.name << " tolerance " << tolerance);
      sscc::ccd::CcdOptions options;
      options.toi_tolerance = tolerance;
      CHECK(disagreement_with_reference(named.query, options) == "");
    }
  }
}

TEST_CASE("bad input is refused with a message", "[kernels]") {
  const auto cases = sscc::test::named_cases();
  Query q = cases.front().query;
  q.points[2][1] = std::nan("");
  CHECK_THROWS_WITH(sscc::validation::run_kernel(q), Catch::Contains("non-finite"));
  q.points[2][1] = INFINITY;
  CHECK_THROWS_WITH(sscc::validation::run_kernel(q), Catch::Contains("non-finite"));
  sscc::ccd::CcdOptions options;
  options.minimum_separation = -1.0;
  CHECK_THROWS_WITH(sscc::validation::run_kernel(cases.front().query, options), Catch::Contains("minimum_separation"));
  options = {};
  options.toi_tolerance = 0.0;
  CHECK_THROWS_WITH(sscc::validation::run_kernel(cases.front().query, options), Catch::Contains("toi_tolerance"));
}

TEST_CASE("huge and tiny edges together: underflow cannot fake a certain sign", "[kernels]") {
  // A huge edge (2^300) with tiny ones (2^-525): products of the tiny coordinates are
  // subnormal, and their rounding, multiplied by the huge edge, dwarfs a fixed underflow
  // allowance. The primitives touch exactly (static, coplanar for all t).
  std::mt19937_64 rng(3);
  const double ints[3] = {3, 5, 7};
  int contacts = 0;
  for (int trial = 0; trial < 200; ++trial) {
    double r[3];
    for (double& x : r) x = 1.0 + std::ldexp(double(rng() >> 15), -49);
    const Eigen::Vector3d zero(0, 0, 0);
    const Eigen::Vector3d huge(std::ldexp(3.0, 300), std::ldexp(5.0, 300), std::ldexp(7.0, 300));
    Eigen::Vector3d tiny, on_face, tiny_end;
    for (int k = 0; k < 3; ++k) {
      tiny[k] = std::ldexp(r[k], -525);
      on_face[k] = std::ldexp(ints[k] + r[k], -526);   // 2^-826 huge + tiny / 2, exactly
      tiny_end[k] = std::ldexp(ints[k] - r[k], -526);  // 2^-826 huge - tiny / 2, exactly
    }
    const Query vf{sscc::validation::Kind::kVertexFace, {on_face, zero, huge, tiny, on_face, zero, huge, tiny}};
    const Query ee{sscc::validation::Kind::kEdgeEdge, {zero, huge, tiny, tiny_end, zero, huge, tiny, tiny_end}};
    for (const Query& q : {vf, ee}) {
      INFO(sscc::validation::describe(q));
      CHECK(disagreement_with_reference(q) == "");
      contacts += sscc::validation::run_kernel(q).hit ? 1 : 0;
    }
  }
  CHECK(contacts == 400);
}

TEST_CASE("contact parameters on nearly parallel edges and needle triangles", "[kernels]") {
  // Found by fuzzing at the smallest tolerance: closed-form closest points cancel here.
  using V = Eigen::Vector3d;
  using sscc::validation::Kind;
  const std::vector<Query> queries = {
      {Kind::kEdgeEdge,  // edges 2e-8 rad apart at contact
       {V(-0x1.6p+1, -0x1.2p+1, 0x1.600004p+1), V(0x1.3p+1, 0x1.1p+2, 0x1.6p+0), V(0x1.3p+3, 0x1.58p+2, -0x1.8p-1),
        V(0x1.ep+0, 0x1.ap+1, 0x1.ep+1), V(-0x1.2fffffffp+2, -0x1p-2, 0x1.3p+2), V(0x1.bp+1, 0x1.2p+1, 0x1.3p+1),
        V(0x1.ep+2, 0x1.98p+2, 0x1.4p+0), V(0x1.cp-1, 0x1.4p+0, 0x1.cp+0)}},
      {Kind::kEdgeEdge,  // collinear edges meeting end to end
       {V(0x1p+2, 0x1.8p+1, 0x1p+0), V(0x1.cp+0, 0x1p+0, 0x1.4p+0), V(0x1.8p+2, 0x1.4p+2, 0x1p+0),
        V(0x1p+2, 0x1.8p+1, 0x1.4p+0), V(0x1p+2, 0x1.8p+1, 0x1p+0), V(0x1.ep+1, 0x1p+0, -0x1.8p-1),
        V(0x1.8p+2, 0x1.4p+2, 0x1p+0), V(0x1.fffffffffffffp+1, 0x1.7ffffffffffffp+1, -0x1.8p-1)}},
      {Kind::kVertexFace,  // a needle triangle, two vertices 4e-10 apart
       {V(-0x1p-1, -0x1.4p+0, 0x1.ap+0), V(-0x1.dp+1, -0x1.4p-1, -0x1p-2), V(0x1.2p+1, -0x1.6p+0, 0x1.8p-1),
        V(0x1.000000000004p+0, -0x1p+1, 0x1p+1), V(-0x1p-1, -0x1.4p+0, 0x1.a0000002p+0),
        V(-0x1.5p+1, 0x1.8p-2, 0x1.cp+0), V(0x1p-2, -0x1.3p+1, 0x1.6p+1), V(0x1p+0, -0x1p+1, 0x1p+1)}}};
  sscc::ccd::CcdOptions options;
  options.toi_tolerance = sscc::ccd::kMinToiTolerance;
  for (const Query& q : queries) {
    INFO(sscc::validation::describe(q));
    CHECK(sscc::validation::run_kernel(q, options).hit);
    CHECK(disagreement_with_reference(q, options) == "");
  }
}

TEST_CASE("queries spanning the double range, found slow by searches, agree with the reference", "[kernels]") {
  // Points in the kernels' argument order (vertex-face: v f0 f1 f2 at t0, then at t1;
  // edge-edge: ea0 ea1 eb0 eb1 at t0, then at t1). The first two are issue 15's; the others
  // were found by `sscc kernels --search-slow` on versions of the fixed-size exact stage.
  using sscc::validation::Kind;
  const std::vector<Query> queries = {
      {Kind::kEdgeEdge,
       {Eigen::Vector3d(0, 1, 0),
        {0, 0, 0},
        {-1, 0, 0},
        {0x1p-1074, -1, 0},
        {-1, -0x1p-1074, 0},
        {0x1p956, 0, 0},
        {1, -1, 0},
        {-1, 0, 0}}},
      {Kind::kVertexFace,
       {Eigen::Vector3d(1, 0, 0x1p1000),
        {0, 0, 0},
        {1, 0, 0},
        {1, 0x1p-855, 0},
        {0, -1, 0},
        {1, 0, 0},
        {1, 0, 1},
        {1, -0x1p979, 0}}},
      {Kind::kVertexFace,
       {Eigen::Vector3d(0, -0x1p+1, -0x1.8p-545),
        {0x1p+0, 0x1p+921, 0x0.000008p-1022},
        {-0x1p+607, -0x1p+1, -0x1.4p-16},
        {-0x0.0000080000001p-1022, -0x1p-1022, 0x1.0000000002p+921},
        {0x0.00000000008p-1022, -0x0.00a000000002p-1022, 0x0.0000000009p-1022},
        {-0x0p+0, 0x1p-1022, -0x1.000008p+17},
        {-0x1p+921, 0x0.0000102p-1022, 0x0.00001p-1022},
        {0x1p-643, -0x1p+0, 0x1p+0}}},
      {Kind::kEdgeEdge,
       {Eigen::Vector3d(-0x0.000002p-1022, -0x1p+241, -0x1p-992),
        {0x1p+0, 0x0.00000000004p-1022, 0x1.40020000008p+3},
        {0x1.00000002p+1020, 0x1p+1, 0x1p+1},
        {0x1p+0, 0x1p-461, -0x1p+241},
        {0x1p-2, 0x1p+0, 0x1.0000000004p+529},
        {0x1p+0, -0x1.000004p+789, -0x1p-104},
        {-0x1.000000008p+499, -0x1p+789, -0x1.004000000004p-906},
        {-0x1.00008p+221, -0x1p-521, 0x1.000000000001p+1020}}},
      {Kind::kVertexFace,
       {Eigen::Vector3d(0x1p+1, -0x1p+1, -0x1p+0),
        {-0x1p-352, -0x1p+1, 0x1p+0},
        {-0x1.0000000000004p+857, -0x1p+1, 0x0.0008p-1022},
        {0x1p+1, -0x1p+1, -0x1.0000080800008p-481},
        {-0x1p+1, -0x1p+1, 0x1.000001004p+1016},
        {-0x1.0000000000008p+1, -0x1p+1, -0x1p+0},
        {0x0.0008p-1022, -0x1p+1, 0x1.0000000000008p+1},
        {0x1.00002000008p-895, -0x1p+1, -0x1p+1}}},
      {Kind::kEdgeEdge,
       {Eigen::Vector3d(0x1.001p+484, -0x1p+771, 0x1p+0),
        {0x1p-562, 0x0.000000002p-1022, -0x1.4p+651},
        {-0x1p+0, 0x1.001p+484, -0x1p+1},
        {-0x0.000000002p-1022, -0x1.000000000004p+33, -0x1.1p+0},
        {-0x1.100000001p+0, 0x1p+0, 0x1.000000004004p+0},
        {0x1.000000000004p-32, 0x0p+0, 0x1.000080010004p+0},
        {0x1.0000000000004p+916, 0x1.2p+0, -0x1p-999},
        {-0x0.000000002p-1022, 0x1p+0, 0x0.000000002p-1022}}},
  };
  // The decision and the time of impact against the reference (disagreement_with_reference
  // would also measure distances in doubles, which overflow at these magnitudes).
  for (const Query& q : queries) {
    INFO(sscc::validation::describe(q));
    const sscc::ccd::CcdResult kernel = sscc::validation::run_kernel(q);
    sscc::exact::ContactTime truth = sscc::validation::run_reference(q);
    REQUIRE(kernel.hit == truth.has_value());
    if (!truth) continue;
    CHECK(sscc::exact::compare(mpq_class(kernel.toi), *truth) <= 0);
    CHECK(sscc::exact::compare(mpq_class(kernel.toi) + mpq_class(sscc::ccd::kDefaultToiTolerance), *truth) >= 0);
  }
}
