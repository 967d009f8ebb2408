// The moving frame's shifted coordinates (moving_frame.hpp) enclose the exact difference
// x - c whatever the rounding: checked in exact rational arithmetic on differences that
// round (operands of every relative magnitude, signs and exponents), and through a kernel
// whose contact the unpadded subtraction would cut apart.
#include <catch2/catch.hpp>

#include <gmpxx.h>

#include <cmath>
#include <random>

#include "sscc/ccd/kernels.hpp"
#include "sscc/ccd/moving_frame.hpp"

TEST_CASE("moving frame: shifted bounds enclose the exact difference", "[kernels][moving_frame]") {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  std::uniform_int_distribution<int> exponent(-60, 60), sign(0, 1), gap(0, 60);
  int rounded = 0;
  for (int i = 0; i < 200000; ++i) {
    const int e = exponent(rng);
    const double x = (sign(rng) ? -1.0 : 1.0) * std::ldexp(mantissa(rng), e);
    const double c = (sign(rng) ? -1.0 : 1.0) * std::ldexp(mantissa(rng), e - gap(rng) + 30);
    const mpq_class exact = mpq_class(x) - mpq_class(c);
    const double lower = sscc::ccd::shifted_lower(x, c), upper = sscc::ccd::shifted_upper(x, c);
    INFO("x " << x << " c " << c);
    REQUIRE(mpq_class(lower) <= exact);
    REQUIRE(exact <= mpq_class(upper));
    rounded += mpq_class(x - c) != exact;
  }
  CHECK(rounded > 100000);  // most differences round: the bounds are tested where it matters
}

TEST_CASE("moving frame: a minimum separation reached exactly at the end is kept", "[kernels][moving_frame]") {
  // A vertex comes down from 1000 above to exactly d above a face coming up from 1000
  // below (d an exact difference of doubles near z = S): the fixed-frame boxes are d apart,
  // and in the moving frame both end heights are shifted by the same rounded amount, whose
  // rounding can widen their gap past d unless the shift is padded.
  std::mt19937_64 rng(30);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  int tested = 0;
  for (int i = 0; i < 4000; ++i) {
    const double s = 1000.0 * uniform(rng);
    const double top = s + std::ldexp(uniform(rng), -40);
    const double d = top - s;  // exact: top and s are within a factor 2 of each other
    if (!(d > 0.0)) continue;
    const Eigen::Vector3d v0(0.5, 0.5, 1000.0), v1(0.5, 0.5, top);
    const Eigen::Vector3d f0(-1, -1, -1000.0), f1(3, -1, -1000.0), f2(-1, 3, -1000.0);
    const Eigen::Vector3d g0(-1, -1, s), g1(3, -1, s), g2(-1, 3, s);
    sscc::ccd::CcdOptions options;
    options.minimum_separation = d;
    INFO("trial " << i << " s " << s << " d " << d);
    REQUIRE(sscc::ccd::vertex_face_ccd(v0, f0, f1, f2, v1, g0, g1, g2, options).hit);
    ++tested;
  }
  CHECK(tested > 1800);
}
