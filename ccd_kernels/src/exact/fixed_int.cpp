#include "exact/fixed_int.hpp"

#include <utility>

namespace sscc::ccd::exact_stage {

namespace {

constexpr unsigned long kLimbBits = GMP_NUMB_BITS;

}  // namespace

FixedInt::FixedInt(long value) {
  if (value == 0) return;
  // The magnitude of LONG_MIN does not fit a long, but does fit a limb.
  const mp_limb_t magnitude = value < 0 ? mp_limb_t{0} - static_cast<mp_limb_t>(value) : static_cast<mp_limb_t>(value);
  limbs_[0] = magnitude;
  size_ = value < 0 ? -1 : 1;
}

void FixedInt::normalize(int limbs, bool negative) {
  while (limbs > 0 && limbs_[limbs - 1] == 0) --limbs;
  size_ = negative ? -limbs : limbs;
}

int cmp(const FixedInt& a, const FixedInt& b) {
  // Sizes carry the signs: a longer positive number is larger, a longer negative smaller.
  if (a.size_ != b.size_) return a.size_ > b.size_ ? 1 : -1;
  const int c = mpn_cmp(a.limbs_.data(), b.limbs_.data(), a.magnitude_size());
  const int s = (c > 0) - (c < 0);
  return a.size_ >= 0 ? s : -s;
}

FixedInt FixedInt::add(const FixedInt& a, const FixedInt& b_unsigned, bool subtract) {
  FixedInt negated;
  if (subtract) negated = -b_unsigned;
  const FixedInt& b = subtract ? negated : b_unsigned;
  if (b.size_ == 0) return a;
  if (a.size_ == 0) return b;
  const FixedInt* big = &a;
  const FixedInt* small = &b;
  FixedInt r;
  if ((a.size_ > 0) == (b.size_ > 0)) {
    if (big->magnitude_size() < small->magnitude_size()) std::swap(big, small);
    int n = big->magnitude_size();
    const mp_limb_t carry =
        mpn_add(r.limbs_.data(), big->limbs_.data(), n, small->limbs_.data(), small->magnitude_size());
    if (carry != 0) {
      if (n == kFixedIntLimbs) throw FixedIntOverflow();
      r.limbs_[n++] = carry;
    }
    r.size_ = a.size_ > 0 ? n : -n;
    return r;
  }
  // Opposite signs: subtract the smaller magnitude from the larger, whose sign wins.
  const int an = a.magnitude_size();
  const int bn = b.magnitude_size();
  int c = an != bn ? (an > bn ? 1 : -1) : mpn_cmp(a.limbs_.data(), b.limbs_.data(), an);
  if (c == 0) return r;
  if (c < 0) std::swap(big, small);
  mpn_sub(r.limbs_.data(), big->limbs_.data(), big->magnitude_size(), small->limbs_.data(), small->magnitude_size());
  r.normalize(big->magnitude_size(), big->size_ < 0);
  return r;
}

FixedInt FixedInt::multiply(const FixedInt& a, const FixedInt& b) {
  FixedInt r;
  if (a.size_ == 0 || b.size_ == 0) return r;
  const FixedInt* big = &a;
  const FixedInt* small = &b;
  if (big->magnitude_size() < small->magnitude_size()) std::swap(big, small);
  const int n = big->magnitude_size() + small->magnitude_size();
  if (n > kFixedIntLimbs) throw FixedIntOverflow();
  mpn_mul(r.limbs_.data(), big->limbs_.data(), big->magnitude_size(), small->limbs_.data(), small->magnitude_size());
  r.normalize(n, (a.size_ < 0) != (b.size_ < 0));
  return r;
}

FixedInt FixedInt::shift_left(const FixedInt& x, unsigned long bits) {
  if (x.size_ == 0) return x;
  const unsigned long whole = bits / kLimbBits;
  const unsigned partial = static_cast<unsigned>(bits % kLimbBits);
  const unsigned long n = static_cast<unsigned long>(x.magnitude_size());
  if (n + whole > static_cast<unsigned long>(kFixedIntLimbs)) throw FixedIntOverflow();
  FixedInt r;
  for (unsigned long i = 0; i < whole; ++i) r.limbs_[i] = 0;
  int size = static_cast<int>(n + whole);
  if (partial == 0) {
    for (unsigned long i = 0; i < n; ++i) r.limbs_[whole + i] = x.limbs_[i];
  } else {
    const mp_limb_t carry = mpn_lshift(r.limbs_.data() + whole, x.limbs_.data(), static_cast<mp_size_t>(n), partial);
    if (carry != 0) {
      if (size == kFixedIntLimbs) throw FixedIntOverflow();
      r.limbs_[size++] = carry;
    }
  }
  r.size_ = x.size_ < 0 ? -size : size;
  return r;
}

FixedInt exact_shift_right(const FixedInt& x, unsigned long bits) {
  const unsigned long whole = bits / kLimbBits;
  const unsigned partial = static_cast<unsigned>(bits % kLimbBits);
  const long n = static_cast<long>(x.magnitude_size()) - static_cast<long>(whole);
  FixedInt r;
  if (n <= 0) return r;
  if (partial == 0) {
    for (long i = 0; i < n; ++i) r.limbs_[i] = x.limbs_[whole + i];
  } else {
    mpn_rshift(r.limbs_.data(), x.limbs_.data() + whole, n, partial);
  }
  r.normalize(static_cast<int>(n), x.size_ < 0);
  return r;
}

unsigned long trailing_zeros(const FixedInt& x) {
  unsigned long i = 0;
  while (x.limbs_[i] == 0) ++i;
  return i * kLimbBits + static_cast<unsigned long>(__builtin_ctzll(x.limbs_[i]));
}

mpz_srcptr FixedInt::view(mpz_t storage) const { return mpz_roinit_n(storage, limbs_.data(), size_); }

FixedInt FixedInt::from_mpz(mpz_srcptr x) {
  const size_t n = mpz_size(x);
  if (n > static_cast<size_t>(kFixedIntLimbs)) throw FixedIntOverflow();
  FixedInt r;
  const mp_limb_t* limbs = mpz_limbs_read(x);
  for (size_t i = 0; i < n; ++i) r.limbs_[i] = limbs[i];
  r.size_ = mpz_sgn(x) < 0 ? -static_cast<int>(n) : static_cast<int>(n);
  return r;
}

mpz_class FixedInt::to_mpz() const {
  mpz_t v;
  return mpz_class(view(v));
}

namespace {

/// Results of the view-based operations; per thread, so its limbs are allocated once.
mpz_ptr scratch() {
  thread_local mpz_class result;
  return result.get_mpz_t();
}

}  // namespace

FixedInt operator/(const FixedInt& a, const FixedInt& b) {
  mpz_t va;
  mpz_t vb;
  mpz_tdiv_q(scratch(), a.view(va), b.view(vb));
  return FixedInt::from_mpz(scratch());
}

FixedInt divexact(const FixedInt& a, const FixedInt& b) {
  mpz_t va;
  mpz_t vb;
  mpz_divexact(scratch(), a.view(va), b.view(vb));
  return FixedInt::from_mpz(scratch());
}

FixedInt integer_gcd(const FixedInt& a, const FixedInt& b) {
  mpz_t va;
  mpz_t vb;
  mpz_gcd(scratch(), a.view(va), b.view(vb));
  return FixedInt::from_mpz(scratch());
}

double get_d_2exp(long& exponent, const FixedInt& x) {
  mpz_t v;
  return mpz_get_d_2exp(&exponent, x.view(v));
}

}  // namespace sscc::ccd::exact_stage
