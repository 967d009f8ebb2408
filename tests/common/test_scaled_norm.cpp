#include <catch2/catch.hpp>

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <random>

#include "common/scaled_norm.hpp"
#include "support/overflow_allowed.hpp"

TEST_CASE("stable_norm3 answers as Eigen's stableNorm on an aligned vector, bit for bit", "[common][scaled_norm]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-1074, 1023);
  std::uniform_int_distribution<int> spread(0, 60);
  // Aligned to every packet size: stableNorm takes the vector as one block.
  alignas(64) double storage[3];
  const Eigen::Map<const Eigen::Vector3d, Eigen::AlignedMax> aligned(storage);
  long inexact = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    // Coordinates of one magnitude, of magnitudes up to 2^60 apart, or anywhere in the range
    // (subnormal, zero and huge ones included).
    const int e = exponent(rng);
    for (int i = 0; i < 3; ++i) {
      const int ei = trial % 3 == 0 ? e : trial % 3 == 1 ? e - spread(rng) : exponent(rng);
      storage[i] = trial % 97 == 0 && i == 1 ? 0.0 : std::ldexp(mantissa(rng), ei);
    }
    const Eigen::Vector3d v = aligned;
    const sscc::test::OverflowAllowed overflow;  // stableNorm's 1 / largest on subnormal vectors
    const double expected = aligned.stableNorm();
    const double value = sscc::detail::stable_norm3(v);
    INFO("trial " << trial << " v " << v.transpose());
    REQUIRE(std::isfinite(value));
    REQUIRE(value == expected);
    // Not a plain sum of squares: the scaling's roundings show (where squares neither
    // overflow nor underflow).
    if (std::abs(e) < 400 && trial % 3 == 0 && value != std::sqrt(v.squaredNorm())) ++inexact;
  }
  REQUIRE(inexact > 0);
  const double zero = sscc::detail::stable_norm3(Eigen::Vector3d(-0.0, 0.0, -0.0));
  REQUIRE(zero == 0.0);
  REQUIRE(!std::signbit(zero));
  const double infinity = std::numeric_limits<double>::infinity();
  REQUIRE(sscc::detail::stable_norm3(Eigen::Vector3d(1.0, -infinity, 0.0)) == infinity);
  // Near the top of the range, where 1 / largest is subnormal (Eigen scales by it all the same).
  storage[0] = 0x1.8p1023, storage[1] = -0x1p1022, storage[2] = 0x1p1000;
  REQUIRE(sscc::detail::stable_norm3(aligned) == aligned.stableNorm());
}
