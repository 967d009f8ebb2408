#include <catch2/catch.hpp>

#include <cmath>

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
  CHECK_THROWS_WITH(sscc::validation::run_kernel(cases.front().query, options),
                    Catch::Contains("minimum_separation"));
  options = {};
  options.toi_tolerance = 0.0;
  CHECK_THROWS_WITH(sscc::validation::run_kernel(cases.front().query, options),
                    Catch::Contains("toi_tolerance"));
}
