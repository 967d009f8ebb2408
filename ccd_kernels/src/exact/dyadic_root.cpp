#include "exact/dyadic_root.hpp"

#include <cfloat>
#include <cmath>

namespace sscc::ccd::exact_stage {

namespace {

Dyadic left_child(const Dyadic& start) { return {start.a << 1, start.k + 1}; }
Dyadic right_child(const Dyadic& start) { return {(start.a << 1) + 1, start.k + 1}; }
Dyadic piece_end(const Dyadic& start) { return {start.a + 1, start.k}; }

/// Sign of x - y.
int compare(const Dyadic& x, const Dyadic& y) {
  if (x.k == y.k) return cmp(x.a, y.a);
  if (x.k < y.k) return cmp(mpz_class(x.a << (y.k - x.k)), y.a);
  return cmp(x.a, mpz_class(y.a << (x.k - y.k)));
}

Dyadic upper_end(const DyadicRoot& r) { return r.exact ? r.start : piece_end(r.start); }

/// Whether a lies certainly below b from their pieces alone.
bool certainly_below(const DyadicRoot& a, const DyadicRoot& b) {
  const int c = compare(upper_end(a), b.start);
  return c < 0 || (c == 0 && !(a.exact && b.exact));
}

/// Whether the open piece of `root` holds a root of `common` (a divisor of the root's
/// square-free polynomial, so with at most that one root there, and simple).
bool common_root_in_piece(const IntegerPolynomial& common, const Dyadic& lo, const Dyadic& hi) {
  return common.degree >= 1 && sign_at(common, lo) * sign_at(common, hi) < 0;
}

/// Depth-first subdivision of [0, 1], left first, so roots come out in increasing order.
struct IsolationStep {
  Bernstein b;
  Dyadic start;
  bool emit_exact_start = false;  ///< emit an exact root at `start` before this piece
};

}  // namespace

DyadicRoot exact_root(const Dyadic& x) {
  DyadicRoot r;
  r.polynomial.c[0] = -x.a;
  mpz_mul_2exp(r.polynomial.c[1].get_mpz_t(), mpz_class(1).get_mpz_t(), x.k);
  r.polynomial.trim();
  r.start = x;
  r.exact = true;
  return r;
}

std::vector<DyadicRoot> roots_in_unit_interval(const IntegerPolynomial& p) {
  std::vector<DyadicRoot> roots;
  if (p.degree <= 0) return roots;
  const IntegerPolynomial q = squarefree_part(p);
  const auto emit_exact = [&](const Dyadic& x) {
    DyadicRoot r;
    r.polynomial = q;
    r.start = x;
    r.exact = true;
    roots.push_back(std::move(r));
  };
  const Dyadic zero{0, 0};
  const Dyadic one{1, 0};
  if (sign_at(q, zero) == 0) emit_exact(zero);
  std::vector<IsolationStep> stack;
  stack.push_back({bernstein_on_piece(q, zero), zero, false});
  while (!stack.empty()) {
    IsolationStep step = std::move(stack.back());
    stack.pop_back();
    if (step.emit_exact_start) emit_exact(step.start);
    const int variations = sign_variations(step.b);
    if (variations == 0) continue;
    if (variations == 1 && sgn(step.b[0]) != 0 && sgn(step.b[kMaxDegree]) != 0) {
      DyadicRoot r;
      r.polynomial = q;
      r.start = step.start;
      r.sign_at_start = sgn(step.b[0]);
      roots.push_back(std::move(r));
      continue;
    }
    IsolationStep left{{}, left_child(step.start), false};
    IsolationStep right{{}, right_child(step.start), false};
    split(step.b, left.b, right.b);
    right.emit_exact_start = sgn(left.b[kMaxDegree]) == 0;  // the midpoint is a root
    stack.push_back(std::move(right));
    stack.push_back(std::move(left));
  }
  if (sign_at(q, one) == 0) emit_exact(one);
  return roots;
}

void bisect(DyadicRoot& root) {
  if (root.exact) return;
  const Dyadic mid = right_child(root.start);
  const int s = sign_at(root.polynomial, mid);
  if (s == 0) {
    root.start = mid;
    root.exact = true;
  } else if (s == root.sign_at_start) {
    root.start = mid;
  } else {
    root.start = left_child(root.start);
  }
}

int sign_at_root(const IntegerPolynomial& g, DyadicRoot& root) {
  if (g.is_zero()) return 0;
  bool zero_excluded = false;
  while (!root.exact) {
    const int s = uniform_sign(bernstein_on_piece(g, root.start));
    if (s != 0) return s;
    if (!zero_excluded) {
      // g may vanish at the root: exactly when it shares a factor with the root's
      // polynomial that vanishes in the piece. Otherwise narrowing ends with one sign.
      if (common_root_in_piece(gcd(root.polynomial, g), root.start, piece_end(root.start))) return 0;
      zero_excluded = true;
    }
    bisect(root);
  }
  return sign_at(g, root.start);
}

int compare(DyadicRoot& a, DyadicRoot& b) {
  bool equality_excluded = false;
  while (true) {
    if (certainly_below(a, b)) return -1;
    if (certainly_below(b, a)) return 1;
    if (a.exact && b.exact) return 0;  // neither below the other: the same point
    if (a.exact) {
      // a lies in b's open piece: equal iff a is a root of b's polynomial there.
      if (sign_at(b.polynomial, a.start) == 0) return 0;
      bisect(b);
      continue;
    }
    if (b.exact) {
      if (sign_at(a.polynomial, b.start) == 0) return 0;
      bisect(a);
      continue;
    }
    if (!equality_excluded) {
      const Dyadic& lo = compare(a.start, b.start) >= 0 ? a.start : b.start;
      const Dyadic a_end = piece_end(a.start);
      const Dyadic b_end = piece_end(b.start);
      const Dyadic& hi = compare(a_end, b_end) <= 0 ? a_end : b_end;
      if (common_root_in_piece(gcd(a.polynomial, b.polynomial), lo, hi)) return 0;
      equality_excluded = true;
    }
    bisect(a);
    bisect(b);
  }
}

double lower_bound_within(DyadicRoot& root, double width) {
  // Pieces of width 2^-k <= width / 2 leave room for the rounding of the start below.
  int exponent = 0;
  std::frexp(width, &exponent);  // width in [2^(exponent-1), 2^exponent)
  const unsigned long k_needed = static_cast<unsigned long>(std::max(0, 2 - exponent));
  while (!root.exact && root.start.k < k_needed) bisect(root);
  if (sgn(root.start.a) == 0) return 0.0;
  long a_exponent = 0;
  const double mantissa = mpz_get_d_2exp(&a_exponent, root.start.a.get_mpz_t());  // truncated
  const long exponent_of_start = a_exponent - static_cast<long>(root.start.k);
  // Below the normal range ldexp would round; such a time is within any width of 0.
  if (exponent_of_start <= DBL_MIN_EXP) return 0.0;
  return std::ldexp(mantissa, static_cast<int>(exponent_of_start));
}

}  // namespace sscc::ccd::exact_stage
