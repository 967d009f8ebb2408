// The exact stage's fixed-size integers against GMP's: every operation either gives the
// exact result or throws FixedIntOverflow, and throws only when the result needs at least
// the full width.
#include <catch2/catch.hpp>

#include <climits>
#include <functional>
#include <random>
#include <string>

#include "exact/fixed_int.hpp"

using sscc::ccd::exact_stage::FixedInt;
using sscc::ccd::exact_stage::FixedIntOverflow;
using sscc::ccd::exact_stage::kFixedIntLimbs;

namespace {

constexpr int kLimbBits = GMP_NUMB_BITS;
constexpr int kRandomCases = 20000;

/// Random integers of 0 to kFixedIntLimbs limbs: random bits, runs of ones and of zeros
/// (carries and borrows across limbs), powers of two, either sign.
mpz_class random_integer(std::mt19937_64& rng, int max_limbs) {
  const int limbs = std::uniform_int_distribution<int>(0, max_limbs)(rng);
  mpz_class x = 0;
  switch (std::uniform_int_distribution<int>(0, 3)(rng)) {
    case 0:
      for (int i = 0; i < limbs; ++i) x = (x << kLimbBits) + mpz_class(std::to_string(rng()));
      x >>= std::uniform_int_distribution<int>(0, kLimbBits - 1)(rng);
      break;
    case 1:  // 2^n - 1
      x = (mpz_class(1) << std::uniform_int_distribution<int>(0, limbs * kLimbBits)(rng)) - 1;
      break;
    case 2:  // 2^n
      x = mpz_class(1) << std::uniform_int_distribution<int>(0, std::max(0, limbs * kLimbBits - 1))(rng);
      break;
    default:
      x = static_cast<long>(std::uniform_int_distribution<int>(-3, 3)(rng));
      break;
  }
  return rng() & 1 ? mpz_class(-x) : x;
}

/// The operation on FixedInt agrees with the exact result, or throws and the exact result
/// needs at least the full width.
void check(const std::function<FixedInt()>& fixed, const mpz_class& exact, const std::string& what) {
  INFO(what << " exact " << exact.get_str(16));
  try {
    const FixedInt r = fixed();
    CHECK(r.to_mpz() == exact);
  } catch (const FixedIntOverflow&) {
    CHECK(mpz_size(exact.get_mpz_t()) >= static_cast<size_t>(kFixedIntLimbs));
  }
}

}  // namespace

TEST_CASE("fixed-size integers agree with GMP or overflow", "[kernels][exact]") {
  std::mt19937_64 rng(15);
  for (int i = 0; i < kRandomCases; ++i) {
    const mpz_class a = random_integer(rng, kFixedIntLimbs);
    const mpz_class b = random_integer(rng, kFixedIntLimbs);
    const FixedInt fa = FixedInt::from_mpz(a.get_mpz_t());
    const FixedInt fb = FixedInt::from_mpz(b.get_mpz_t());
    const std::string operands = a.get_str(16) + ", " + b.get_str(16);
    REQUIRE(fa.to_mpz() == a);
    CHECK(cmp(fa, fb) == (a > b) - (a < b));
    CHECK(sgn(fa) == sgn(a));
    CHECK((fa == fb) == (a == b));
    CHECK(abs(fa).to_mpz() == abs(a));
    check([&] { return fa + fb; }, a + b, "sum " + operands);
    check([&] { return fa - fb; }, a - b, "difference " + operands);
    check([&] { return fa * fb; }, a * b, "product " + operands);
    const unsigned long bits = std::uniform_int_distribution<unsigned long>(0, 3 * kLimbBits)(rng);
    check([&] { return fa << bits; }, a << bits, "shift " + operands);
    if (sgn(a) != 0) {
      const unsigned long zeros = mpz_scan1(a.get_mpz_t(), 0);
      CHECK(trailing_zeros(fa) == zeros);
      const unsigned long down = std::uniform_int_distribution<unsigned long>(0, zeros)(rng);
      CHECK(exact_shift_right(fa, down).to_mpz() == (a >> down));
    }
    if (sgn(b) != 0) {
      check([&] { return fa / fb; }, mpz_class(a / b), "quotient " + operands);
      const mpz_class multiple = a * b;
      if (mpz_size(multiple.get_mpz_t()) < static_cast<size_t>(kFixedIntLimbs)) {
        CHECK(divexact(FixedInt::from_mpz(multiple.get_mpz_t()), fb).to_mpz() == a);
      }
    }
    mpz_class g;
    mpz_gcd(g.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
    CHECK(integer_gcd(fa, fb).to_mpz() == g);
    long exponent = 0;
    long expected_exponent = 0;
    CHECK(get_d_2exp(exponent, fa) == mpz_get_d_2exp(&expected_exponent, a.get_mpz_t()));
    CHECK(exponent == expected_exponent);
  }
}

TEST_CASE("fixed-size integers refuse what does not fit", "[kernels][exact]") {
  const mpz_class widest = (mpz_class(1) << (kFixedIntLimbs * kLimbBits)) - 1;
  const FixedInt w = FixedInt::from_mpz(widest.get_mpz_t());
  CHECK_THROWS_AS(w + FixedInt(1), FixedIntOverflow);
  CHECK_THROWS_AS(w << 1, FixedIntOverflow);
  CHECK_THROWS_AS(w * FixedInt(2), FixedIntOverflow);
  const mpz_class too_wide = widest + 1;
  CHECK_THROWS_AS(FixedInt::from_mpz(too_wide.get_mpz_t()), FixedIntOverflow);
  CHECK((w - w).to_mpz() == 0);
  CHECK(FixedInt(-(1L << 62)).to_mpz() == mpz_class(-(1L << 62)));
  CHECK(FixedInt(LONG_MIN).to_mpz() == mpz_class(LONG_MIN));
}
