#include <catch2/catch.hpp>

#include <random>

#include "query_generators.hpp"
#include "support/named_cases.hpp"

using sscc::validation::Kind;
using sscc::validation::Query;

TEST_CASE("minimum separation never misses a sampled near approach", "[kernels][separation]") {
  std::mt19937_64 rng(7);
  int positives = 0;
  for (int i = 0; i < 150; ++i) {
    for (Kind kind : {Kind::kVertexFace, Kind::kEdgeEdge}) {
      const Query q = sscc::validation::random_query(kind, rng);
      const double sampled = sscc::validation::sampled_min_distance(q, 40);
      for (double d : {1e-3, 0.05, 0.2}) {
        sscc::ccd::CcdOptions options;
        options.minimum_separation = d;
        const auto result = sscc::validation::run_kernel(q, options);
        INFO(sscc::validation::to_string(kind) << " query " << i << " d=" << d << " sampled min distance " << sampled);
        if (sampled < d * (1 - 1e-9)) {
          CHECK(result.hit);
          ++positives;
        }
        // Touching implies coming within any d > 0.
        if (sscc::validation::run_kernel(q).hit) CHECK(result.hit);
      }
    }
  }
  CHECK(positives > 50);
}

TEST_CASE("minimum separation on the named cases", "[kernels][separation]") {
  for (const auto& named : sscc::test::named_cases()) {
    INFO(named.name);
    sscc::ccd::CcdOptions options;
    options.minimum_separation = 1e-3;
    const auto result = sscc::validation::run_kernel(named.query, options);
    if (!named.expected_toi.empty()) {
      REQUIRE(result.hit);
      CHECK(mpq_class(result.toi) <= mpq_class(named.expected_toi));
    }
  }
  // Parallel edges 0.5 apart: a contact for d = 0.6, not for d = 0.4.
  using V = Eigen::Vector3d;
  const Query parallel{
      Kind::kEdgeEdge,
      {V(0, 0, 0), V(1, 0, 0), V(0, 0.5, 0), V(1, 0.5, 0), V(0, 0, 0), V(1, 0, 0), V(0, 0.5, 0), V(1, 0.5, 0)}};
  sscc::ccd::CcdOptions options;
  options.minimum_separation = 0.6;
  CHECK(sscc::validation::run_kernel(parallel, options).hit);
  options.minimum_separation = 0.4;
  CHECK_FALSE(sscc::validation::run_kernel(parallel, options).hit);
}
