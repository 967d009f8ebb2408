// Polynomials in t of degree <= 3 in Bernstein form on a piece [t0, t1] of [0, 1], with
// error-bounded coefficients. On its piece a polynomial lies within the hull of its
// Bernstein coefficients, and its values at the ends are the first and last coefficient:
// that is what lets the filters certify signs over a whole piece.
#pragma once

#include <array>

#include "filter/bounded.hpp"

namespace sscc::ccd::filter {

template <int Degree>
struct Bernstein {
  std::array<Bounded, Degree + 1> b;

  /// +1 or -1 when the polynomial certainly has that sign on the whole piece, else 0.
  int certain_sign_on_piece() const {
    const int s = certain_sign(b[0]);
    for (int i = 1; i <= Degree; ++i) {
      if (certain_sign(b[i]) != s) return 0;
    }
    return s;
  }

  /// Certain sign of the value at the piece's start (0 if unknown).
  int sign_at_start() const { return certain_sign(b[0]); }
  int sign_at_end() const { return certain_sign(b[Degree]); }

  /// de Casteljau at the midpoint: the same polynomial on the two halves.
  void split(Bernstein& left, Bernstein& right) const {
    std::array<Bounded, Degree + 1> work = b;
    left.b[0] = work[0];
    right.b[Degree] = work[Degree];
    for (int level = 1; level <= Degree; ++level) {
      for (int i = 0; i + level <= Degree; ++i) work[i] = scaled(work[i] + work[i + 1], 0.5);
      left.b[level] = work[0];
      right.b[Degree - level] = work[Degree - level];
    }
  }

  Bernstein operator+(const Bernstein& o) const {
    Bernstein r;
    for (int i = 0; i <= Degree; ++i) r.b[i] = b[i] + o.b[i];
    return r;
  }
  Bernstein operator-(const Bernstein& o) const {
    Bernstein r;
    for (int i = 0; i <= Degree; ++i) r.b[i] = b[i] - o.b[i];
    return r;
  }
  Bernstein operator-() const {
    Bernstein r;
    for (int i = 0; i <= Degree; ++i) r.b[i] = -b[i];
    return r;
  }
};

using Quadratic = Bernstein<2>;
using Cubic = Bernstein<3>;

}  // namespace sscc::ccd::filter
