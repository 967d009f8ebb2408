#include <catch2/catch.hpp>

#include <array>
#include <random>

#include "agreement.hpp"
#include "query_generators.hpp"

using sscc::validation::Kind;

namespace {

/// Runs `count` generated queries of each kind against the exact reference; returns the
/// first disagreement (empty when none) and counts the stages that decided.
template <typename Generator>
std::string first_disagreement(Generator generate, int count, std::uint64_t seed,
                               std::array<int, sscc::ccd::kDecidedByCount>& stages) {
  std::mt19937_64 rng(seed);
  for (int i = 0; i < count; ++i) {
    for (Kind kind : {Kind::kVertexFace, Kind::kEdgeEdge}) {
      const auto q = generate(kind, rng);
      const std::string problem = sscc::validation::disagreement_with_reference(q);
      if (!problem.empty()) return "query " + std::to_string(i) + ": " + problem;
      ++stages[static_cast<int>(sscc::validation::run_kernel(q).decided_by)];
    }
  }
  return {};
}

}  // namespace

TEST_CASE("1e5 seeded random queries agree with the exact reference", "[kernels][random]") {
  std::array<int, sscc::ccd::kDecidedByCount> stages{};
  CHECK(first_disagreement(sscc::validation::random_query, 50000, 1, stages) == "");
  // Generic queries reach every floating-point stage; the exact stage is rare.
  CHECK(stages[static_cast<int>(sscc::ccd::DecidedBy::kSweptBoxes)] > 0);
  CHECK(stages[static_cast<int>(sscc::ccd::DecidedBy::kCoplanaritySign)] > 0);
  CHECK(stages[static_cast<int>(sscc::ccd::DecidedBy::kIntervalFilter)] > 0);
  CHECK(stages[static_cast<int>(sscc::ccd::DecidedBy::kExact)] < 100);
}

TEST_CASE("2e4 seeded near-degenerate queries agree with the exact reference", "[kernels][random]") {
  std::array<int, sscc::ccd::kDecidedByCount> stages{};
  CHECK(first_disagreement(sscc::validation::near_degenerate_query, 10000, 2, stages) == "");
  // These are built to defeat the filters: the exact stage must have been exercised.
  CHECK(stages[static_cast<int>(sscc::ccd::DecidedBy::kExact)] > 100);
}
