#include "filter/coplanar_filter.hpp"

#include "filter/bernstein.hpp"

namespace sscc::ccd::filter {

namespace {

using BVec3 = std::array<Bounded, 3>;

constexpr int kMaxDepth = 20;
static_assert(kMinDecisionPieceWidth == 1.0 / (1 << kMaxDepth), "depth and width agree");

BVec3 difference(const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
  BVec3 d;
  for (int k = 0; k < 3; ++k) d[k] = Bounded::exact(x[k]) - Bounded::exact(y[k]);
  return d;
}

BVec3 cross(const BVec3& a, const BVec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Bounded dot(const BVec3& a, const BVec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// x(t) x y(t) for x, y moving linearly: its Bernstein coefficients per component are
/// x0 x y0, (x0 x y1 + x1 x y0) / 2 and x1 x y1 (the blossom of a bilinear form).
struct CrossProductMotion {
  BVec3 at00, at01, at10, at11;

  CrossProductMotion(const BVec3& x0, const BVec3& x1, const BVec3& y0, const BVec3& y1)
      : at00(cross(x0, y0)), at01(cross(x0, y1)), at10(cross(x1, y0)), at11(cross(x1, y1)) {}

  Quadratic component(int k) const {
    return {{at00[k], scaled(at01[k] + at10[k], 0.5), at11[k]}};
  }
};

struct Piece {
  double t0 = 0.0;
  double t1 = 1.0;
  Cubic coplanarity;
  std::array<std::array<Quadratic, 4>, 3> orientation;  // [dropped axis][orientation]
};

void split(const Piece& piece, int orientations, Piece& left, Piece& right) {
  const double mid = 0.5 * (piece.t0 + piece.t1);
  left.t0 = piece.t0;
  left.t1 = mid;
  right.t0 = mid;
  right.t1 = piece.t1;
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
Verdict classify_inside(PrimitivePair pair, const Piece& piece) {
  const int count = orientation_count(pair);
  Verdict verdict = Verdict::kUndecided;
  for (int k = 0; k < 3; ++k) {
    int signs[4] = {0, 0, 0, 0};
    for (int i = 0; i < count; ++i) signs[i] = piece.orientation[k][i].certain_sign_on_piece();
    const Verdict plane = classify_plane(pair, signs);
    if (plane == Verdict::kNoContact) return plane;
    if (plane == Verdict::kContact) verdict = plane;
  }
  return verdict;
}

bool certainly_changes_sign(const Cubic& f) { return f.sign_at_start() * f.sign_at_end() < 0; }

/// Narrows a piece on which every root is a contact and the cubic changes sign down to the
/// earliest root. Returns false when a sign is too close to call.
bool refine_first_root(Cubic f, double t0, double t1, double tolerance, double& toi) {
  while (t1 - t0 > tolerance) {
    Cubic left;
    Cubic right;
    f.split(left, right);
    const double mid = 0.5 * (t0 + t1);
    if (left.certain_sign_on_piece() != 0) {
      f = right;
      t0 = mid;
    } else if (certainly_changes_sign(left)) {
      f = left;
      t1 = mid;
    } else {
      return false;
    }
  }
  toi = t0;
  return true;
}

Piece initial_piece(const FourPointMotion& motion, const BVec3 (&e)[3][2],
                    const CrossProductMotion& k23) {
  const CrossProductMotion k12(e[0][0], e[0][1], e[1][0], e[1][1]);
  const CrossProductMotion k13(e[0][0], e[0][1], e[2][0], e[2][1]);
  Piece piece;
  for (int k = 0; k < 3; ++k) {
    const Quadratic q12 = k12.component(k);
    const Quadratic q13 = k13.component(k);
    const Quadratic q23 = k23.component(k);
    const Quadratic mixed = q12 + q23 - q13;
    auto& o = piece.orientation[k];
    if (motion.pair == PrimitivePair::kVertexFace) {
      o = {q13, mixed, -q23, Quadratic{}};
    } else {
      o = {q12, q13, q23, mixed};
    }
  }
  return piece;
}

}  // namespace

FilterOutcome run_coplanar_filter(const FourPointMotion& motion, double toi_tolerance) {
  // e[i][j]: e_{i+1} at time j.
  BVec3 e[3][2];
  for (int i = 0; i < 3; ++i) {
    e[i][0] = difference(motion.t0[i + 1], motion.t0[0]);
    e[i][1] = difference(motion.t1[i + 1], motion.t1[0]);
  }
  const CrossProductMotion k23(e[1][0], e[1][1], e[2][0], e[2][1]);
  BVec3 mixed23;
  for (int k = 0; k < 3; ++k) mixed23[k] = k23.at01[k] + k23.at10[k];
  // det(e1, e2, e3) = e1 . (e2 x e3): trilinear, so its blossom gives the Bernstein form.
  Cubic coplanarity{{dot(e[0][0], k23.at00),
                     divided(dot(e[0][1], k23.at00) + dot(e[0][0], mixed23), 3.0),
                     divided(dot(e[0][0], k23.at11) + dot(e[0][1], mixed23), 3.0),
                     dot(e[0][1], k23.at11)}};
  if (coplanarity.certain_sign_on_piece() != 0) {
    return {Verdict::kNoContact, DecidedBy::kCoplanaritySign};
  }

  Piece root = initial_piece(motion, e, k23);
  root.coplanarity = coplanarity;
  const int orientations = orientation_count(motion.pair);
  // Depth-first, left half first, so pieces are met in increasing t. Each bisection
  // replaces one piece by two, and pieces stop at kMinDecisionPieceWidth, so the stack
  // never holds more than one piece per level plus one.
  std::array<Piece, kMaxDepth + 2> stack;
  int size = 0;
  stack[size++] = root;
  while (size > 0) {
    const Piece piece = stack[--size];
    if (piece.coplanarity.certain_sign_on_piece() != 0) continue;
    const Verdict inside = classify_inside(motion.pair, piece);
    if (inside == Verdict::kNoContact) continue;
    if (inside == Verdict::kContact && certainly_changes_sign(piece.coplanarity)) {
      FilterOutcome outcome{Verdict::kContact, DecidedBy::kIntervalFilter};
      if (!refine_first_root(piece.coplanarity, piece.t0, piece.t1, toi_tolerance,
                             outcome.toi)) {
        return {};
      }
      return outcome;
    }
    if (piece.t1 - piece.t0 <= kMinDecisionPieceWidth) return {};
    Piece left;
    Piece right;
    split(piece, orientations, left, right);
    stack[size++] = right;
    stack[size++] = left;
  }
  return {Verdict::kNoContact, DecidedBy::kIntervalFilter};
}

}  // namespace sscc::ccd::filter
