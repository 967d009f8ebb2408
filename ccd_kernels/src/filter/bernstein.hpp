// Polynomials in t of degree <= 3 in Bernstein form on a piece [t0, t1] of [0, 1], in
// floating point, with one absolute error bound shared by all coefficients (supplied by
// the caller, see coplanar_filter.cpp for its derivation). On its piece a polynomial lies
// within the hull of its Bernstein coefficients, and its values at the ends are the first
// and last coefficient: that is what lets the filters certify signs over a whole piece.
#pragma once

#include <array>

namespace sscc::ccd::filter {

/// +1 or -1 when a value known to within `error` certainly has that sign, else 0.
inline int certain_sign(double value, double error) {
  // Branch-free: these signs are data-dependent coin flips on generic input.
  return static_cast<int>(value > error) - static_cast<int>(-value > error);
}

template <int Degree>
struct Bernstein {
  std::array<double, Degree + 1> b;

  /// +1 or -1 when the polynomial certainly has that sign on the whole piece, else 0.
  int certain_sign_on_piece(double error) const {
    bool positive = true;
    bool negative = true;
    for (int i = 0; i <= Degree; ++i) {
      positive &= b[i] > error;
      negative &= -b[i] > error;
    }
    return static_cast<int>(positive) - static_cast<int>(negative);
  }

  /// Certain sign of the value at the piece's start or end (0 if unknown).
  int sign_at_start(double error) const { return certain_sign(b[0], error); }
  int sign_at_end(double error) const { return certain_sign(b[Degree], error); }

  /// de Casteljau at the midpoint: the same polynomial on the two halves. Each level adds
  /// at most one rounding of a coefficient-sized value to the error.
  void split(Bernstein& left, Bernstein& right) const {
    std::array<double, Degree + 1> work = b;
    left.b[0] = work[0];
    right.b[Degree] = work[Degree];
    for (int level = 1; level <= Degree; ++level) {
      for (int i = 0; i + level <= Degree; ++i) work[i] = 0.5 * (work[i] + work[i + 1]);
      left.b[level] = work[0];
      right.b[Degree - level] = work[Degree - level];
    }
  }

  /// de Casteljau at an arbitrary tau in [0, 1]: the polynomial on [start, start + tau w]
  /// and on the rest. 1 - tau may round, so each level rounds up to 4 times a coefficient's
  /// size instead of once: count the split as 4 bisections in the error bound.
  void split_at(double tau, Bernstein& left, Bernstein& right) const {
    const double sigma = 1.0 - tau;
    std::array<double, Degree + 1> work = b;
    left.b[0] = work[0];
    right.b[Degree] = work[Degree];
    for (int level = 1; level <= Degree; ++level) {
      for (int i = 0; i + level <= Degree; ++i) work[i] = sigma * work[i] + tau * work[i + 1];
      left.b[level] = work[0];
      right.b[Degree - level] = work[Degree - level];
    }
  }

  /// The value at tau in [0, 1], with the error of a split_at.
  double value_at(double tau) const {
    Bernstein left;
    Bernstein right;
    split_at(tau, left, right);
    return left.b[Degree];
  }
};

using Quadratic = Bernstein<2>;
using Cubic = Bernstein<3>;

}  // namespace sscc::ccd::filter
