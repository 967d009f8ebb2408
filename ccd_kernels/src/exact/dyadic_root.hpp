// Real roots in [0, 1] of the kernels' integer predicate polynomials, held as dyadic
// isolating pieces, and exact signs of other polynomials at them.
//
// Guarantee: exact. A root is either exactly a dyadic point or the only root of its
// square-free polynomial in the open piece (a / 2^k, (a + 1) / 2^k), at whose ends that
// polynomial is non-zero with opposite signs. Isolation subdivides [0, 1] and counts the
// sign changes of Bernstein coefficients (Descartes' rule of signs); signs at a root come
// from a polynomial's Bernstein coefficients on the root's piece once they agree, and are
// zero exactly when the gcd with the root's polynomial vanishes inside the piece.
#pragma once

#include <vector>

#include "exact/integer_polynomial.hpp"

namespace sscc::ccd::exact_stage {

template <class Int>
struct DyadicRoot {
  IntegerPolynomial<Int> polynomial;  ///< square-free
  Dyadic<Int> start;                  ///< the root itself when exact, else its piece's start
  bool exact = false;
  int sign_at_start = 0;  ///< of `polynomial`, when not exact (never 0)
  /// `polynomial` on the piece, when not exact: narrowing splits it (additions and shifts)
  /// rather than evaluating at the midpoint (products of long integers).
  Bernstein<Int> on_piece;
  /// Bits the next Newton step aims to add (0: as many as the piece has). Halved past each
  /// failure, doubled after each success: where the polynomial curves strongly (|p''/p'|
  /// huge, coefficients of very different magnitudes) Newton gains fewer bits than the
  /// piece has, long before it gains as many.
  unsigned long newton_gain = 0;
};

/// The distinct real roots of p in the closed interval [0, 1], in increasing order.
/// Precondition: p is not the zero polynomial.
template <class Int>
std::vector<DyadicRoot<Int>> roots_in_unit_interval(const IntegerPolynomial<Int>& p);

/// A root exactly at a / 2^k.
template <class Int>
DyadicRoot<Int> exact_root(const Dyadic<Int>& x);

/// Halves the root's piece (or finds it exactly at the midpoint).
template <class Int>
void bisect(DyadicRoot<Int>& root);

/// Exact sign (-1, 0, +1) of g at the root; narrows the root's piece as needed.
template <class Int>
int sign_at_root(const IntegerPolynomial<Int>& g, DyadicRoot<Int>& root);

/// Sign of (a - b); narrows both pieces as needed.
template <class Int>
int compare(DyadicRoot<Int>& a, DyadicRoot<Int>& b);

/// A double at most the root and within `width` of it (width >= 2^-52); narrows the piece.
template <class Int>
double lower_bound_within(DyadicRoot<Int>& root, double width);

}  // namespace sscc::ccd::exact_stage
