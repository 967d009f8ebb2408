#include "sscc/certificates/triangle_pair_bound.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "common/avx2_clone.hpp"
#include "common/scaled_norm.hpp"
#include "sscc/geometry/triangle_distance.hpp"

namespace sscc {

namespace {

using ModeBlock = Eigen::Matrix<double, 3, Eigen::Dynamic>;
using Weights6 = Eigen::Matrix<double, 6, 1>;

// Added, times the trace, to the Gram matrices of mode combinations, with the Gram pad:
// errs the dual bound's denominator upwards (so the bound downwards) by more than the
// rounding of v^T G v. Larger values only weaken the bounds.
constexpr double kEigenvaluePad = 1e-12;
// Gram matrices of combinations of the six vertex blocks are formed from their pairwise
// products; the absolute rounding of a combination with coefficients c is below
// gram_rounding_pad(r) * (sum |c_i|)^2 * (largest block Gram trace), added as a further pad.
// Smallest eigenvalue of the constant-mode Gram matrix used in its map, relative to the
// largest. Only conditions the choice of multiplier: not a soundness matter.
constexpr double kMapConditioning = 1e-12;
// Allowance, relative to the extent of the pair (its rest positions are taken relative to
// its first vertex), subtracted from the dual bound's numerator v^T (Xa - Xb) (v of unit
// length): covers the rounding of that translation, of the pieces' corners and of the dot
// product, a few units of roundoff each. Units: length. Larger only weakens pairs closer
// than this fraction of their size.
constexpr double kDistanceAllowance = 1e-12;
// Relative shrink of the 1D bound covering the rounding of its sums over r columns, the
// square root and the division (the absolute errors of the gaps and rates are padded where
// they arise). Covers r up to about 10^6 modes.
constexpr double kOneDimensionalShrink = 1.0 - 1e-9;

/// How far the positions a query computes, p + U_hat q_hat in floating point, can lie from
/// the exact ones at a vertex of the pair (2-norm): absolute + per_norm ||q_hat||. Each
/// coordinate is an (r + 1)-term sum, rounded by at most gamma_{r+1} times the sum of its
/// terms' magnitudes, itself at most |p_k| + ||U_hat_k||_2 ||q_hat|| (Cauchy-Schwarz); three
/// coordinates add sqrt(3), and (r + 2) epsilon covers sqrt(3) gamma_{r+1}. A contact of the
/// computed positions needs the exact ones within twice this of each other, so the bounds
/// subtract 2 absolute from every gap and add 2 per_norm to every rate: contacts that exist
/// only through rounding (far from the origin, where a unit of roundoff is large) stay
/// outside the certificates.
struct PositionRounding {
  double absolute = 0.0;
  double per_norm = 0.0;
};

PositionRounding rounding_of_positions(const TriangleSummary& a, const TriangleSummary& b, Eigen::Index modes) {
#ifdef SSCC_MUTANT_NO_POSITION_ROUNDING
  return {};
#endif
  const double c = (static_cast<double>(modes) + 2.0) * std::numeric_limits<double>::epsilon();
  return {c * std::max(a.largest_coordinate, b.largest_coordinate),
          c * std::max(a.largest_row_norm, b.largest_row_norm)};
}

/// The summary's largest coordinate, row and block of t: all the 1D bound reads of it
/// without a cut, and all the position rounding needs.
TriangleSummary scales_of(const ModalTriangle& t) {
  TriangleSummary s;
  for (int i = 0; i < 3; ++i) {
    s.largest_coordinate = std::max(s.largest_coordinate, t.rest[i].cwiseAbs().maxCoeff());
    s.largest_row_norm = std::max(s.largest_row_norm, t.modes[i].rowwise().norm().maxCoeff());
    s.largest_block_norm = std::max(s.largest_block_norm, t.modes[i].norm());
  }
  return s;
}

PositionRounding rounding_of_positions(const ModalTriangle& a, const ModalTriangle& b) {
  return rounding_of_positions(scales_of(a), scales_of(b), a.modes[0].cols());
}

/// The two triangles of a pair, reduced to what the bounds need: the six rest vertices and
/// the Gram matrix of the six 3 x r vertex mode blocks (centred on their mean, which every
/// combination used here cancels: their coefficients sum to zero). Every mode block of a
/// point of either triangle is a combination of the six, so the refinement below never
/// touches r-dimensional data.
class PairFrame {
 public:
  PairFrame(const ModalTriangle& a, const ModalTriangle& b) : position_rounding_(rounding_of_positions(a, b)) {
    const int r = static_cast<int>(a.modes[0].cols());
    ModeBlock mean = ModeBlock::Zero(3, r);
    for (int i = 0; i < 3; ++i) mean += (a.modes[i] + b.modes[i]) / 6.0;
    Eigen::Matrix<double, 18, Eigen::Dynamic> stacked(18, r);
    for (int i = 0; i < 3; ++i) {
      stacked.middleRows<3>(3 * i) = a.modes[i] - mean;
      stacked.middleRows<3>(9 + 3 * i) = b.modes[i] - mean;
      rest_[i] = a.rest[i] - a.rest[0];
      rest_[3 + i] = b.rest[i] - a.rest[0];
    }
    // Symmetric: each entry below the diagonal is its mirror's sum, the same products in the
    // same order (from +0, column by column, as Eigen's coefficient-wise product sums them).
    for (int j = 0; j < 18; ++j) {
      for (int i = 0; i <= j; ++i) gram_(i, j) = 0.0;
      for (int k = 0; k < r; ++k) {
        for (int i = 0; i <= j; ++i) gram_(i, j) += stacked(i, k) * stacked(j, k);
      }
      for (int i = 0; i < j; ++i) gram_(j, i) = gram_(i, j);
    }
    double largest = 0.0;
    for (int i = 0; i < 6; ++i) largest = std::max(largest, gram_.block<3, 3>(3 * i, 3 * i).trace());
    rounding_ = gram_rounding_pad(r) * largest;
    for (const Eigen::Vector3d& p : rest_) extent_ = std::max(extent_, p.cwiseAbs().maxCoeff());
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) traces_(i, j) = gram_.block<3, 3>(3 * i, 3 * j).trace();
    }
  }

  /// The quadratic forms u^T W_ij u of the block Gram matrix for a unit direction u: then
  /// ||(sum_i c_i U_i)^T u||^2 = c^T F c.
  Eigen::Matrix<double, 6, 6> projected(const Eigen::Vector3d& u) const {
    Eigen::Matrix<double, 6, 6> f;
    for (int i = 0; i < 6; ++i) {
      for (int j = i; j < 6; ++j) f(i, j) = f(j, i) = u.dot(gram_.block<3, 3>(3 * i, 3 * j) * u);
    }
    return f;
  }

  /// The pads of projected_norm_squared_upper for combination c, which do not depend on the
  /// direction: computed once for the directions a piece pair is tried in.
  struct ProjectionPads {
    double rounding;
    double eigenvalue;
  };
  ProjectionPads projection_pads(const Weights6& c) const {
    const double spread = c.cwiseAbs().sum();
    return {rounding_ * spread * spread, kEigenvaluePad * std::max(0.0, c.dot(traces_ * c))};
  }

  /// An upper bound of ||(sum_i c_i U_i)^T u||^2 from the projected forms F of unit u, with
  /// c's pads.
  static double projected_norm_squared_upper(const Eigen::Matrix<double, 6, 6>& f, const Weights6& c,
                                             const ProjectionPads& pads) {
    return std::max(0.0, c.dot(f * c)) + pads.rounding + pads.eigenvalue + std::numeric_limits<double>::min();
  }

  /// Gram matrix of the combination sum_i c_i U_i, and the pad covering its rounding.
  Eigen::Matrix3d gram(const Weights6& c, double& pad) const {
    Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 6; ++i) {
      if (c[i] == 0.0) continue;
      for (int j = 0; j < 6; ++j) {
        if (c[j] != 0.0) g += (c[i] * c[j]) * gram_.block<3, 3>(3 * i, 3 * j);
      }
    }
    pad = rounding_ * c.cwiseAbs().sum() * c.cwiseAbs().sum() + kEigenvaluePad * g.trace() +
          std::numeric_limits<double>::min();
    return g;
  }

  /// Largest rest coordinate, relative to the first vertex of the first triangle.
  double extent() const { return extent_; }
  const PositionRounding& position_rounding() const { return position_rounding_; }

  Eigen::Vector3d point(const Weights6& w) const {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int i = 0; i < 6; ++i) p += w[i] * rest_[i];
    return p;
  }

 private:
  Eigen::Matrix<double, 18, 18> gram_;
  Eigen::Matrix<double, 6, 6> traces_;
  std::array<Eigen::Vector3d, 6> rest_;
  double rounding_ = 0.0;
  double extent_ = 0.0;
  PositionRounding position_rounding_;
};

/// A piece of one triangle: row k holds the barycentric weights of the piece's vertex k.
using Piece = Eigen::Matrix3d;

/// The weights of a point of the first (second) triangle in the six-vertex frame.
Weights6 on_first(const Eigen::Vector3d& w) {
  Weights6 weights;
  weights << w[0], w[1], w[2], 0.0, 0.0, 0.0;
  return weights;
}
Weights6 on_second(const Eigen::Vector3d& w) {
  Weights6 weights;
  weights << 0.0, 0.0, 0.0, w[0], w[1], w[2];
  return weights;
}

struct Evaluation {
  double lower;
  double upper;
};

/// The rest positions of a piece's three vertices.
using Corners = std::array<Eigen::Vector3d, 3>;

/// The nine vertex pairs (j, k) of two pieces, at 3 j + k: the combination xb - xa of the
/// frame's vertices that moves them apart, and its pads (the same for every direction).
struct VertexPairCombinations {
  std::array<Weights6, 9> weights;
  std::array<PairFrame::ProjectionPads, 9> pads;
  VertexPairCombinations(const PairFrame& frame, const Piece& pa, const Piece& pb) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) {
        weights[3 * j + k] = on_second(pb.row(k).transpose()) - on_first(pa.row(j).transpose());
        pads[3 * j + k] = frame.projection_pads(weights[3 * j + k]);
      }
    }
  }
};

/// The dual bound: for any v, a contact q_hat of points Xa, Xb satisfies
///   v^T (Xa - Xb) = v^T (U(Xb) - U(Xa)) q_hat <= ||(U(Xb) - U(Xa))^T v|| ||q_hat||.
/// Over the two pieces the ratio N / D, N = v^T (Xa - Xb) linear and D = ||(U(Xb) - U(Xa))^T v||
/// convex in the barycentric weights, is quasi-concave where N > 0 (N - t D >= 0 is a convex
/// set for t >= 0), so its minimum over the product of the pieces is at one of the 9 vertex
/// pairs; where N <= 0 at some vertex pair the pieces may meet with no motion: bound 0.
/// For a fixed v the bound loses only second order in the pieces' size. With v = (A A^T)^(-1)
/// d_c, the constant-mode optimum's multiplier, it is never weaker than the paper's
/// perturbation bound (eq. 10): the numerator is at least R_c^2 and the denominator at most
/// R_c + |dU| ||v||, with ||v|| <= R_c / sigma_min(A).
double dual_bound(const PairFrame& frame, const Corners& corners_a, const Corners& corners_b,
                  const VertexPairCombinations& combinations, const Eigen::Vector3d& v) {
  const double length = v.stableNorm();
  if (!(length > 0.0) || !std::isfinite(length)) return 0.0;
  const Eigen::Vector3d unit = v / length;
  const Eigen::Matrix<double, 6, 6> forms = frame.projected(unit);
  double bound = INFINITY;
  for (int j = 0; j < 3; ++j) {
    const Eigen::Vector3d& a_point = corners_a[j];
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& b_point = corners_b[k];
      const double numerator =
          unit.dot(a_point - b_point) - kDistanceAllowance * frame.extent() - 2.0 * frame.position_rounding().absolute;
      if (!(numerator > 0.0)) return 0.0;
      const int i = 3 * j + k;
      bound = std::min(bound, numerator / (std::sqrt(PairFrame::projected_norm_squared_upper(
                                               forms, combinations.weights[i], combinations.pads[i])) +
                                           2.0 * frame.position_rounding().per_norm));
    }
  }
  return bound;
}

/// Bounds for pieces pa and pb of the frame's triangles: the dual bound at the
/// constant-mode optimum's multiplier and at the upper bound's, and the paper's upper
/// bound R_hi (the true modes at the constant-mode closest points).
Evaluation evaluate(const PairFrame& frame, const Piece& pa, const Piece& pb) {
  const Eigen::Vector3d centroid_a = pa.colwise().mean().transpose();
  const Eigen::Vector3d centroid_b = pb.colwise().mean().transpose();
  double unused;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(
      frame.gram(on_second(centroid_b) - on_first(centroid_a), unused));
  // Floored relative to the largest (identity when nothing moves): the map stays finite and
  // its conditioning bounded; it only chooses the multiplier, so any floor is sound.
  const double largest = solver.eigenvalues()[2];
  const Eigen::Vector3d eigenvalues = largest > 0.0
                                          ? Eigen::Vector3d(solver.eigenvalues().cwiseMax(kMapConditioning * largest))
                                          : Eigen::Vector3d::Ones();
  // Contact of Xa and Xb under constant modes needs A q_hat = Xa - Xb (A = mean_b - mean_a),
  // whose smallest solution has norm ||(A A^T)^(-1/2) (Xa - Xb)||: a triangle distance after
  // that map. Only its closest points are used (the bound itself is the dual bound).
  const Eigen::Matrix3d map =
      solver.eigenvectors() * eigenvalues.array().rsqrt().matrix().asDiagonal() * solver.eigenvectors().transpose();
  Corners corners_a, corners_b, mapped_a, mapped_b;
  for (int i = 0; i < 3; ++i) {
    corners_a[i] = frame.point(on_first(pa.row(i).transpose()));
    corners_b[i] = frame.point(on_second(pb.row(i).transpose()));
  }
  for (int i = 0; i < 3; ++i) {
    mapped_a[i] = map * (corners_a[i] - corners_a[0]);
    mapped_b[i] = map * (corners_b[i] - corners_a[0]);
  }
  const TriangleClosestPoints closest = closest_points_disjoint_triangles(mapped_a, mapped_b);
  const Weights6 xa = on_first(pa.transpose() * closest.first_weights);
  const Weights6 xb = on_second(pb.transpose() * closest.second_weights);
  const Eigen::Vector3d d = frame.point(xa) - frame.point(xb);
  const Eigen::Vector3d constant_mode_multiplier =
      solver.eigenvectors() * eigenvalues.cwiseInverse().asDiagonal() * solver.eigenvectors().transpose() * d;
  Evaluation e;
  const VertexPairCombinations combinations(frame, pa, pb);
  e.lower = dual_bound(frame, corners_a, corners_b, combinations, constant_mode_multiplier);
#ifdef SSCC_MUTANT_NO_CONSTANT_MODE_MULTIPLIER
  e.lower = 0.0;
#endif
  // The paper's R_hi with the true modes at those points: the least-norm solution of
  // (U(Xb) - U(Xa)) q_hat = d through the eigen-decomposition of its Gram matrix (a
  // component of d in its null space means no solution).
  double true_pad;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> true_modes(frame.gram(xb - xa, true_pad));
  const Eigen::Vector3d along = true_modes.eigenvectors().transpose() * d;
  Eigen::Vector3d inverse_along = Eigen::Vector3d::Zero();
  e.upper = 0.0;
  for (int i = 0; i < 3; ++i) {
    if (true_modes.eigenvalues()[i] > true_pad) {
      inverse_along[i] = along[i] / true_modes.eigenvalues()[i];
      e.upper += along[i] * inverse_along[i];
    } else if (std::fabs(along[i]) > kDistanceAllowance * d.norm()) {
      e.upper = INFINITY;
    }
  }
  e.upper = std::sqrt(e.upper);
  if (std::isfinite(e.upper)) {
    e.lower = std::max(
        e.lower, dual_bound(frame, corners_a, corners_b, combinations, true_modes.eigenvectors() * inverse_along));
  }
  return e;
}

/// Longest rest edge of a piece: the one to split.
double longest_edge(const PairFrame& frame, const Piece& piece, bool second) {
  double longest = 0.0;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d x = piece.row(i).transpose(), y = piece.row((i + 1) % 3).transpose();
    const Eigen::Vector3d e = second ? frame.point(on_second(x)) - frame.point(on_second(y))
                                     : frame.point(on_first(x)) - frame.point(on_first(y));
    longest = std::max(longest, e.norm());
  }
  return longest;
}

/// The four pieces joining a piece's edge midpoints.
std::array<Piece, 4> split(const Piece& p) {
  const Eigen::RowVector3d m01 = 0.5 * (p.row(0) + p.row(1));
  const Eigen::RowVector3d m12 = 0.5 * (p.row(1) + p.row(2));
  const Eigen::RowVector3d m20 = 0.5 * (p.row(2) + p.row(0));
  const auto make = [](const Eigen::RowVector3d& x, const Eigen::RowVector3d& y, const Eigen::RowVector3d& z) {
    Piece piece;
    piece << x, y, z;
    return piece;
  };
  return {make(p.row(0), m01, m20), make(m01, p.row(1), m12), make(m20, m12, p.row(2)), make(m01, m12, m20)};
}

struct OpenPair {
  Piece a, b;
  Evaluation bound;
  int depth;
};

}  // namespace

TrianglePairRadius triangle_pair_radius(const ModalTriangle& a, const ModalTriangle& b,
                                        const TrianglePairRadiusOptions& options) {
  const PairFrame frame(a, b);
  TrianglePairRadius result;
  const Piece whole = Piece::Identity();
  const Evaluation root = evaluate(frame, whole, whole);
  result.evaluations = 1;
  result.upper = root.upper;
  // Best first: the open pair with the smallest lower bound is refined until its bound is
  // within epsilon of min(best contact found, target), reaches the ceiling, or cannot be
  // refined. The open pairs cover both triangles, so the smallest open lower bound is a
  // lower bound. A refinement splits the larger piece (4 new pairs).
  const auto later = [](const OpenPair& x, const OpenPair& y) { return x.bound.lower > y.bound.lower; };
  thread_local std::vector<OpenPair> open;  // reused: the precomputation makes millions of calls
  open.clear();
  open.push_back({whole, whole, root, 0});
  while (true) {
    std::pop_heap(open.begin(), open.end(), later);
    const OpenPair smallest = open.back();
    open.pop_back();
    const double lower = smallest.bound.lower;
    // Within epsilon of min(radius, target), which is all the caller needs.
    const bool accurate = lower >= (1.0 - options.epsilon) * std::min(result.upper, options.target);
    const bool exhausted = smallest.depth >= options.max_depth || result.evaluations + 4 > options.max_evaluations;
    if (accurate || exhausted || lower >= options.ceiling) {
      result.lower = lower;
      return result;
    }
    const bool split_a = longest_edge(frame, smallest.a, false) >= longest_edge(frame, smallest.b, true);
    for (const Piece& piece : split(split_a ? smallest.a : smallest.b)) {
      OpenPair child{split_a ? piece : smallest.a, split_a ? smallest.b : piece, {}, smallest.depth + 1};
      child.bound = evaluate(frame, child.a, child.b);
      ++result.evaluations;
      result.upper = std::min(result.upper, child.bound.upper);
      open.push_back(child);
      std::push_heap(open.begin(), open.end(), later);
    }
    result.depth = std::max(result.depth, smallest.depth + 1);
  }
}

namespace {

// The floor of the 1D bound replaces vertex pair (j, k)'s computed rate sqrt(sum_c d_c^2),
// d_c = |along_b - along_a| (1 + u) + slack_a + slack_b, by
//   growth (||n^T (M_b - M_a)|| + sqrt(n^T S_b,k n + pad_b,k) + sqrt(n^T S_a,j n + pad_a,j))
//     + allowance (block_a + block_b).
// Exactly, U_b,k - U_a,j = (M_b - M_a) + D_b,k - D_a,j with D = U - M for any M (the means
// as computed), and ||n^T D_k||^2 = n^T S_k n with S_k = D_k D_k^T. The computed
// projections err by gamma_3 |n|.|column| each and the slacks add 4u |n|.|column|: in the
// 2-norm over columns at most 8u (||U_a,j||_F + ||U_b,k||_F), far below the allowance; the
// same holds for the projected difference of the means (its subtraction adds u |M_b - M_a|
// per entry) and for the rounding of D itself (u |D| per entry, |D| below twice the largest
// block). Each entry of S_k is an r-term sum, rounded by at most gamma_r trace(S_k): pad =
// kSpreadPad trace(S_k) covers that and the quadratic form's rounding for r up to 10^6.
// Every other rounding (the norms, the sums of squares and the square roots, about
// (3r + 4)u relative) is far below the growth. The gaps are the same numbers, and rounding
// is monotone in the quotient and the sums, so each vertex pair's floor never exceeds its
// ratio in the computed 1D bound (nor the least floor the bound). Smaller constants could lift
// it above; larger ones only cut fewer pairs early.
// Both ends of the range: squares that underflow err by up to 2^-1074 each in absolute
// terms, which nothing relative covers: sqrt((r + 16) DBL_MIN), 2^26 times sqrt(r 2^-1074),
// is added to every floor rate (no effect on rates of any normal size). And blocks whose
// sum reaches kLargestFloorBlocks could overflow the 1D bound's sums of squares (to a rate
// of infinity, a bound of 0) before the floor's: there the floor abstains (it is 0, and the
// 1D bound leaves no vertex pair out), as it does on any rate that is not a positive number.
constexpr double kFloorRateGrowth = 1.0 + 1e-9;
constexpr double kFloorRateAllowance = 1e-12;
constexpr double kSpreadPad = 1e-9;
// The quick floor's spread, sqrt(kSpreadBound trace(S)), bounds the floor's sqrt(n^T S n + pad)
// for every unit n (|n| <= 1 + 2u), S the Gram matrix as computed: its entries err by at most
// gamma_r times the sums of |products|, so |S_ij| <= (1 + 2 gamma_r) sqrt(S_ii S_jj) and the
// computed n^T S n is at most (1 + 2 gamma_r)(1 + gamma_5)(1 + 4u) trace(S), within 3e-10 of
// trace(S) for r up to 10^6 (subnormal entries err by more, far below the floor's underflow
// allowance); the pad adds kSpreadPad trace(S). trace(S) (1 + 2 kSpreadPad) covers both with
// room for the rounding of the trace and of the square roots (monotone). Larger only weakens
// the quick floor.
constexpr double kSpreadBound = 1.0 + 2e-9;
// The projected floor's rows are padded with zero columns to a multiple of this many, its
// sums of squares kept in as many independent lanes (a 256-bit register of floats).
constexpr int kProjectionLanes = 8;
constexpr Eigen::Index padded_width(Eigen::Index modes) {
  return (modes + kProjectionLanes - 1) / kProjectionLanes * kProjectionLanes;
}
constexpr double kLargestFloorBlocks = 1e145;  // 4 r (1e145)^2 < 1e297 for r up to 10^6
// The projected floor runs in single precision on blocks below this Frobenius norm (its
// squares stay below 2^84, far from the floats' overflow); larger ones get no rows, and the
// floor abstains there.
constexpr double kLargestProjectedBlocks = 0x1p40;

/// sqrt(n^T S n + pad): a bound of a vertex's motion along n relative to its triangle's mean.
[[gnu::always_inline]] inline double spread_along(const Eigen::Matrix3d& deviation_gram, const Eigen::Vector3d& n) {
#ifdef SSCC_MUTANT_FLOOR_WITHOUT_SPREAD
  return 0.0;
#endif
  return std::sqrt(std::max(0.0, n.dot(deviation_gram * n)) + kSpreadPad * deviation_gram.trace());
}

/// The 1D bound's unit axis (the centroids' direction) and its nine vertex-pair gaps, each a
/// lower bound of n^T (X_b,k - X_a,j) less twice the positions' rounding; false when some
/// gap is not positive (or the centroids coincide): the bound is then 0.
[[gnu::always_inline]] inline bool axis_and_gaps(const ModalTriangle& a, const ModalTriangle& b,
                                                 const PositionRounding& rounding, Eigen::Vector3d& n,
                                                 std::array<double, 9>& gap) {
  const Eigen::Vector3d axis = (b.rest[0] + b.rest[1] + b.rest[2]) - (a.rest[0] + a.rest[1] + a.rest[2]);
  const double length = detail::stable_norm3(axis);
  if (!(length > 0.0)) return false;
  n = axis / length;
  constexpr double u = std::numeric_limits<double>::epsilon();
  for (int j = 0; j < 3; ++j) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d d = b.rest[k] - a.rest[j];
      gap[3 * j + k] = n.dot(d) - 8.0 * u * n.cwiseAbs().dot(d.cwiseAbs()) - 2.0 * rounding.absolute;
      if (!(gap[3 * j + k] > 0.0)) return false;
    }
  }
  return true;
}

}  // namespace

TriangleSummary summarize(const ModalTriangle& t) {
  TriangleSummary s = scales_of(t);
  const Eigen::Index r = t.modes[0].cols();
  s.floor_underflow = std::sqrt((static_cast<double>(r) + 16.0) * std::numeric_limits<double>::min());
  const double columns = static_cast<double>(padded_width(r));
  s.projected_growth = 1.0 + (columns / kProjectionLanes + 16.0) * 0x1p-23;
  s.projected_underflow = std::sqrt((columns + 16.0) * std::numeric_limits<float>::min());
  s.mean_modes = (t.modes[0] + t.modes[1] + t.modes[2]) / 3.0;
  for (int i = 0; i < 3; ++i) {
    s.deviation_grams[i].setZero();
    if (!(s.largest_block_norm < kLargestFloorBlocks)) continue;  // the floor abstains there
    const Eigen::Matrix<double, 3, Eigen::Dynamic> deviation = t.modes[i] - s.mean_modes;
    s.deviation_grams[i] = deviation * deviation.transpose();
#ifndef SSCC_MUTANT_QUICK_FLOOR_WITHOUT_SPREAD
    s.largest_spread = std::max(s.largest_spread, std::sqrt(kSpreadBound * s.deviation_grams[i].trace()));
#endif
  }
  if (!(s.largest_block_norm < kLargestProjectedBlocks)) return s;
  s.vertex_rows = Eigen::Matrix<float, 9, Eigen::Dynamic, Eigen::RowMajor>::Zero(9, padded_width(r));
  for (int i = 0; i < 3; ++i) s.vertex_rows.block(3 * i, 0, 3, r) = t.modes[i].cast<float>();
  return s;
}

double one_dimensional_radius(const ModalTriangle& a, const ModalTriangle& b) {
  return one_dimensional_radius(a, b, scales_of(a), scales_of(b));
}

namespace {

// Columns of a mode block the 1D bound projects at a time: its buffers stay on the stack.
constexpr int kColumnChunk = 32;
using ChunkProjections = std::array<std::array<double, kColumnChunk>, 3>;

/// For columns first..first + count - 1 of a 3 x r block: n^T column, and 4u |n|^T |column|
/// (the rounding of the projection), with the operations in the order Eigen's 3-vector dot
/// product takes them ((x0 + x1) + x2), so the values equal n.dot(column) bit for bit.
void project_columns(const Eigen::Matrix<double, 3, Eigen::Dynamic>& block, Eigen::Index first, int count,
                     const Eigen::Vector3d& n, const Eigen::Vector3d& magnitude,
                     std::array<double, kColumnChunk>& along, std::array<double, kColumnChunk>& slack) {
  constexpr double u = std::numeric_limits<double>::epsilon();
  const double* column = block.data() + 3 * first;
  for (int c = 0; c < count; ++c, column += 3) {
    along[c] = (n[0] * column[0] + n[1] * column[1]) + n[2] * column[2];
    slack[c] = 4.0 * u *
               ((magnitude[0] * std::fabs(column[0]) + magnitude[1] * std::fabs(column[1])) +
                magnitude[2] * std::fabs(column[2]));
  }
}

/// Which vertices of a (j) and of b (k) the vertex pairs 3 j + k in needed[0, count) use.
[[gnu::always_inline]] inline void vertices_of(const std::array<int, 9>& needed, int count, std::array<bool, 3>& of_a,
                                               std::array<bool, 3>& of_b) {
  of_a = {};
  of_b = {};
  for (int t = 0; t < count; ++t) {
    of_a[needed[t] / 3] = true;
    of_b[needed[t] % 3] = true;
  }
}

/// What the floors add to every rate they bound (see kFloorRateAllowance).
double floor_rate_allowance(const TriangleSummary& summary_a, const TriangleSummary& summary_b,
                            const PositionRounding& rounding) {
  return kFloorRateAllowance * (summary_a.largest_block_norm + summary_b.largest_block_norm) + 2.0 * rounding.per_norm +
         summary_a.floor_underflow;
}

/// The floor (header) of each vertex pair's ratio, at 3 j + k, from the axis and gaps the 1D
/// bound computes, each times the 1D bound's shrink (so never above that vertex pair's ratio
/// in the 1D bound as computed); false when the floor abstains.
[[gnu::always_inline]] inline bool vertex_pair_floors(const TriangleSummary& summary_a,
                                                      const TriangleSummary& summary_b, const Eigen::Vector3d& n,
                                                      const std::array<double, 9>& gap, double allowance, double cut,
                                                      std::array<double, 9>& floor) {
  const double blocks = summary_a.largest_block_norm + summary_b.largest_block_norm;
  if (!(blocks < kLargestFloorBlocks)) return false;
  // ||n^T (M_b - M_a)||, whole rows at a time (vectorized).
  const auto& mean_a = summary_a.mean_modes;
  const auto& mean_b = summary_b.mean_modes;
  const double common = (n[0] * (mean_b.row(0) - mean_a.row(0)) + n[1] * (mean_b.row(1) - mean_a.row(1)) +
                         n[2] * (mean_b.row(2) - mean_a.row(2)))
                            .norm();
  // The quick floor: every vertex pair's rate at most the largest spreads', its gap at least
  // the least gap.
  const double quick_rate =
      kFloorRateGrowth * (common + summary_b.largest_spread + summary_a.largest_spread) + allowance;
  if (quick_rate > 0.0 && std::isfinite(quick_rate)) {
    const double quick = kOneDimensionalShrink * (*std::min_element(gap.begin(), gap.end()) / quick_rate);
    if (quick >= cut) {
      floor.fill(quick);
      return true;
    }
  }
  std::array<double, 3> spread_a, spread_b;
  for (int i = 0; i < 3; ++i) {
    spread_a[i] = spread_along(summary_a.deviation_grams[i], n);
    spread_b[i] = spread_along(summary_b.deviation_grams[i], n);
  }
  for (int j = 0; j < 3; ++j) {
    for (int k = 0; k < 3; ++k) {
      const double rate = kFloorRateGrowth * (common + spread_b[k] + spread_a[j]) + allowance;
      if (!(rate > 0.0) || !std::isfinite(rate)) return false;
      floor[3 * j + k] = kOneDimensionalShrink * (gap[3 * j + k] / rate);
    }
  }
  return true;
}

// The projected floor replaces a vertex pair's computed rate by
//   g ||n_f^T (U_b,k - U_a,j)_f||_f + kProjectedBlockAllowance (block_a + block_b)
//     + sqrt((w + 16) FLT_MIN) + allowance (the floor's),
// the norm computed in single precision (f: n and the blocks rounded to floats, the
// arithmetic in floats, whole rows of vertex_rows, w columns padded, summed in eight lanes),
// g = 1 + (w / 8 + 16) 2^-23. Against the exact norm N of the computed n, the 1D bound's
// projections err by gamma_3 |n|.|column| and its slacks add 4u (1 + gamma_3) |n|.|column| (u
// the double epsilon, 2^-52), so by Minkowski over the columns its rate is at most (1 +
// gamma_(r + 6)) (N + 7.2u (F_a,j + F_b,k)) plus its 2 per_norm, F the blocks' Frobenius norms
// (|n| <= 1 + 2u). With v the float unit roundoff (2^-24): rounding n and a column to floats
// errs by 2v |n_i| |U_i| per term and the 3-term float dot product by gamma_3(v), in all 5.1 v
// ||column|| (Cauchy-Schwarz) per vertex, plus at most 2^-107 a column from floats below
// FLT_MIN (blocks below 2^40); the float difference adds v of itself. So N <= (1 + 1.1 v)
// ||d|| + 5.2 v (F_a,j + F_b,k) + sqrt(w) 2^-106, d the float differences. Their squares and
// sums (nonnegative, at most w / 8 terms a lane, then three levels across the lanes) and the
// square root lose at most a factor (1 - v)^(w / 8 + 5) of the squared norm, and squares below
// FLT_MIN 2^-150 each (sums of subnormals are exact): ||d|| <= (1 - (w / 16 + 2.5) v)^-1 N_f +
// sqrt(w) 2^-75. The growth g covers these relative terms with gamma_(r + 6) (at most 2.3e-10
// for r up to 10^6) and the rounding of the double operations on N_f, for w up to 10^6 and
// beyond; kProjectedBlockAllowance (16.7 v) covers 5.2 v (1 + 1e-9) (F_a,j + F_b,k) with 7.2u
// of it; the square-root term the underflow, 2^-63 per column's worth (and the squares a
// flush-to-zero mode would drop, 2^-63 each). As for the floor, rounding is monotone in the
// quotient: the projected floor never exceeds the vertex pair's ratio in the 1D bound as
// computed. Whole rows in eight float lanes, 57% of the bytes at 27 modes, and no slacks: a
// fraction of the bound's own pass, which then runs only on the vertex pairs near or below the
// cut. Smaller constants could lift it above the bound; larger ones only leave more pairs to
// the bound's own pass.
constexpr double kProjectedBlockAllowance = 1e-6;
[[gnu::always_inline]] inline void leave_out_by_projection(const TriangleSummary& summary_a,
                                                           const TriangleSummary& summary_b, const Eigen::Vector3d& n,
                                                           const std::array<double, 9>& gap, double floor_allowance,
                                                           double cut, std::array<int, 9>& needed, int& count_needed,
                                                           double& least_floor) {
  const Eigen::Index width = summary_a.vertex_rows.cols();
  std::array<bool, 3> used_a, used_b;
  vertices_of(needed, count_needed, used_a, used_b);
  // Copies: the compiler then knows no store below changes them.
  const float n0 = static_cast<float>(n[0]), n1 = static_cast<float>(n[1]), n2 = static_cast<float>(n[2]);
  alignas(32) float along[6][kColumnChunk];
  // Only the rows read below are cleared (clearing all nine was a string store per call).
  alignas(32) float lanes[9][kProjectionLanes];
  for (int t = 0; t < count_needed; ++t) {
    for (int l = 0; l < kProjectionLanes; ++l) lanes[t][l] = 0.0f;
  }
  for (Eigen::Index first = 0; first < width; first += kColumnChunk) {
    const int count = static_cast<int>(std::min<Eigen::Index>(kColumnChunk, width - first));
    for (int v = 0; v < 6; ++v) {
      if (!(v < 3 ? used_a[v] : used_b[v - 3])) continue;
      const float* x = (v < 3 ? summary_a : summary_b).vertex_rows.data() + 3 * (v % 3) * width + first;
      const float* y = x + width;
      const float* z = y + width;
      for (int c = 0; c < count; ++c) along[v][c] = (n0 * x[c] + n1 * y[c]) + n2 * z[c];
    }
    for (int t = 0; t < count_needed; ++t) {
      const float* pa = along[needed[t] / 3];
      const float* pb = along[3 + needed[t] % 3];
      for (int c = 0; c < count; c += kProjectionLanes) {
        for (int l = 0; l < kProjectionLanes; ++l) {
          const float d = pb[c + l] - pa[c + l];
          lanes[t][l] += d * d;
        }
      }
    }
  }
  const double growth = summary_a.projected_growth;
  const double allowance = floor_allowance +
                           kProjectedBlockAllowance * (summary_a.largest_block_norm + summary_b.largest_block_norm) +
                           summary_a.projected_underflow;
  int kept = 0;
  for (int t = 0; t < count_needed; ++t) {
    const int i = needed[t];
    static_assert(kProjectionLanes == 8, "the sum below takes eight lanes");
    const float* sums = lanes[t];
    const double norm =
        std::sqrt(((sums[0] + sums[1]) + (sums[2] + sums[3])) + ((sums[4] + sums[5]) + (sums[6] + sums[7])));
#ifdef SSCC_MUTANT_PROJECTED_FLOOR_UNPADDED
    const double rate = norm;
#elif defined(SSCC_MUTANT_PROJECTED_FLOOR_NO_GROWTH)
    const double rate = norm + allowance;
#else
    const double rate = growth * norm + allowance;
#endif
    const double floor = kOneDimensionalShrink * (gap[i] / rate);
    if (rate > 0.0 && std::isfinite(rate) && floor >= cut) {
      least_floor = std::min(least_floor, floor);
    } else {
      needed[kept++] = i;
    }
  }
  count_needed = kept;
}

/// The floor (header): the least of the vertex pairs' floors, 0 when it abstains.
double floor_from_gaps(const TriangleSummary& summary_a, const TriangleSummary& summary_b, const Eigen::Vector3d& n,
                       const std::array<double, 9>& gap, const PositionRounding& rounding) {
  std::array<double, 9> floor;
  const double allowance = floor_rate_allowance(summary_a, summary_b, rounding);
  if (!vertex_pair_floors(summary_a, summary_b, n, gap, allowance, INFINITY, floor)) return 0.0;
  return *std::min_element(floor.begin(), floor.end());
}

}  // namespace

SSCC_AVX2_CLONE
double one_dimensional_radius(const ModalTriangle& a, const ModalTriangle& b, const TriangleSummary& summary_a,
                              const TriangleSummary& summary_b, double cut) {
  constexpr double u = std::numeric_limits<double>::epsilon();
  const Eigen::Index r = a.modes[0].cols();
  const PositionRounding rounding = rounding_of_positions(summary_a, summary_b, r);
  // Per vertex pair (j, k): a lower bound of the gap n^T (X_b,k - X_a,j), the computed dot
  // product less its absolute rounding (the difference and the three products).
  Eigen::Vector3d n;
  std::array<double, 9> gap, floor;
  if (!axis_and_gaps(a, b, rounding, n, gap)) return 0.0;
  // The vertex pairs whose ratio is computed below, at 3 j + k. With a cut, those whose floor
  // reaches it are left out: each one's ratio is at least its floor, so at least the cut,
  // and the least ratio is either below the cut (then among the others) or not needed.
  std::array<int, 9> needed;
  int count_needed = 0;
  double least_floor = INFINITY;  // of the vertex pairs left out
  const double allowance = floor_rate_allowance(summary_a, summary_b, rounding);
  const bool floors = cut < INFINITY && vertex_pair_floors(summary_a, summary_b, n, gap, allowance, cut, floor);
  for (int i = 0; i < 9; ++i) {
    const bool left_out = floors && floor[i] >= cut;
    needed[count_needed] = i;
    count_needed += left_out ? 0 : 1;
    least_floor = left_out ? std::min(least_floor, floor[i]) : least_floor;
  }
  if (count_needed == 0) return least_floor;
  if (floors && summary_a.vertex_rows.cols() == padded_width(r) && summary_b.vertex_rows.cols() == padded_width(r)) {
    leave_out_by_projection(summary_a, summary_b, n, gap, allowance, cut, needed, count_needed, least_floor);
    if (count_needed == 0) return least_floor;
  }
  std::array<bool, 3> needed_a, needed_b;
  vertices_of(needed, count_needed, needed_a, needed_b);
  // And an upper bound of the squared rate ||n^T (U_b,k - U_a,j)||^2, column by column: each
  // projected difference grown by the rounding of the two projections it subtracts. Columns
  // go in chunks, each quantity for a whole chunk at once (vectorized), and the squares are
  // summed in column order: the sums are those of a column-by-column loop, bit for bit, in
  // builds that do not contract products and sums into FMA (the project's: baseline x86-64;
  // with -mfma either loop may contract differently, the bound as sound).
  const Eigen::Vector3d magnitude = n.cwiseAbs();
  ChunkProjections along_a, along_b, slack_a, slack_b;
  std::array<std::array<double, kColumnChunk>, 9> squares;
  std::array<double, 9> squared{};
  for (Eigen::Index first = 0; first < r; first += kColumnChunk) {
    const int count = static_cast<int>(std::min<Eigen::Index>(kColumnChunk, r - first));
    for (int i = 0; i < 3; ++i) {
      if (needed_a[i]) project_columns(a.modes[i], first, count, n, magnitude, along_a[i], slack_a[i]);
      if (needed_b[i]) project_columns(b.modes[i], first, count, n, magnitude, along_b[i], slack_b[i]);
    }
    for (int t = 0; t < count_needed; ++t) {
      const int j = needed[t] / 3, k = needed[t] % 3;
      for (int c = 0; c < count; ++c) {
        const double difference = std::fabs(along_b[k][c] - along_a[j][c]) * (1.0 + u) + slack_a[j][c] + slack_b[k][c];
        squares[t][c] = difference * difference;
      }
    }
    // Independent sums, each in column order.
    for (int c = 0; c < count; ++c) {
      for (int t = 0; t < count_needed; ++t) squared[t] += squares[t][c];
    }
  }
  // The ratio is quasi-concave in the barycentric weights (see dual_bound): its minimum
  // over the two triangles is at a vertex pair. The last factor covers the rounding of the
  // sums, the square root and the division.
  double radius = INFINITY;
  for (int t = 0; t < count_needed; ++t) {
    const double rate = std::sqrt(squared[t]) + 2.0 * rounding.per_norm;
    if (rate > 0.0) radius = std::min(radius, gap[needed[t]] / rate);
  }
  return std::min(kOneDimensionalShrink * radius, least_floor);
}

double one_dimensional_radius_floor(const ModalTriangle& a, const ModalTriangle& b, const TriangleSummary& summary_a,
                                    const TriangleSummary& summary_b) {
  const PositionRounding rounding = rounding_of_positions(summary_a, summary_b, a.modes[0].cols());
  Eigen::Vector3d n;
  std::array<double, 9> gap;
  if (!axis_and_gaps(a, b, rounding, n, gap)) return 0.0;
  return floor_from_gaps(summary_a, summary_b, n, gap, rounding);
}

namespace {

// The group floor's margins. Relative: it bounds the quick floor of every pair of the two
// groups, whose gaps, common rate and quotient round by a few hundred units of roundoff at
// most (r + 10 for the sums over r columns: 2.3e-10 for r up to 10^6), and its own sums and
// square roots as little. Absolute: the gaps and centroids round by about a hundred units of
// roundoff of the largest coordinate, and the mean modes' differences by a few of the largest
// blocks. Smaller could lift the floor above a pair's quick floor (a pair left out that its
// own screening would keep: other certificates); larger only leaves out fewer groups.
constexpr double kGroupRelative = 1e-6;
constexpr double kGroupAbsolute = 1e-12;
// Coordinates from this size on could overflow the pairs' sums, and below the other the
// squares of the vertices' distances from their centroids could underflow by more than the
// absolute margin covers (2^-537 each, against 1e-12 L): the group floor abstains.
constexpr double kLargestGroupCoordinate = 1e150;
constexpr double kSmallestGroupCoordinate = 0x1p-400;

}  // namespace

/// At least ||x||_2 for a 3 x r matrix x (exactly, as given): Gershgorin's bound on the
/// largest eigenvalue of x x^T, whose computed entries err by at most gamma_r times the
/// product of the rows' norms (padded by 3 (r + 8) u trace) and by 2^-1075 a product that
/// underflows (padded by (r + 16) DBL_MIN), grown by the relative margin for the square root. Equal to ||x||_2 (within
/// the margins) when the rows are orthogonal, as for the polynomial bases, whose vertex blocks are I (x) m(p)^T. x is y
/// - z for two 3 x r blocks, its entries as computed; no allocation: the precomputation calls this for every node pair
/// it visits.
template <typename First, typename Second>
double spectral_norm_upper(const First& y, const Second& z) {
  constexpr double u = std::numeric_limits<double>::epsilon();
  double g00 = 0.0, g11 = 0.0, g22 = 0.0, g01 = 0.0, g02 = 0.0, g12 = 0.0;
  for (Eigen::Index c = 0; c < y.cols(); ++c) {
    const double x0 = y(0, c) - z(0, c), x1 = y(1, c) - z(1, c), x2 = y(2, c) - z(2, c);
    g00 += x0 * x0;
    g11 += x1 * x1;
    g22 += x2 * x2;
    g01 += x0 * x1;
    g02 += x0 * x2;
    g12 += x1 * x2;
  }
  const double rows = std::max({g00 + std::fabs(g01) + std::fabs(g02), std::fabs(g01) + g11 + std::fabs(g12),
                                std::fabs(g02) + std::fabs(g12) + g22});
  const double columns = static_cast<double>(y.cols());
  const double pad =
      3.0 * (columns + 8.0) * u * (g00 + g11 + g22) + (columns + 16.0) * std::numeric_limits<double>::min();
  return std::sqrt(rows + pad) * (1.0 + kGroupRelative);
}

TriangleGroupSummary summarize_group(const ModalTriangle* triangles, const TriangleSummary* summaries, int count,
                                     const GroupReference& reference) {
  TriangleGroupSummary g;
  g.lowest_centroid.setConstant(INFINITY);
  g.highest_centroid.setConstant(-INFINITY);
  double reach = 0.0, deviation = 0.0;
  for (int t = 0; t < count; ++t) {
    const ModalTriangle& x = triangles[t];
    const TriangleSummary& s = summaries[t];
    const Eigen::Vector3d centroid = (x.rest[0] + x.rest[1] + x.rest[2]) / 3.0;
    g.lowest_centroid = g.lowest_centroid.cwiseMin(centroid);
    g.highest_centroid = g.highest_centroid.cwiseMax(centroid);
    for (const Eigen::Vector3d& p : x.rest) reach = std::max(reach, (p - centroid).norm());
    for (const auto& block : x.modes) deviation = std::max(deviation, spectral_norm_upper(block, reference));
    g.largest_coordinate = std::max(g.largest_coordinate, s.largest_coordinate);
    g.largest_row_norm = std::max(g.largest_row_norm, s.largest_row_norm);
    g.largest_block_norm = std::max(g.largest_block_norm, s.largest_block_norm);
  }
  // The computed centroids and distances err by a few units of roundoff of the coordinates,
  // the blocks' differences by one of the blocks and the reference: grown past the exact values.
  const double centroid_rounding = kGroupAbsolute * g.largest_coordinate;
  g.lowest_centroid.array() -= centroid_rounding;
  g.highest_centroid.array() += centroid_rounding;
  g.reach = reach * (1.0 + kGroupRelative) + centroid_rounding;
  g.deviation = deviation * (1.0 + kGroupRelative) + kGroupAbsolute * (g.largest_block_norm + reference.norm());
  g.rate_underflow = std::sqrt((static_cast<double>(reference.cols()) + 16.0) * std::numeric_limits<double>::min());
  return g;
}

// For triangles s of group A and t of group B, the 1D bound as computed (its pass over the
// columns) is shrink min_jk (gap_jk / rate_jk). Gaps: with c the exact centroids and n the
// computed unit axis (within 7u of the computed centroids' direction, whose sums err by at most
// 32u L, L the largest coordinate), every computed gap n^T (X_t,k - X_s,j) less its slacks is at
// least (1 - 10u) (|c_t - c_s| - (1 + 7u)(reach_s + reach_t)) - 100u L - 2 absolute (1 + 2u),
// absolute = (r + 2) u L the positions' rounding: the centroids' direction less the vertices'
// distances from them, and the roundings of the axis, the products and the slacks. The least
// distance of the groups' centroid boxes bounds |c_t - c_s|, their reach the vertices'
// distances. Rates: rate_jk is at most (1 + (r + 6)u)(N + 7.2u (block_s + block_t)) + 2
// per_norm, N = ||n^T (U_t,k - U_s,j)|| exactly (the projected floor's argument), and N <= (1 +
// 7u) (||R_B - R_A||_2 + dev_A + dev_B) for the groups' references R (triangle inequality). The
// 2-norms come from Gershgorin's bound on Gram matrices (spectral_norm_upper), equal to them
// for the polynomial bases. The margins (kGroupRelative, kGroupAbsolute) cover these roundings
// many times over: the floor is at most every pair's 1D bound, which is then positive (every
// gap positive). Underflow: the 1D bound's squares that round up to 2^-1074 (r of them at most)
// add up to sqrt(r 2^-1074) to its rates, covered by rate_underflow, sqrt((r + 16) DBL_MIN), the
// Gram matrices' by their pad; on the gaps' side the floor abstains below
// kSmallestGroupCoordinate. Blocks from kLargestFloorBlocks on could overflow its sums (to a bound of 0):
// the floor abstains there, as for coordinates from kLargestGroupCoordinate on.
double group_pair_floor(const TriangleGroupSummary& a, const TriangleGroupSummary& b, const GroupReference& reference_a,
                        const GroupReference& reference_b) {
  constexpr double u = std::numeric_limits<double>::epsilon();
  const double blocks = a.largest_block_norm + b.largest_block_norm;
  const double coordinate = std::max(a.largest_coordinate, b.largest_coordinate);
  if (!(blocks < kLargestFloorBlocks) || !(coordinate < kLargestGroupCoordinate) ||
      !(coordinate >= kSmallestGroupCoordinate)) {
    return 0.0;
  }
  double squared = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double apart =
        std::max({0.0, b.lowest_centroid[i] - a.highest_centroid[i], a.lowest_centroid[i] - b.highest_centroid[i]});
    squared += apart * apart;
  }
  const double modes = static_cast<double>(reference_a.cols());
  const double position_rounding = (modes + 2.0) * u;
#ifdef SSCC_MUTANT_GROUP_FLOOR_NO_REACH
  const double gap = (1.0 - kGroupRelative) * std::sqrt(squared);
#else
  const double gap = (1.0 - kGroupRelative) * (std::sqrt(squared) - a.reach - b.reach) -
                     (kGroupAbsolute + 2.0 * position_rounding * (1.0 + kGroupRelative)) * coordinate;
#endif
  if (!(gap > 0.0)) return 0.0;
#ifdef SSCC_MUTANT_GROUP_FLOOR_NO_DEVIATION
  const double deviations = 0.0;
#else
  const double deviations = a.deviation + b.deviation;
#endif
  const double motion = spectral_norm_upper(reference_b, reference_a) + deviations + kGroupAbsolute * blocks;
  const double rate =
      (1.0 + kGroupRelative) * motion +
      2.0 * position_rounding * (1.0 + kGroupRelative) * std::max(a.largest_row_norm, b.largest_row_norm) +
      a.rate_underflow;
  const double floor = (1.0 - kGroupRelative) * (gap / rate);
  return rate > 0.0 && std::isfinite(floor) ? floor : 0.0;
}

}  // namespace sscc
