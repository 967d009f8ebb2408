#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

#include "common/sorted_fraction.hpp"

using sscc::detail::fraction_above;

TEST_CASE("fraction_above counts the radii strictly above the norm", "[common][sorted_fraction]") {
  CHECK(fraction_above({}, 1.0) == 0.0);
  const std::vector<double> radii{1.0, 2.0, 2.0, 4.0};
  CHECK(fraction_above(radii, 0.5) == 1.0);
  CHECK(fraction_above(radii, 2.0) == 0.25);  // equal is not above: s < radius culls
  CHECK(fraction_above(radii, 3.0) == 0.25);
  CHECK(fraction_above(radii, 4.0) == 0.0);

  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<double> sorted(200);
  for (double& radius : sorted) radius = uniform(rng);
  std::sort(sorted.begin(), sorted.end());
  for (int trial = 0; trial < 50; ++trial) {
    const double s = uniform(rng);
    long above = 0;
    for (double radius : sorted) above += s < radius;
    CHECK(fraction_above(sorted, s) == static_cast<double>(above) / 200.0);
  }
}
