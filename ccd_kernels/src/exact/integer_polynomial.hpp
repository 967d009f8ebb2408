// The arithmetic of the kernels' exact stage: polynomials in t of degree at most 3 with
// integer coefficients, evaluated at dyadic points and bounded on dyadic pieces of [0, 1].
//
// Every input is a double, so once all coordinates are scaled by one power of two they are
// integers, every predicate polynomial has integer coefficients, and every point the stage
// looks at (bisection points of [0, 1]) is a dyadic a / 2^k. Evaluating at a dyadic needs
// only integer products and shifts, and a piece's Bernstein coefficients come from the
// parent's by additions and shifts (de Casteljau without the halvings): no rational
// arithmetic and no gcds on the way.
//
// Everything is generic in the integer type `Int`: FixedInt (limbs inline, throws
// FixedIntOverflow past its width) first, for speed; mpz_class (unbounded) when that
// overflows. Both are instantiated in integer_polynomial.cpp and dyadic_root.cpp.
//
// Guarantee: exact; nothing is rounded. Signs of Bernstein coefficients are those of the
// true coefficients (all are scaled by the same positive integer).
#pragma once

#include <gmpxx.h>

#include <array>

#include "exact/fixed_int.hpp"

namespace sscc::ccd::exact_stage {

// The integer operations beyond +, -, *, << and comparisons, for mpz_class under the names
// FixedInt gives them.
inline mpz_class exact_shift_right(const mpz_class& x, unsigned long bits) { return x >> bits; }
inline unsigned long trailing_zeros(const mpz_class& x) { return mpz_scan1(x.get_mpz_t(), 0); }
inline mpz_class divexact(const mpz_class& a, const mpz_class& b) {
  mpz_class r;
  mpz_divexact(r.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  return r;
}
inline mpz_class integer_gcd(const mpz_class& a, const mpz_class& b) {
  mpz_class r;
  mpz_gcd(r.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  return r;
}
inline double get_d_2exp(long& exponent, const mpz_class& x) { return mpz_get_d_2exp(&exponent, x.get_mpz_t()); }

/// The highest degree any predicate of the kernels reaches (the coplanarity cubic).
inline constexpr int kMaxDegree = 3;

/// c[0] + c[1] t + ... + c[degree] t^degree; degree -1 is the zero polynomial, otherwise
/// c[degree] is non-zero.
template <class Int>
struct IntegerPolynomial {
  std::array<Int, kMaxDegree + 1> c;
  int degree = -1;

  bool is_zero() const { return degree < 0; }
  /// Recomputes `degree` from the coefficients.
  void trim() {
    degree = kMaxDegree;
    while (degree >= 0 && sgn(c[degree]) == 0) --degree;
  }
};

template <class Int>
IntegerPolynomial<Int> operator+(const IntegerPolynomial<Int>& a, const IntegerPolynomial<Int>& b);
template <class Int>
IntegerPolynomial<Int> operator-(const IntegerPolynomial<Int>& a, const IntegerPolynomial<Int>& b);
template <class Int>
IntegerPolynomial<Int> operator-(const IntegerPolynomial<Int>& a);
/// Precondition: deg a + deg b <= kMaxDegree.
template <class Int>
IntegerPolynomial<Int> operator*(const IntegerPolynomial<Int>& a, const IntegerPolynomial<Int>& b);

/// A dyadic point a / 2^k.
template <class Int>
struct Dyadic {
  Int a;
  unsigned long k = 0;
};

/// p(a / 2^k) 2^(k deg p): an integer, of the sign of p at a / 2^k.
template <class Int>
Int scaled_value(const IntegerPolynomial<Int>& p, const Dyadic<Int>& x);
/// Sign (-1, 0, +1) of p at a / 2^k.
template <class Int>
int sign_at(const IntegerPolynomial<Int>& p, const Dyadic<Int>& x) {
  return sgn(scaled_value(p, x));
}
template <class Int>
IntegerPolynomial<Int> derivative(const IntegerPolynomial<Int>& p);

/// The Bernstein coefficients of p, raised to degree kMaxDegree, on the piece
/// [a / 2^k, (a + 1) / 2^k], each multiplied by the same positive integer: the polynomial
/// lies in their hull on the piece, and the first and last have the signs of its values
/// at the piece's ends.
template <class Int>
using Bernstein = std::array<Int, kMaxDegree + 1>;
template <class Int>
Bernstein<Int> bernstein_on_piece(const IntegerPolynomial<Int>& p, const Dyadic<Int>& piece_start);
/// The same on [a / 2^k, (a + units) / 2^k].
template <class Int>
Bernstein<Int> bernstein_on_interval(const IntegerPolynomial<Int>& p, const Dyadic<Int>& start, const Int& units);
/// The coefficients on the two halves of the piece (de Casteljau at the midpoint).
template <class Int>
void split(const Bernstein<Int>& whole, Bernstein<Int>& left, Bernstein<Int>& right);
/// +1 or -1 when every coefficient has that sign (strictly), else 0.
template <class Int>
int uniform_sign(const Bernstein<Int>& b);
/// Sign changes in the sequence with zeros skipped: an upper bound on the number of roots
/// in the open piece, of the same parity (Descartes' rule in the Bernstein basis).
template <class Int>
int sign_variations(const Bernstein<Int>& b);

/// p divided by the gcd of its coefficients, with a positive leading coefficient: equal
/// for polynomials that differ by a constant factor.
template <class Int>
IntegerPolynomial<Int> primitive_positive(const IntegerPolynomial<Int>& p);
template <class Int>
bool operator==(const IntegerPolynomial<Int>& a, const IntegerPolynomial<Int>& b) {
  return a.degree == b.degree && a.c == b.c;
}

/// Greatest common divisor up to a constant factor (primitive, integer coefficients);
/// zero when both are zero.
template <class Int>
IntegerPolynomial<Int> gcd(const IntegerPolynomial<Int>& a, const IntegerPolynomial<Int>& b);
/// The product of p's distinct irreducible factors (up to a constant): p / gcd(p, p').
/// Precondition: p is not zero.
template <class Int>
IntegerPolynomial<Int> squarefree_part(const IntegerPolynomial<Int>& p);

}  // namespace sscc::ccd::exact_stage
