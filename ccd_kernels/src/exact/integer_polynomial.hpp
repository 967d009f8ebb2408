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
// Guarantee: exact; nothing is rounded. Signs of Bernstein coefficients are those of the
// true coefficients (all are scaled by the same positive integer).
#pragma once

#include <gmpxx.h>

#include <array>

namespace sscc::ccd::exact_stage {

/// The highest degree any predicate of the kernels reaches (the coplanarity cubic).
inline constexpr int kMaxDegree = 3;

/// c[0] + c[1] t + ... + c[degree] t^degree; degree -1 is the zero polynomial, otherwise
/// c[degree] is non-zero.
struct IntegerPolynomial {
  std::array<mpz_class, kMaxDegree + 1> c;
  int degree = -1;

  bool is_zero() const { return degree < 0; }
  /// Recomputes `degree` from the coefficients.
  void trim();
};

IntegerPolynomial operator+(const IntegerPolynomial& a, const IntegerPolynomial& b);
IntegerPolynomial operator-(const IntegerPolynomial& a, const IntegerPolynomial& b);
IntegerPolynomial operator-(const IntegerPolynomial& a);
/// Precondition: deg a + deg b <= kMaxDegree.
IntegerPolynomial operator*(const IntegerPolynomial& a, const IntegerPolynomial& b);

/// A dyadic point a / 2^k.
struct Dyadic {
  mpz_class a;
  unsigned long k = 0;
};

/// p(a / 2^k) 2^(k deg p): an integer, of the sign of p at a / 2^k.
mpz_class scaled_value(const IntegerPolynomial& p, const Dyadic& x);
/// Sign (-1, 0, +1) of p at a / 2^k.
inline int sign_at(const IntegerPolynomial& p, const Dyadic& x) { return sgn(scaled_value(p, x)); }
IntegerPolynomial derivative(const IntegerPolynomial& p);

/// The Bernstein coefficients of p, raised to degree kMaxDegree, on the piece
/// [a / 2^k, (a + 1) / 2^k], each multiplied by the same positive integer: the polynomial
/// lies in their hull on the piece, and the first and last have the signs of its values
/// at the piece's ends.
using Bernstein = std::array<mpz_class, kMaxDegree + 1>;
Bernstein bernstein_on_piece(const IntegerPolynomial& p, const Dyadic& piece_start);
/// The coefficients on the two halves of the piece (de Casteljau at the midpoint).
void split(const Bernstein& whole, Bernstein& left, Bernstein& right);
/// +1 or -1 when every coefficient has that sign (strictly), else 0.
int uniform_sign(const Bernstein& b);
/// Sign changes in the sequence with zeros skipped: an upper bound on the number of roots
/// in the open piece, of the same parity (Descartes' rule in the Bernstein basis).
int sign_variations(const Bernstein& b);

/// p divided by the gcd of its coefficients, with a positive leading coefficient: equal
/// for polynomials that differ by a constant factor.
IntegerPolynomial primitive_positive(const IntegerPolynomial& p);
inline bool operator==(const IntegerPolynomial& a, const IntegerPolynomial& b) {
  return a.degree == b.degree && a.c == b.c;
}

/// Greatest common divisor up to a constant factor (primitive, integer coefficients);
/// zero when both are zero.
IntegerPolynomial gcd(const IntegerPolynomial& a, const IntegerPolynomial& b);
/// The product of p's distinct irreducible factors (up to a constant): p / gcd(p, p').
/// Precondition: p is not zero.
IntegerPolynomial squarefree_part(const IntegerPolynomial& p);

}  // namespace sscc::ccd::exact_stage
