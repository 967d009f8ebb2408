#include "exact/integer_polynomial.hpp"

#include <algorithm>
#include <stdexcept>

namespace sscc::ccd::exact_stage {

template <class Int>
IntegerPolynomial<Int> operator+(const IntegerPolynomial<Int>& a, const IntegerPolynomial<Int>& b) {
  IntegerPolynomial<Int> r;
  for (int i = 0; i <= kMaxDegree; ++i) r.c[i] = a.c[i] + b.c[i];
  r.trim();
  return r;
}

template <class Int>
IntegerPolynomial<Int> operator-(const IntegerPolynomial<Int>& a, const IntegerPolynomial<Int>& b) {
  IntegerPolynomial<Int> r;
  for (int i = 0; i <= kMaxDegree; ++i) r.c[i] = a.c[i] - b.c[i];
  r.trim();
  return r;
}

template <class Int>
IntegerPolynomial<Int> operator-(const IntegerPolynomial<Int>& a) {
  IntegerPolynomial<Int> r = a;
  for (Int& x : r.c) x = -x;
  return r;
}

template <class Int>
IntegerPolynomial<Int> operator*(const IntegerPolynomial<Int>& a, const IntegerPolynomial<Int>& b) {
  IntegerPolynomial<Int> r;
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

template <class Int>
Int scaled_value(const IntegerPolynomial<Int>& p, const Dyadic<Int>& x) {
  if (p.is_zero()) return 0;
  // p(a / 2^k) 2^(k d) = sum c_i a^i 2^(k (d - i)), by Horner.
  Int value = p.c[p.degree];
  for (int i = p.degree - 1; i >= 0; --i) {
    value *= x.a;
    value += p.c[i] << (x.k * static_cast<unsigned long>(p.degree - i));
  }
  return value;
}

template <class Int>
IntegerPolynomial<Int> derivative(const IntegerPolynomial<Int>& p) {
  IntegerPolynomial<Int> d;
  for (int i = 1; i <= p.degree; ++i) d.c[i - 1] = p.c[i] * Int(i);
  d.trim();
  return d;
}

template <class Int>
Bernstein<Int> bernstein_on_piece(const IntegerPolynomial<Int>& p, const Dyadic<Int>& piece_start) {
  return bernstein_on_interval(p, piece_start, Int(1));
}

template <class Int>
Bernstein<Int> bernstein_on_interval(const IntegerPolynomial<Int>& p, const Dyadic<Int>& start, const Int& units) {
  // q(s) = 2^(3k) p((a + u s) / 2^k) for s in [0, 1], by Horner in polynomials of s.
  const bool unit = units == Int(1);
  std::array<Int, kMaxDegree + 1> q;
  for (Int& x : q) x = 0;
  for (int i = kMaxDegree; i >= 0; --i) {
    for (int j = kMaxDegree; j >= 0; --j) {
      q[j] *= start.a;
      if (j > 0) q[j] += unit ? q[j - 1] : Int(units * q[j - 1]);
    }
    q[0] += p.c[i] << (start.k * static_cast<unsigned long>(kMaxDegree - i));
  }
  // Bernstein coefficients of a cubic, times 3: b_j = sum_i C(j, i) (3 / C(3, i)) q_i.
  Bernstein<Int> b;
  b[0] = Int(3) * q[0];
  b[1] = b[0] + q[1];
  b[2] = b[0] + Int(2) * q[1] + q[2];
  b[3] = Int(3) * (q[0] + q[1] + q[2] + q[3]);
  return b;
}

template <class Int>
void split(const Bernstein<Int>& whole, Bernstein<Int>& left, Bernstein<Int>& right) {
  // de Casteljau at 1/2 without the halvings: level l's values carry a factor 2^l, so
  // both halves are scaled by 2^3 once each level's value is shifted by 3 - l.
  Bernstein<Int> work = whole;
  left[0] = work[0] << kMaxDegree;
  right[kMaxDegree] = work[kMaxDegree] << kMaxDegree;
  for (int level = 1; level <= kMaxDegree; ++level) {
    for (int i = 0; i + level <= kMaxDegree; ++i) work[i] += work[i + 1];
    left[level] = work[0] << (kMaxDegree - level);
    right[kMaxDegree - level] = work[kMaxDegree - level] << (kMaxDegree - level);
  }
  // Drop the common power of two, so that deep pieces keep short coefficients.
  for (Bernstein<Int>* half : {&left, &right}) {
    unsigned long shift = ~0UL;
    for (const Int& x : *half) {
      if (sgn(x) != 0) shift = std::min(shift, trailing_zeros(x));
    }
    if (shift == ~0UL || shift == 0) continue;
    for (Int& x : *half) x = exact_shift_right(x, shift);
  }
}

template <class Int>
int uniform_sign(const Bernstein<Int>& b) {
  const int s = sgn(b[0]);
  for (const Int& x : b) {
    if (sgn(x) != s) return 0;
  }
  return s;
}

template <class Int>
int sign_variations(const Bernstein<Int>& b) {
  int variations = 0;
  int previous = 0;
  for (const Int& x : b) {
    const int s = sgn(x);
    if (s == 0) continue;
    if (previous != 0 && s != previous) ++variations;
    previous = s;
  }
  return variations;
}

namespace {

/// p divided by the gcd of its coefficients (sign kept).
template <class Int>
void make_primitive(IntegerPolynomial<Int>& p) {
  if (p.is_zero()) return;
  const Int one(1);
  Int content = abs(p.c[p.degree]);
  for (int i = 0; i < p.degree && content != one; ++i) content = integer_gcd(content, p.c[i]);
  if (content == one) return;
  for (int i = 0; i <= p.degree; ++i) p.c[i] = divexact(p.c[i], content);
}

/// lc(b)^m a = q b + r with deg r < deg b (pseudo-division); b not zero.
template <class Int>
void pseudo_divide(const IntegerPolynomial<Int>& a, const IntegerPolynomial<Int>& b, IntegerPolynomial<Int>& q,
                   IntegerPolynomial<Int>& r) {
  r = a;
  q = IntegerPolynomial<Int>();
  const Int& lead = b.c[b.degree];
  while (r.degree >= b.degree) {
    const int shift = r.degree - b.degree;
    const Int factor = r.c[r.degree];
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

template <class Int>
IntegerPolynomial<Int> primitive_positive(const IntegerPolynomial<Int>& p) {
  IntegerPolynomial<Int> q = p;
  make_primitive(q);
  return !q.is_zero() && sgn(q.c[q.degree]) < 0 ? -q : q;
}

template <class Int>
IntegerPolynomial<Int> gcd(const IntegerPolynomial<Int>& a, const IntegerPolynomial<Int>& b) {
  IntegerPolynomial<Int> x = a;
  IntegerPolynomial<Int> y = b;
  make_primitive(x);
  make_primitive(y);
  while (!y.is_zero()) {
    IntegerPolynomial<Int> q;
    IntegerPolynomial<Int> r;
    pseudo_divide(x, y, q, r);
    make_primitive(r);
    x = std::move(y);
    y = std::move(r);
  }
  return x;
}

template <class Int>
IntegerPolynomial<Int> squarefree_part(const IntegerPolynomial<Int>& p) {
  const IntegerPolynomial<Int> slope = derivative(p);
  IntegerPolynomial<Int> result = p;
  // Lines are square-free, and so are quadratics and cubics with a non-zero discriminant
  // (a few products, where the gcd with the derivative takes pseudo-divisions and gcds).
  bool squarefree = p.degree <= 1;
  if (p.degree == 2) {
    const Int& a = p.c[2];
    const Int& b = p.c[1];
    const Int& c = p.c[0];
    squarefree = sgn(Int(b * b - Int(4) * a * c)) != 0;
  } else if (p.degree == 3) {
    // 18abcd - 4b^3 d + b^2 c^2 - 4a c^3 - 27 a^2 d^2 for a t^3 + b t^2 + c t + d.
    const Int& a = p.c[3];
    const Int& b = p.c[2];
    const Int& c = p.c[1];
    const Int& d = p.c[0];
    const Int bc = b * c;
    const Int ad = a * d;
    squarefree =
        sgn(Int(Int(18) * bc * ad - Int(4) * b * b * b * d + bc * bc - Int(4) * a * c * c * c - Int(27) * ad * ad)) !=
        0;
  }
  if (!squarefree && !slope.is_zero()) {
    const IntegerPolynomial<Int> common = gcd(p, slope);
    if (common.degree >= 1) {
      IntegerPolynomial<Int> remainder;
      pseudo_divide(p, common, result, remainder);
    }
  }
  make_primitive(result);
  return result;
}

#define SSCC_INSTANTIATE_INTEGER_POLYNOMIAL(Int)                                                                \
  template IntegerPolynomial<Int> operator+(const IntegerPolynomial<Int>&, const IntegerPolynomial<Int>&);      \
  template IntegerPolynomial<Int> operator-(const IntegerPolynomial<Int>&, const IntegerPolynomial<Int>&);      \
  template IntegerPolynomial<Int> operator-(const IntegerPolynomial<Int>&);                                     \
  template IntegerPolynomial<Int> operator*(const IntegerPolynomial<Int>&, const IntegerPolynomial<Int>&);      \
  template Int scaled_value(const IntegerPolynomial<Int>&, const Dyadic<Int>&);                                 \
  template IntegerPolynomial<Int> derivative(const IntegerPolynomial<Int>&);                                    \
  template Bernstein<Int> bernstein_on_piece(const IntegerPolynomial<Int>&, const Dyadic<Int>&);                \
  template Bernstein<Int> bernstein_on_interval(const IntegerPolynomial<Int>&, const Dyadic<Int>&, const Int&); \
  template void split(const Bernstein<Int>&, Bernstein<Int>&, Bernstein<Int>&);                                 \
  template int uniform_sign(const Bernstein<Int>&);                                                             \
  template int sign_variations(const Bernstein<Int>&);                                                          \
  template IntegerPolynomial<Int> primitive_positive(const IntegerPolynomial<Int>&);                            \
  template IntegerPolynomial<Int> gcd(const IntegerPolynomial<Int>&, const IntegerPolynomial<Int>&);            \
  template IntegerPolynomial<Int> squarefree_part(const IntegerPolynomial<Int>&);

SSCC_INSTANTIATE_INTEGER_POLYNOMIAL(FixedInt)
SSCC_INSTANTIATE_INTEGER_POLYNOMIAL(mpz_class)

}  // namespace sscc::ccd::exact_stage
