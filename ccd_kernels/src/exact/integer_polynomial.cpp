#include "exact/integer_polynomial.hpp"

#include <algorithm>
#include <stdexcept>

namespace sscc::ccd::exact_stage {

void IntegerPolynomial::trim() {
  degree = kMaxDegree;
  while (degree >= 0 && sgn(c[degree]) == 0) --degree;
}

IntegerPolynomial operator+(const IntegerPolynomial& a, const IntegerPolynomial& b) {
  IntegerPolynomial r;
  for (int i = 0; i <= kMaxDegree; ++i) r.c[i] = a.c[i] + b.c[i];
  r.trim();
  return r;
}

IntegerPolynomial operator-(const IntegerPolynomial& a, const IntegerPolynomial& b) {
  IntegerPolynomial r;
  for (int i = 0; i <= kMaxDegree; ++i) r.c[i] = a.c[i] - b.c[i];
  r.trim();
  return r;
}

IntegerPolynomial operator-(const IntegerPolynomial& a) {
  IntegerPolynomial r = a;
  for (mpz_class& x : r.c) x = -x;
  return r;
}

IntegerPolynomial operator*(const IntegerPolynomial& a, const IntegerPolynomial& b) {
  IntegerPolynomial r;
  if (a.is_zero() || b.is_zero()) return r;
  if (a.degree + b.degree > kMaxDegree) {
    throw std::logic_error("sscc::ccd::exact_stage: product above the supported degree");
  }
  for (int i = 0; i <= a.degree; ++i) {
    for (int j = 0; j <= b.degree; ++j) r.c[i + j] += a.c[i] * b.c[j];
  }
  r.degree = a.degree + b.degree;  // integers have no zero divisors
  return r;
}

mpz_class scaled_value(const IntegerPolynomial& p, const Dyadic& x) {
  if (p.is_zero()) return 0;
  // p(a / 2^k) 2^(k d) = sum c_i a^i 2^(k (d - i)), by Horner.
  mpz_class value = p.c[p.degree];
  thread_local mpz_class term;  // scratch, limbs reused
  for (int i = p.degree - 1; i >= 0; --i) {
    value *= x.a;
    mpz_mul_2exp(term.get_mpz_t(), p.c[i].get_mpz_t(), x.k * static_cast<unsigned long>(p.degree - i));
    value += term;
  }
  return value;
}

IntegerPolynomial derivative(const IntegerPolynomial& p) {
  IntegerPolynomial d;
  for (int i = 1; i <= p.degree; ++i) d.c[i - 1] = p.c[i] * i;
  d.trim();
  return d;
}

Bernstein bernstein_on_piece(const IntegerPolynomial& p, const Dyadic& piece_start) {
  // q(s) = 2^(3k) p((a + s) / 2^k) for s in [0, 1], by Horner in polynomials of s.
  thread_local std::array<mpz_class, kMaxDegree + 1> q;  // scratch, limbs reused
  thread_local mpz_class term;
  for (mpz_class& x : q) x = 0;
  for (int i = kMaxDegree; i >= 0; --i) {
    for (int j = kMaxDegree; j >= 0; --j) {
      q[j] *= piece_start.a;
      if (j > 0) q[j] += q[j - 1];
    }
    mpz_mul_2exp(term.get_mpz_t(), p.c[i].get_mpz_t(), piece_start.k * static_cast<unsigned long>(kMaxDegree - i));
    q[0] += term;
  }
  // Bernstein coefficients of a cubic, times 3: b_j = sum_i C(j, i) (3 / C(3, i)) q_i.
  Bernstein b;
  b[0] = 3 * q[0];
  b[1] = b[0] + q[1];
  b[2] = b[0] + 2 * q[1] + q[2];
  b[3] = 3 * (q[0] + q[1] + q[2] + q[3]);
  return b;
}

void split(const Bernstein& whole, Bernstein& left, Bernstein& right) {
  // de Casteljau at 1/2 without the halvings: level l's values carry a factor 2^l, so
  // both halves are scaled by 2^3 once each level's value is shifted by 3 - l.
  // Scratch kept per thread: its limbs are reused rather than allocated on every split.
  thread_local Bernstein work;
  for (int i = 0; i <= kMaxDegree; ++i) work[i] = whole[i];
  left[0] = work[0] << kMaxDegree;
  right[kMaxDegree] = work[kMaxDegree] << kMaxDegree;
  for (int level = 1; level <= kMaxDegree; ++level) {
    for (int i = 0; i + level <= kMaxDegree; ++i) work[i] += work[i + 1];
    left[level] = work[0] << (kMaxDegree - level);
    right[kMaxDegree - level] = work[kMaxDegree - level] << (kMaxDegree - level);
  }
  // Drop the common power of two, so that deep pieces keep short coefficients.
  for (Bernstein* half : {&left, &right}) {
    mp_bitcnt_t shift = ~mp_bitcnt_t{0};
    for (const mpz_class& x : *half) {
      if (sgn(x) != 0) shift = std::min(shift, mpz_scan1(x.get_mpz_t(), 0));
    }
    if (shift == ~mp_bitcnt_t{0} || shift == 0) continue;
    for (mpz_class& x : *half) mpz_fdiv_q_2exp(x.get_mpz_t(), x.get_mpz_t(), shift);
  }
}

int uniform_sign(const Bernstein& b) {
  const int s = sgn(b[0]);
  for (const mpz_class& x : b) {
    if (sgn(x) != s) return 0;
  }
  return s;
}

int sign_variations(const Bernstein& b) {
  int variations = 0;
  int previous = 0;
  for (const mpz_class& x : b) {
    const int s = sgn(x);
    if (s == 0) continue;
    if (previous != 0 && s != previous) ++variations;
    previous = s;
  }
  return variations;
}

namespace {

/// p divided by the gcd of its coefficients (sign kept).
void make_primitive(IntegerPolynomial& p) {
  if (p.is_zero()) return;
  mpz_class content = abs(p.c[p.degree]);
  for (int i = 0; i < p.degree && content != 1; ++i) {
    mpz_gcd(content.get_mpz_t(), content.get_mpz_t(), p.c[i].get_mpz_t());
  }
  if (content == 1) return;
  for (int i = 0; i <= p.degree; ++i) mpz_divexact(p.c[i].get_mpz_t(), p.c[i].get_mpz_t(), content.get_mpz_t());
}

/// lc(b)^m a = q b + r with deg r < deg b (pseudo-division); b not zero.
void pseudo_divide(const IntegerPolynomial& a, const IntegerPolynomial& b, IntegerPolynomial& q, IntegerPolynomial& r) {
  r = a;
  q = IntegerPolynomial();
  const mpz_class& lead = b.c[b.degree];
  while (r.degree >= b.degree) {
    const int shift = r.degree - b.degree;
    const mpz_class factor = r.c[r.degree];
    for (int i = 0; i <= kMaxDegree; ++i) {
      q.c[i] *= lead;
      r.c[i] *= lead;
    }
    q.c[shift] += factor;
    for (int i = 0; i <= b.degree; ++i) r.c[i + shift] -= factor * b.c[i];
    r.trim();
  }
  q.trim();
}

}  // namespace

IntegerPolynomial primitive_positive(const IntegerPolynomial& p) {
  IntegerPolynomial q = p;
  make_primitive(q);
  return !q.is_zero() && sgn(q.c[q.degree]) < 0 ? -q : q;
}

IntegerPolynomial gcd(const IntegerPolynomial& a, const IntegerPolynomial& b) {
  IntegerPolynomial x = a;
  IntegerPolynomial y = b;
  make_primitive(x);
  make_primitive(y);
  while (!y.is_zero()) {
    IntegerPolynomial q;
    IntegerPolynomial r;
    pseudo_divide(x, y, q, r);
    make_primitive(r);
    x = std::move(y);
    y = std::move(r);
  }
  return x;
}

IntegerPolynomial squarefree_part(const IntegerPolynomial& p) {
  const IntegerPolynomial slope = derivative(p);
  IntegerPolynomial result = p;
  // Lines are square-free, and so are quadratics with a non-zero discriminant.
  const bool squarefree = p.degree <= 1 || (p.degree == 2 && sgn(p.c[1] * p.c[1] - 4 * p.c[0] * p.c[2]) != 0);
  if (!squarefree && !slope.is_zero()) {
    const IntegerPolynomial common = gcd(p, slope);
    if (common.degree >= 1) {
      IntegerPolynomial remainder;
      pseudo_divide(p, common, result, remainder);
    }
  }
  make_primitive(result);
  return result;
}

}  // namespace sscc::ccd::exact_stage
