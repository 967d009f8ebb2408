// A signed integer of at most kFixedIntLimbs 64-bit limbs, stored inline: the exact stage's
// arithmetic for the common case (coordinates whose exponents lie close together, roots
// that separate within a few hundred bits), where GMP's integers spend more time in
// malloc and free than in arithmetic.
//
// Guarantee: every operation is exact or throws FixedIntOverflow; nothing wraps or
// truncates. The exact stage catches the exception and decides the query again with GMP's
// unbounded integers, so the width is a speed setting, never a correctness one. Limb
// arithmetic is GMP's low-level mpn layer (no allocation); division and gcd go through
// read-only mpz views of the limbs.
#pragma once

#include <gmpxx.h>

#include <array>
#include <exception>

namespace sscc::ccd::exact_stage {

__extension__ typedef unsigned __int128 FixedIntWide;  // two limbs: single-limb products and sums

/// Limbs of a FixedInt: 1024 bits. Wider means fewer queries redone with GMP, but every
/// coefficient is copied at this size.
inline constexpr int kFixedIntLimbs = 16;

/// A result that does not fit in kFixedIntLimbs limbs.
struct FixedIntOverflow : std::exception {
  const char* what() const noexcept override { return "sscc::ccd::exact_stage: fixed-size integer overflow"; }
};

class FixedInt {
 public:
  // User-provided, so that value-initialization (`T()`, `{}`) sets the size alone rather
  // than zeroing every limb.
  FixedInt() {}          // NOLINT(modernize-use-equals-default)
  FixedInt(long value);  // NOLINT(google-explicit-constructor): integer literals mix in as with mpz_class

  friend int sgn(const FixedInt& x) { return (x.size_ > 0) - (x.size_ < 0); }
  friend int cmp(const FixedInt& a, const FixedInt& b);
  friend FixedInt abs(const FixedInt& x) {
    FixedInt r = x;
    r.size_ = r.size_ < 0 ? -r.size_ : r.size_;
    return r;
  }
  friend FixedInt operator-(const FixedInt& x) {
    FixedInt r = x;
    r.size_ = -r.size_;
    return r;
  }
  // Operands of one limb, the common case, take an inline path on two-limb integers.
  friend FixedInt operator+(const FixedInt& a, const FixedInt& b) {
    if (a.single_limb() && b.single_limb()) return add_single(a, b.size_ < 0, b);
    return add(a, b, false);
  }
  friend FixedInt operator-(const FixedInt& a, const FixedInt& b) {
    if (a.single_limb() && b.single_limb()) return add_single(a, b.size_ > 0, b);
    return add(a, b, true);
  }
  friend FixedInt operator*(const FixedInt& a, const FixedInt& b) {
    if (a.single_limb() && b.single_limb()) {
      if (a.size_ == 0 || b.size_ == 0) return FixedInt();
      return from_wide(static_cast<FixedIntWide>(a.limbs_[0]) * b.limbs_[0], (a.size_ < 0) != (b.size_ < 0));
    }
    return multiply(a, b);
  }
  friend FixedInt operator<<(const FixedInt& x, unsigned long bits) {
    if (x.single_limb() && bits < kWideShiftLimit) {
      if (x.size_ == 0) return x;
      return from_wide(static_cast<FixedIntWide>(x.limbs_[0]) << bits, x.size_ < 0);
    }
    return shift_left(x, bits);
  }
  /// x / 2^bits; precondition: exact (the low `bits` bits of x are zero).
  friend FixedInt exact_shift_right(const FixedInt& x, unsigned long bits);
  /// Index of the lowest set bit; precondition: x is not zero.
  friend unsigned long trailing_zeros(const FixedInt& x);
  /// Truncating quotient, as mpz_class's `/`.
  friend FixedInt operator/(const FixedInt& a, const FixedInt& b);
  /// a / b; precondition: exact.
  friend FixedInt divexact(const FixedInt& a, const FixedInt& b);
  /// Non-negative greatest common divisor.
  friend FixedInt integer_gcd(const FixedInt& a, const FixedInt& b);
  /// x = m 2^exponent with |m| in [0.5, 1), m truncated (as mpz_get_d_2exp).
  friend double get_d_2exp(long& exponent, const FixedInt& x);

  /// Conversions, for the tests that hold FixedInt against mpz_class.
  static FixedInt from_mpz(mpz_srcptr x);  ///< throws FixedIntOverflow when x does not fit
  mpz_class to_mpz() const;

  FixedInt& operator+=(const FixedInt& b) { return *this = *this + b; }
  FixedInt& operator-=(const FixedInt& b) { return *this = *this - b; }
  FixedInt& operator*=(const FixedInt& b) { return *this = *this * b; }
  friend bool operator==(const FixedInt& a, const FixedInt& b) { return cmp(a, b) == 0; }
  friend bool operator!=(const FixedInt& a, const FixedInt& b) { return cmp(a, b) != 0; }

 private:
  /// A read-only mpz view of the limbs (valid while `this` is).
  mpz_srcptr view(mpz_t storage) const;
  /// Shifts of a single limb by fewer bits than this stay within two limbs.
  static constexpr unsigned long kWideShiftLimit = GMP_NUMB_BITS;
  bool single_limb() const { return size_ >= -1 && size_ <= 1; }
  static FixedInt from_wide(FixedIntWide magnitude, bool negative) {
    FixedInt r;
    r.limbs_[0] = static_cast<mp_limb_t>(magnitude);
    r.limbs_[1] = static_cast<mp_limb_t>(magnitude >> GMP_NUMB_BITS);
    const int n = r.limbs_[1] != 0 ? 2 : r.limbs_[0] != 0 ? 1 : 0;
    r.size_ = negative ? -n : n;
    return r;
  }
  /// a + b, or a - b when `b_negative` is the opposite of b's sign; both single limbs.
  static FixedInt add_single(const FixedInt& a, bool b_negative, const FixedInt& b) {
    const FixedIntWide x = a.size_ == 0 ? 0 : a.limbs_[0];
    const FixedIntWide y = b.size_ == 0 ? 0 : b.limbs_[0];
    const bool a_negative = a.size_ < 0;
    if (a_negative == b_negative) return from_wide(x + y, a_negative);
    return x >= y ? from_wide(x - y, a_negative) : from_wide(y - x, b_negative);
  }
  /// a + b, or a - b when `subtract`; any sizes.
  static FixedInt add(const FixedInt& a, const FixedInt& b, bool subtract);
  static FixedInt multiply(const FixedInt& a, const FixedInt& b);
  static FixedInt shift_left(const FixedInt& x, unsigned long bits);
  int magnitude_size() const { return size_ < 0 ? -size_ : size_; }

  void normalize(int limbs, bool negative);

  int size_ = 0;                                 ///< limbs in use; negative for a negative value (as in mpz)
  std::array<mp_limb_t, kFixedIntLimbs> limbs_;  ///< beyond |size_|: unspecified, never read
};

}  // namespace sscc::ccd::exact_stage
