#include "exact/dyadic_root.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <utility>

namespace sscc::ccd::exact_stage {

namespace {

template <class Int>
Dyadic<Int> left_child(const Dyadic<Int>& start) {
  return {start.a << 1, start.k + 1};
}
template <class Int>
Dyadic<Int> right_child(const Dyadic<Int>& start) {
  return {Int((start.a << 1) + Int(1)), start.k + 1};
}
template <class Int>
Dyadic<Int> piece_end(const Dyadic<Int>& start) {
  return {Int(start.a + Int(1)), start.k};
}

/// Sign of x - y.
template <class Int>
int compare(const Dyadic<Int>& x, const Dyadic<Int>& y) {
  if (x.k == y.k) return cmp(x.a, y.a);
  if (x.k < y.k) return cmp(Int(x.a << (y.k - x.k)), y.a);
  return cmp(x.a, Int(y.a << (x.k - y.k)));
}

template <class Int>
Dyadic<Int> upper_end(const DyadicRoot<Int>& r) {
  return r.exact ? r.start : piece_end(r.start);
}

/// Whether a lies certainly below b from their pieces alone.
template <class Int>
bool certainly_below(const DyadicRoot<Int>& a, const DyadicRoot<Int>& b) {
  const int c = compare(upper_end(a), b.start);
  return c < 0 || (c == 0 && !(a.exact && b.exact));
}

/// Whether the open piece of `root` holds a root of `common` (a divisor of the root's
/// square-free polynomial, so with at most that one root there, and simple).
template <class Int>
bool common_root_in_piece(const IntegerPolynomial<Int>& common, const Dyadic<Int>& lo, const Dyadic<Int>& hi) {
  return common.degree >= 1 && sign_at(common, lo) * sign_at(common, hi) < 0;
}

/// Pieces the isolation stack holds without growing: one per level of a cubic's usual
/// isolation depth (it grows past that, rarely).
constexpr std::size_t kIsolationStackReserve = 16;

/// Depth-first subdivision of [0, 1], left first, so roots come out in increasing order.
template <class Int>
struct IsolationStep {
  Bernstein<Int> b;
  Dyadic<Int> start;
  bool emit_exact_start = false;  ///< emit an exact root at `start` before this piece
  /// Splits in a row, just above this piece, that kept the same side (+: left, -: right)
  /// while the other half had no sign change: the roots crowd towards that end.
  int one_sided_run = 0;
};

/// How far below the piece's own depth a gallop looks (bits): beyond the doubling of the
/// depth that Newton would reach.
constexpr unsigned long kMaxGallopBits = 64;

/// One-sided splits in a row before isolation gallops towards that end: roots that close to
/// an end relative to the piece (coordinates of very different magnitudes) are common, but
/// an attempt costs a few bisections, and splits that alternate sides (a cluster inside the
/// piece) never make such a run.
constexpr int kIsolationGallopRun = 8;

/// Moves an isolation piece to its first (`left`) or last 2^-j part, for the largest j in
/// 2, 4, 8, ... such that the rest of the piece provably holds no root of q: q is non-zero
/// where the part ends and its Bernstein coefficients on the rest have no sign change
/// (Descartes). A root at the piece's outer end is found by whoever owns that end (as for
/// bisection). Returns false, changing nothing, when no such part exists.
template <class Int>
bool gallop_isolation(const IntegerPolynomial<Int>& q, bool left, IsolationStep<Int>& step) {
  const Dyadic<Int>& s = step.start;
  unsigned long best = 0;
  for (unsigned long j = 2; j <= s.k + kMaxGallopBits; j *= 2) {
    // The part's inner end, and the rest of the piece in units of 2^-(k + j).
    const Int scale = Int(1) << j;
    const Dyadic<Int> inner{left ? Int((s.a << j) + Int(1)) : Int((Int(s.a + Int(1)) << j) - Int(1)), s.k + j};
    if (sign_at(q, inner) == 0) break;
    const Dyadic<Int> rest_start = left ? inner : Dyadic<Int>{Int(s.a << j), s.k + j};
    if (sign_variations(bernstein_on_interval(q, rest_start, Int(scale - Int(1)))) != 0) break;
    best = j;
  }
  if (best == 0) return false;
  step.start = left ? Dyadic<Int>{Int(s.a << best), s.k + best}
                    : Dyadic<Int>{Int((Int(s.a + Int(1)) << best) - Int(1)), s.k + best};
  step.b = bernstein_on_piece(q, step.start);
  step.emit_exact_start = false;  // emitted when the piece was first taken
  return true;
}

}  // namespace

template <class Int>
DyadicRoot<Int> exact_root(const Dyadic<Int>& x) {
  DyadicRoot<Int> r;
  r.polynomial.c[0] = -x.a;
  r.polynomial.c[1] = Int(1) << x.k;
  r.polynomial.trim();
  r.start = x;
  r.exact = true;
  return r;
}

template <class Int>
std::vector<DyadicRoot<Int>> roots_in_unit_interval(const IntegerPolynomial<Int>& p) {
  std::vector<DyadicRoot<Int>> roots;
  if (p.degree <= 0) return roots;
  const IntegerPolynomial<Int> q = squarefree_part(p);
  const auto emit_exact = [&](const Dyadic<Int>& x) {
    DyadicRoot<Int> r;
    r.polynomial = q;
    r.start = x;
    r.exact = true;
    roots.push_back(std::move(r));
  };
  const Dyadic<Int> zero{0, 0};
  const Dyadic<Int> one{1, 0};
  if (sign_at(q, zero) == 0) emit_exact(zero);
  std::vector<IsolationStep<Int>> stack;
  stack.reserve(kIsolationStackReserve);
  stack.push_back({bernstein_on_piece(q, zero), zero, false});
  while (!stack.empty()) {
    IsolationStep<Int> step = std::move(stack.back());
    stack.pop_back();
    if (step.emit_exact_start) emit_exact(step.start);
    const int variations = sign_variations(step.b);
    if (variations == 0) continue;
    if (variations == 1 && sgn(step.b[0]) != 0 && sgn(step.b[kMaxDegree]) != 0) {
      DyadicRoot<Int> r;
      r.polynomial = q;
      r.start = step.start;
      r.sign_at_start = sgn(step.b[0]);
      r.on_piece = std::move(step.b);
      roots.push_back(std::move(r));
      continue;
    }
    if (std::abs(step.one_sided_run) >= kIsolationGallopRun) {
      const bool moved = gallop_isolation(q, step.one_sided_run > 0, step);
      step.one_sided_run = 0;  // the next attempt waits for another run
      if (moved) {
        stack.push_back(std::move(step));
        continue;
      }
    }
    IsolationStep<Int> left{{}, left_child(step.start), false};
    IsolationStep<Int> right{{}, right_child(step.start), false};
    split(step.b, left.b, right.b);
    right.emit_exact_start = sgn(left.b[kMaxDegree]) == 0;  // the midpoint is a root
    if (sign_variations(right.b) == 0) left.one_sided_run = std::max(step.one_sided_run, 0) + 1;
    if (sign_variations(left.b) == 0) right.one_sided_run = std::min(step.one_sided_run, 0) - 1;
    stack.push_back(std::move(right));
    stack.push_back(std::move(left));
  }
  if (sign_at(q, one) == 0) emit_exact(one);
  return roots;
}

namespace {

/// Halves the root's piece; `companion` (another polynomial on the same piece) follows it.
/// Returns the companion's sign at the root when the midpoint is the root, else 2.
template <class Int>
int bisect_with(DyadicRoot<Int>& root, Bernstein<Int>* companion) {
  // Scratch kept per thread (the halves are swapped in, so mpz_class limbs are reused).
  thread_local Bernstein<Int> left;
  thread_local Bernstein<Int> right;
  thread_local Bernstein<Int> companion_left;
  thread_local Bernstein<Int> companion_right;
  split(root.on_piece, left, right);
  if (companion) split(*companion, companion_left, companion_right);
  const int s = sgn(left[kMaxDegree]);  // the polynomial at the midpoint
  if (s == 0) {
    root.start = right_child(root.start);
    root.exact = true;
    return companion ? sgn(companion_left[kMaxDegree]) : 2;
  }
  const bool go_right = s == root.sign_at_start;
  root.start = go_right ? right_child(root.start) : left_child(root.start);
  std::swap(root.on_piece, go_right ? right : left);
  if (companion) std::swap(*companion, go_right ? companion_right : companion_left);
  return 2;
}

/// Bisections between Newton attempts while a sign stays undecided: bisection gains a bit
/// a step whatever happens; Newton doubles the bits once close enough, which is what
/// roots 2^-1000 apart (coordinates of very different magnitudes) need.
constexpr int kBisectionsPerNewtonStep = 16;
/// The fewest bits a Newton step aims for: the bisections between two attempts gain as many.
constexpr unsigned long kMinNewtonGain = static_cast<unsigned long>(kBisectionsPerNewtonStep);
/// Narrowings tried before the gcd that tests whether a sign is exactly zero: a non-zero
/// sign usually shows within a few (additions only), the gcd costs coefficient gcds.
constexpr int kNarrowingsBeforeZeroTest = 6;
/// One Newton step from the piece's midpoint to a grid `gain` bits finer (at most twice the
/// bits), kept only when the signs of the polynomial on both sides of the new estimate (one
/// unit of the finer grid away) prove the root is there. Returns false, changing nothing,
/// when they do not.
template <class Int>
bool newton_step(DyadicRoot<Int>& root, unsigned long gain) {
  const IntegerPolynomial<Int>& p = root.polynomial;
  const IntegerPolynomial<Int> slope = derivative(p);
  const Dyadic<Int> mid = right_child(root.start);
  const Int value = scaled_value(p, mid);            // p(x) 2^(k1 d)
  const Int slope_value = scaled_value(slope, mid);  // p'(x) 2^(k1 (d - 1))
  if (sgn(slope_value) == 0) return false;
  // x - p(x) / p'(x) on the grid 2^-fine: p / p' = value / (slope_value 2^k1).
  const unsigned long fine = mid.k + (gain == 0 ? mid.k : std::min(gain, mid.k));
  const Int step = Int(value << (fine - mid.k)) / slope_value;
  const Dyadic<Int> estimate{Int(mid.a << (fine - mid.k)) - step, fine};
  const Dyadic<Int> below{Int(estimate.a - Int(1)), fine};
  const Dyadic<Int> above{Int(estimate.a + Int(1)), fine};
  if (compare(below, root.start) < 0 || compare(above, piece_end(root.start)) > 0) return false;
  const int s_below = sign_at(p, below);
  const int s_estimate = sign_at(p, estimate);
  const int s_above = sign_at(p, above);
  // r is p's only root in the old piece, so any zero or sign change inside it is r.
  const Dyadic<Int>* zero = s_below == 0 ? &below : s_estimate == 0 ? &estimate : s_above == 0 ? &above : nullptr;
  if (zero) {
    root.start = *zero;
    root.exact = true;
    return true;
  }
  if (s_below != s_estimate) {
    root.start = below;
    root.sign_at_start = s_below;
  } else if (s_estimate != s_above) {
    root.start = estimate;
    root.sign_at_start = s_estimate;
  } else {
    return false;
  }
  root.on_piece = bernstein_on_piece(p, root.start);
  return true;
}

/// Moves the root's piece to its first or last 2^-j part, for the largest j in 2, 4, 8, ...
/// that still holds the root (the signs at the part's inner end prove it). A root far
/// closer to an end of its piece than the piece is wide (coordinates of very different
/// magnitudes) is reached in a few doublings of j, where bisection would take one step per
/// bit and Newton, from the middle of a piece where a higher power of t dominates, gains
/// only a bit per step as well. Returns false, changing nothing, when no part holds it.
template <class Int>
bool gallop_to_end(DyadicRoot<Int>& root) {
  const IntegerPolynomial<Int>& p = root.polynomial;
  for (const bool left : {true, false}) {
    unsigned long best = 0;
    for (unsigned long j = 2; j <= root.start.k + kMaxGallopBits; j *= 2) {
      // The inner end of the part: start + 2^-(k + j) or end - 2^-(k + j).
      const Dyadic<Int> inner{
          left ? Int((root.start.a << j) + Int(1)) : Int((Int(root.start.a + Int(1)) << j) - Int(1)), root.start.k + j};
      const int s = sign_at(p, inner);
      if (s == 0) {
        root.start = inner;
        root.exact = true;
        return true;
      }
      // The root is inside the part when the sign changes across it.
      if ((s != root.sign_at_start) != left) break;
      best = j;
    }
    if (best == 0) continue;
    root.start = left ? Dyadic<Int>{Int(root.start.a << best), root.start.k + best}
                      : Dyadic<Int>{Int((Int(root.start.a + Int(1)) << best) - Int(1)), root.start.k + best};
    // The left part keeps the old start; the right part starts where the sign was checked.
    root.on_piece = bernstein_on_piece(p, root.start);
    return true;
  }
  return false;
}

/// A Newton step with the root's current gain, which it then adapts.
template <class Int>
bool newton_step_adapting(DyadicRoot<Int>& root) {
  const unsigned long gain = root.newton_gain == 0 ? root.start.k + 1 : root.newton_gain;
  if (newton_step(root, gain)) {
    root.newton_gain = 2 * gain;
    return true;
  }
  root.newton_gain = std::max(kMinNewtonGain, gain / 2);
  return false;
}

/// Narrows the root's piece: a bisection, or every few steps a Newton step (or, where that
/// fails, a gallop to an end of the piece). `companion` (another polynomial's coefficients
/// on the piece) follows. Returns the companion's sign at the root when the root turns out
/// exact, else 2.
template <class Int>
int narrow(DyadicRoot<Int>& root, int& steps, const IntegerPolynomial<Int>* companion_polynomial,
           Bernstein<Int>* companion) {
  if (++steps % kBisectionsPerNewtonStep == 0 && (newton_step_adapting(root) || gallop_to_end(root))) {
    if (root.exact) return companion ? sign_at(*companion_polynomial, root.start) : 2;
    if (companion) *companion = bernstein_on_piece(*companion_polynomial, root.start);
    return 2;
  }
  return bisect_with(root, companion);
}

}  // namespace

template <class Int>
void bisect(DyadicRoot<Int>& root) {
  if (!root.exact) bisect_with<Int>(root, nullptr);
}

template <class Int>
int sign_at_root(const IntegerPolynomial<Int>& g, DyadicRoot<Int>& root) {
  if (g.is_zero()) return 0;
  if (root.exact) return sign_at(g, root.start);
  Bernstein<Int> g_on_piece = bernstein_on_piece(g, root.start);
  bool zero_excluded = false;
  int steps = 0;
  while (true) {
    const int s = uniform_sign(g_on_piece);
    if (s != 0) return s;
    if (!zero_excluded && steps >= kNarrowingsBeforeZeroTest) {
      // g may vanish at the root: exactly when it shares a factor with the root's
      // polynomial that vanishes in the piece. Otherwise narrowing ends with one sign.
      if (common_root_in_piece(gcd(root.polynomial, g), root.start, piece_end(root.start))) return 0;
      zero_excluded = true;
    }
    const int at_root = narrow(root, steps, &g, &g_on_piece);
    if (at_root != 2) return at_root;
  }
}

template <class Int>
int compare(DyadicRoot<Int>& a, DyadicRoot<Int>& b) {
  bool equality_excluded = false;
  int a_steps = 0;
  int b_steps = 0;
  while (true) {
    if (certainly_below(a, b)) return -1;
    if (certainly_below(b, a)) return 1;
    if (a.exact && b.exact) return 0;  // neither below the other: the same point
    if (a.exact) {
      // a lies in b's open piece: equal iff a is a root of b's polynomial there.
      if (sign_at(b.polynomial, a.start) == 0) return 0;
      narrow<Int>(b, b_steps, nullptr, nullptr);
      continue;
    }
    if (b.exact) {
      if (sign_at(a.polynomial, b.start) == 0) return 0;
      narrow<Int>(a, a_steps, nullptr, nullptr);
      continue;
    }
    if (!equality_excluded) {
      const Dyadic<Int>& lo = compare(a.start, b.start) >= 0 ? a.start : b.start;
      const Dyadic<Int> a_end = piece_end(a.start);
      const Dyadic<Int> b_end = piece_end(b.start);
      const Dyadic<Int>& hi = compare(a_end, b_end) <= 0 ? a_end : b_end;
      if (common_root_in_piece(gcd(a.polynomial, b.polynomial), lo, hi)) return 0;
      equality_excluded = true;
    }
    // The wider piece first: narrowing the other would not separate them any sooner.
    if (a.start.k <= b.start.k) narrow<Int>(a, a_steps, nullptr, nullptr);
    if (b.start.k <= a.start.k) narrow<Int>(b, b_steps, nullptr, nullptr);
  }
}

template <class Int>
double lower_bound_within(DyadicRoot<Int>& root, double width) {
  // Pieces of width 2^-k <= width / 2 leave room for the rounding of the start below.
  int exponent = 0;
  std::frexp(width, &exponent);  // width in [2^(exponent-1), 2^exponent)
  const unsigned long k_needed = static_cast<unsigned long>(std::max(0, 2 - exponent));
  while (!root.exact && root.start.k < k_needed) bisect(root);
  if (sgn(root.start.a) == 0) return 0.0;
  long a_exponent = 0;
  const double mantissa = get_d_2exp(a_exponent, root.start.a);  // truncated
  const long exponent_of_start = a_exponent - static_cast<long>(root.start.k);
  // Below the normal range ldexp would round; such a time is within any width of 0.
  if (exponent_of_start <= DBL_MIN_EXP) return 0.0;
  return std::ldexp(mantissa, static_cast<int>(exponent_of_start));
}

#define SSCC_INSTANTIATE_DYADIC_ROOT(Int)                                                      \
  template std::vector<DyadicRoot<Int>> roots_in_unit_interval(const IntegerPolynomial<Int>&); \
  template DyadicRoot<Int> exact_root(const Dyadic<Int>&);                                     \
  template void bisect(DyadicRoot<Int>&);                                                      \
  template int sign_at_root(const IntegerPolynomial<Int>&, DyadicRoot<Int>&);                  \
  template int compare(DyadicRoot<Int>&, DyadicRoot<Int>&);                                    \
  template double lower_bound_within(DyadicRoot<Int>&, double);

SSCC_INSTANTIATE_DYADIC_ROOT(FixedInt)
SSCC_INSTANTIATE_DYADIC_ROOT(mpz_class)

}  // namespace sscc::ccd::exact_stage
