#include <catch2/catch.hpp>

#include <cmath>
#include <random>

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
