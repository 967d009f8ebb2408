#include "filter/coplanar_filter.hpp"

#include <algorithm>
#include <cmath>

#include "filter/bernstein.hpp"

namespace sscc::ccd::filter {

// Error bounds (semi-static, as in classic filtered predicates). u = 2^-53. Inputs are
// doubles of magnitude <= kFilterMaxMagnitude, so nothing below overflows. The computed
// edge vectors e~ = fl(x_i - x_0) differ from the exact ones by at most u |e|; M_i is the
// largest |component| of e~_i at t = 0 and t = 1, and every exact component is at most
// M_i (1 + 2u). Bounds per computed quantity (first order in u, each rounded up):
// - a cross-product component x_j y_k - x_k y_j: 4u M_x M_y from its three roundings,
//   4u M_x M_y from the inexact inputs, so 8.1u M_x M_y; the middle Bernstein coefficient
//   (c01 + c10) / 2 adds one rounding of a value <= 2 M_x M_y: 10.1u M_x M_y. Magnitudes
//   <= 2 M_x M_y.
// - an orientation (K12 + K23 - K13, or one K): with S = M1 M2 + M1 M3 + M2 M3, at most
//   10.1u S + two roundings of values <= 2 S: 14.2u S; magnitudes <= 2 S.
// - the cubic's Bernstein coefficients e1 . (e2 x e3) (with the mixed cross products summed
//   and divided by 3): at most 65u P with P = M1 M2 M3; magnitudes <= 6 P.
// - a bisection (de Casteljau at 1/2) averages coefficients (errors do not grow) and
//   rounds each new one once per level: + Degree u (coefficient magnitude) per depth.
//   A split at an arbitrary point (1 - tau rounds) adds up to 4u per level: it counts as 4
//   bisections.
//   At bisection depth d: orientations 14.2u S + 4d u S, taken as (16 + 4d) u S; the cubic
//   65u P + 18d u P, taken as (72 + 20d) u P. Depth stays below 64 (pieces are dyadic, no
//   narrower than kMinToiTolerance), so nothing is evaluated outside that range.
// Underflow adds at most 2^-1075 per operation. An orientation is a sum of products of two
// inputs, so a few thousand such errors stay far below kUnderflowAllowance. The cubic
// multiplies cross products (whose products may underflow) by components of e1, which can
// be huge while e2, e3 are tiny: its allowance is scaled by 1 + M1 + M2 + M3.
// - certainly_monotone compares differences of neighbouring cubic coefficients: each has
//   twice the coefficients' error plus its own rounding (u 12 P), which the slack between
//   the derived 62.3u P and the 72u P used covers.

namespace {

constexpr int kMaxDepth = 20;
static_assert(kMinDecisionPieceWidth == 1.0 / (1 << kMaxDepth), "depth and width agree");
constexpr double kUnitRoundoff = 0x1p-53;
constexpr double kUnderflowAllowance = 1e-290;

/// Error bounds of the cubic's and the orientations' Bernstein coefficients at each
/// bisection depth (see the derivation above).
class ErrorBounds {
 public:
  ErrorBounds(double m1, double m2, double m3)
      : cubic_unit_(kUnitRoundoff * (m1 * m2 * m3)),
        orientation_unit_(kUnitRoundoff * (m1 * m2 + m1 * m3 + m2 * m3)),
        cubic_underflow_(kUnderflowAllowance * (1.0 + m1 + m2 + m3)) {}
  double cubic(int depth) const { return (72.0 + 20.0 * depth) * cubic_unit_ + cubic_underflow_; }
  double orientation(int depth) const { return (16.0 + 4.0 * depth) * orientation_unit_ + kUnderflowAllowance; }

 private:
  double cubic_unit_;
  double orientation_unit_;
  double cubic_underflow_;
};

using Vec3 = std::array<double, 3>;

Vec3 difference(const Eigen::Vector3d& x, const Eigen::Vector3d& y) { return {x[0] - y[0], x[1] - y[1], x[2] - y[2]}; }

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Vec3 difference3(const Vec3& x, const Vec3& y) { return {x[0] - y[0], x[1] - y[1], x[2] - y[2]}; }

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

double max_abs(const Vec3& a, const Vec3& b) {
  double m = 0.0;
  for (int k = 0; k < 3; ++k) m = std::max(m, std::max(std::fabs(a[k]), std::fabs(b[k])));
  return m;
}

/// x(t) x y(t) for x, y moving linearly: its Bernstein coefficients per component are
/// x0 x y0, (x0 x y1 + x1 x y0) / 2 and x1 x y1 (the blossom of a bilinear form).
/// Components are computed on demand.
struct CrossProductMotion {
  const Vec3 &x0, &x1, &y0, &y1;

  static double component(const Vec3& a, const Vec3& b, int k) {
    const int i = (k + 1) % 3;
    const int j = (k + 2) % 3;
    return a[i] * b[j] - a[j] * b[i];
  }
  Quadratic component(int k) const {
    return {{component(x0, y0, k), 0.5 * (component(x0, y1, k) + component(x1, y0, k)), component(x1, y1, k)}};
  }
};

Quadratic operator+(const Quadratic& a, const Quadratic& b) {
  return {{a.b[0] + b.b[0], a.b[1] + b.b[1], a.b[2] + b.b[2]}};
}
Quadratic operator-(const Quadratic& a, const Quadratic& b) {
  return {{a.b[0] - b.b[0], a.b[1] - b.b[1], a.b[2] - b.b[2]}};
}
Quadratic operator-(const Quadratic& a) { return {{-a.b[0], -a.b[1], -a.b[2]}}; }

struct Piece {
  double t0 = 0.0;
  double t1 = 1.0;
  int depth = 0;
  Cubic coplanarity;
  std::array<std::array<Quadratic, 4>, 3> orientation;  // [dropped axis][orientation]
};

void split(const Piece& piece, int orientations, Piece& left, Piece& right) {
  const double mid = 0.5 * (piece.t0 + piece.t1);
  left.t0 = piece.t0;
  left.t1 = mid;
  right.t0 = mid;
  right.t1 = piece.t1;
  left.depth = right.depth = piece.depth + 1;
  piece.coplanarity.split(left.coplanarity, right.coplanarity);
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < orientations; ++i) {
      piece.orientation[k][i].split(left.orientation[k][i], right.orientation[k][i]);
    }
  }
}

/// Verdict of one coordinate plane from the certain signs of its orientations.
Verdict classify_plane(PrimitivePair pair, const int* s) {
  if (pair == PrimitivePair::kVertexFace) {
    const bool has_positive = s[0] > 0 || s[1] > 0 || s[2] > 0;
    const bool has_negative = s[0] < 0 || s[1] < 0 || s[2] < 0;
    if (has_positive && has_negative) return Verdict::kNoContact;
    if (s[0] != 0 && s[0] == s[1] && s[1] == s[2]) return Verdict::kContact;
    return Verdict::kUndecided;
  }
  // Edge-edge: b0 and b1 strictly on one side of line a (or a0, a1 of line b) separates
  // the projected segments; strict straddling both ways makes them cross.
  if (s[0] * s[1] > 0 || s[2] * s[3] > 0) return Verdict::kNoContact;
  if (s[0] * s[1] < 0 && s[2] * s[3] < 0) return Verdict::kContact;
  return Verdict::kUndecided;
}

/// Verdict on the roots of the cubic inside the piece, from the inside test alone.
Verdict classify_inside(PrimitivePair pair, const Piece& piece, double error) {
  const int count = orientation_count(pair);
  Verdict verdict = Verdict::kUndecided;
  for (int k = 0; k < 3; ++k) {
    int signs[4] = {0, 0, 0, 0};
    for (int i = 0; i < count; ++i) signs[i] = piece.orientation[k][i].certain_sign_on_piece(error);
    const Verdict plane = classify_plane(pair, signs);
    if (plane == Verdict::kNoContact) return plane;
    if (plane == Verdict::kContact) verdict = plane;
  }
  return verdict;
}

bool certainly_changes_sign(const Cubic& f, double error) { return f.sign_at_start(error) * f.sign_at_end(error) < 0; }

/// An approximation of a root of a cubic that changes sign on [0, 1] (safeguarded Newton
/// in the monomial basis); only a guess, certified by the caller.
double guess_root(const Cubic& f) {
  const auto& b = f.b;
  const double c[4] = {b[0], 3.0 * (b[1] - b[0]), 3.0 * (b[0] - 2.0 * b[1] + b[2]),
                       b[3] - 3.0 * b[2] + 3.0 * b[1] - b[0]};
  double lo = 0.0;
  double hi = 1.0;
  const bool rising = b[3] > b[0];
  double x = b[0] / (b[0] - b[3]);  // regula falsi
  for (int iteration = 0; iteration < 12; ++iteration) {
    const double fx = ((c[3] * x + c[2]) * x + c[1]) * x + c[0];
    ((fx < 0.0) == rising ? lo : hi) = x;
    const double slope = (3.0 * c[3] * x + 2.0 * c[2]) * x + c[1];
    double next = slope != 0.0 ? x - fx / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - x) <= 1e-14) return next;
    x = next;
  }
  return x;
}

/// Whether the cubic is certainly monotone on its piece: the derivative's Bernstein
/// coefficients, 3 (b[i+1] - b[i]), have one certain sign (each difference carries twice
/// the coefficients' error).
bool certainly_monotone(const Cubic& f, double error) {
  const int s = certain_sign(f.b[1] - f.b[0], 2.0 * error);
  return s != 0 && certain_sign(f.b[2] - f.b[1], 2.0 * error) == s && certain_sign(f.b[3] - f.b[2], 2.0 * error) == s;
}

/// Narrows a piece on which every root is a contact and the cubic changes sign down to the
/// earliest root, by bisection; once the cubic is monotone on the piece its one root is
/// guessed and certified by the signs on both sides of a tolerance-wide band around it.
/// Returns false when a sign is too close to call.
bool refine_first_root(Cubic f, double t0, double t1, int depth, double tolerance, const ErrorBounds& bounds,
                       double& toi) {
  while (t1 - t0 > tolerance) {
    if (certainly_monotone(f, bounds.cubic(depth))) {
      const double width = t1 - t0;
      const double guess = guess_root(f);
      // The band [before, after] and the roundings of toi below stay inside the tolerance.
      const double half_band = (0.5 * tolerance - 0x1p-50) / width;
      const double before = std::max(0.0, guess - half_band);
      const double after = std::min(1.0, guess + half_band);
      const double error = bounds.cubic(depth + 4);
      if (certain_sign(f.value_at(before), error) * certain_sign(f.value_at(after), error) < 0) {
        // t0 + before * width, rounded down by more than its two roundings.
        toi = std::max(t0, t0 + before * width - 0x1p-51);
        return true;
      }
    }
    Cubic left;
    Cubic right;
    f.split(left, right);
    const double mid = 0.5 * (t0 + t1);
    const double error = bounds.cubic(++depth);
    if (left.certain_sign_on_piece(error) != 0) {
      f = right;
      t0 = mid;
    } else if (certainly_changes_sign(left, error)) {
      f = left;
      t1 = mid;
    } else {
      return false;
    }
  }
  toi = t0;
  return true;
}

/// The 2D orientations of the coordinate plane that drops axis k (four_point_motion.hpp).
/// q23 is e2 x e3's component k, which the cubic has already computed.
void set_plane(PrimitivePair pair, const Vec3 (&e)[3][2], int k, const Quadratic& q23, Piece& piece) {
  const Quadratic q12 = CrossProductMotion{e[0][0], e[0][1], e[1][0], e[1][1]}.component(k);
  const Quadratic q13 = CrossProductMotion{e[0][0], e[0][1], e[2][0], e[2][1]}.component(k);
  const Quadratic mixed = q12 + q23 - q13;
  auto& o = piece.orientation[k];
  if (pair == PrimitivePair::kVertexFace) {
    o = {q13, mixed, -q23, Quadratic{}};
  } else {
    o = {q12, q13, q23, mixed};
  }
}

/// Planes in the order most likely to decide: the one facing the primitives' common
/// normal at t = 0 first (the triangle's normal, or edge a x edge b).
std::array<int, 3> plane_order(PrimitivePair pair, const Vec3 (&e)[3][2]) {
  const Vec3 normal =
      pair == PrimitivePair::kVertexFace ? cross(e[0][0], e[1][0]) : cross(e[0][0], difference3(e[2][0], e[1][0]));
  std::array<int, 3> order = {0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int a, int b) { return std::fabs(normal[a]) > std::fabs(normal[b]); });
  return order;
}

}  // namespace

FilterOutcome run_coplanar_filter(const FourPointMotion& motion, double toi_tolerance) {
  // e[i][j]: e_{i+1} at time j.
  Vec3 e[3][2];
  double m[3];
  for (int i = 0; i < 3; ++i) {
    e[i][0] = difference(motion.t0[i + 1], motion.t0[0]);
    e[i][1] = difference(motion.t1[i + 1], motion.t1[0]);
    m[i] = max_abs(e[i][0], e[i][1]);
  }
  const ErrorBounds bounds(m[0], m[1], m[2]);

  // det(e1, e2, e3) = e1 . (e2 x e3): trilinear, so its blossom gives the Bernstein form.
  const Vec3 k23_00 = cross(e[1][0], e[2][0]);
  const Vec3 k23_11 = cross(e[1][1], e[2][1]);
  const Vec3 k23_01 = cross(e[1][0], e[2][1]);
  const Vec3 k23_10 = cross(e[1][1], e[2][0]);
  const Vec3 mixed23 = {k23_01[0] + k23_10[0], k23_01[1] + k23_10[1], k23_01[2] + k23_10[2]};
  Piece root;
  root.coplanarity = {{dot(e[0][0], k23_00), (dot(e[0][1], k23_00) + dot(e[0][0], mixed23)) / 3.0,
                       (dot(e[0][0], k23_11) + dot(e[0][1], mixed23)) / 3.0, dot(e[0][1], k23_11)}};
  if (root.coplanarity.certain_sign_on_piece(bounds.cubic(0)) != 0) {
    return {Verdict::kNoContact, DecidedBy::kCoplanaritySign};
  }
  // One plane that excludes contact over all of [0, 1] settles the query: fill the
  // planes one at a time at first.
  const int orientation_signs = orientation_count(motion.pair);
  const double root_error = bounds.orientation(0);
  for (int k : plane_order(motion.pair, e)) {
    set_plane(motion.pair, e, k, {{k23_00[k], 0.5 * mixed23[k], k23_11[k]}}, root);
    int signs[4] = {0, 0, 0, 0};
    for (int i = 0; i < orientation_signs; ++i) {
      signs[i] = root.orientation[k][i].certain_sign_on_piece(root_error);
    }
    if (classify_plane(motion.pair, signs) == Verdict::kNoContact) {
      return {Verdict::kNoContact, DecidedBy::kIntervalFilter};
    }
  }

  const int orientations = orientation_signs;
  // Depth-first, left half first, so pieces are met in increasing t. Each bisection
  // replaces one piece by two, and pieces stop at kMinDecisionPieceWidth, so the stack
  // never holds more than one piece per level plus one.
  std::array<Piece, kMaxDepth + 2> stack;
  int size = 0;
  stack[size++] = root;
  while (size > 0) {
    const Piece& piece = stack[size - 1];
    const double cubic_error = bounds.cubic(piece.depth);
    if (piece.coplanarity.certain_sign_on_piece(cubic_error) != 0) {
      --size;
      continue;
    }
    const Verdict inside = classify_inside(motion.pair, piece, bounds.orientation(piece.depth));
    if (inside == Verdict::kNoContact) {
      --size;
      continue;
    }
    if (inside == Verdict::kContact && certainly_changes_sign(piece.coplanarity, cubic_error)) {
      FilterOutcome outcome{Verdict::kContact, DecidedBy::kIntervalFilter};
      if (!refine_first_root(piece.coplanarity, piece.t0, piece.t1, piece.depth, toi_tolerance, bounds, outcome.toi)) {
        return {};
      }
      return outcome;
    }
    if (piece.t1 - piece.t0 <= kMinDecisionPieceWidth) return {};
    // The right half takes the parent's slot and the left half goes on top.
    const Piece parent = piece;
    split(parent, orientations, stack[size], stack[size - 1]);
    ++size;
  }
  return {Verdict::kNoContact, DecidedBy::kIntervalFilter};
}

}  // namespace sscc::ccd::filter
