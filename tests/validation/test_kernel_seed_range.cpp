#include <catch2/catch.hpp>

#include <sstream>

#include "kernel_seed_range.hpp"

namespace {

using sscc::validation::check_seed_range;
using sscc::validation::SeedRangeCounts;
using sscc::validation::SeedRangeOptions;

SeedRangeCounts counts_of(std::uint64_t begin, std::uint64_t end) {
  SeedRangeOptions options;
  options.begin = begin;
  options.end = end;
  options.per_seed = 30;
  std::ostringstream out, progress;
  return check_seed_range(options, out, progress);
}

}  // namespace

TEST_CASE("kernel seed ranges: the counts of a range are the sums of its parts'", "[validation]") {
  const SeedRangeCounts whole = counts_of(5, 9);
  SeedRangeCounts parts = counts_of(5, 6);
  parts += counts_of(6, 8);
  parts += counts_of(8, 9);
  REQUIRE(parts == whole);
  REQUIRE(whole.total().queries == 4 * 2 * (30 + 3));
  REQUIRE(whole.total().contacts > 0);
  REQUIRE(whole.total().disagreements == 0);
  // Each seed its own queries: another range counts other contacts.
  bool other_contacts = false;
  for (std::uint64_t seed = 9; seed < 13 && !other_contacts; ++seed) {
    other_contacts = !(counts_of(seed, seed + 1) == counts_of(5, 6));
  }
  REQUIRE(other_contacts);
}
