// Lower bounds on the subspace distance to contact of two triangles (SSCC paper, section 5.1).
//
// Two triangles deform with their vertices, x = p + U_hat q_hat, the modes interpolated
// barycentrically across each triangle. Their collision radius is the smallest ||q_hat||_2
// at which some point of one touches some point of the other.
//
// Guarantees (exact-arithmetic statements; every floating-point step is padded so that the
// computed value stays on the conservative side, see the constants in the source):
//  - triangle_pair_radius().lower never exceeds the collision radius. Per pair of pieces it
//    is a dual bound: for any v, v^T (Xa - Xb) <= ||(U(Xb) - U(Xa))^T v|| ||q_hat|| at a
//    contact, extremes taken at the pieces' vertex pairs. v is the multiplier of the
//    constant-mode problem (each piece moved by the mean of its modes; the paper's section
//    5.1: a triangle distance after the map (A A^T)^(-1/2)), which makes the bound at least
//    the paper's perturbation bound (eq. 10 with eq. 11) and usually far tighter, or the
//    multiplier at the upper bound's points, whichever is larger. Where the bounds are
//    loose the larger piece is split at its edge midpoints into 4, best first.
//  - .upper is a configuration that does bring the triangles into contact (the paper's
//    R_hi, up to rounding): it only steers the refinement and is never used as a bound.
//  - one_dimensional_radius() is the 1D projection bound in Cauchy-Schwarz form, also a
//    lower bound.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace sscc {

/// The relative rounding pad of the pair bound's Gram matrices for r modes: each entry is a
/// dot product of two r-vectors of centred mode entries, whose rounding is below
/// gamma_{r+2} (the dot product's accumulation and the centring) times the product of the
/// vectors' norms, and combining the entries with six coefficients adds a few units of
/// roundoff more; the pad is twice r plus a constant margin, never below the 256 units used
/// for r <= 64. Smaller could let a radius round above the true one for large r; larger only
/// weakens the bounds.
constexpr double gram_rounding_pad(int modes) {
#ifdef SSCC_MUTANT_GRAM_PAD_FIXED
  return 256.0 * std::numeric_limits<double>::epsilon();
#endif
  return std::max(256.0, 2.0 * (modes + 64.0)) * std::numeric_limits<double>::epsilon();
}

/// A triangle with its rest vertices and the 3 x r scaled mode block of each vertex.
struct ModalTriangle {
  std::array<Eigen::Vector3d, 3> rest;
  std::array<Eigen::Matrix<double, 3, Eigen::Dynamic>, 3> modes;
};

struct TrianglePairRadiusOptions {
  /// Refinement stops once lower >= (1 - epsilon) * min(upper, target), on radii (norms of
  /// q_hat): lower is then within epsilon of min(radius, target).
  double epsilon = 0.1;
  /// What the caller minimises over is known to be at most this (a contact found in
  /// another pair, or the largest radius of interest): resolving beyond it is useless.
  double target = INFINITY;
  /// The caller keeps min(this, lower): refinement stops once the lower bound reaches it.
  double ceiling = INFINITY;
  /// Most midpoint subdivisions along one branch (each splits one of the two pieces in 4).
  int max_depth = 16;
  /// Most constant-mode evaluations for one pair.
  int max_evaluations = 2048;
};

struct TrianglePairRadius {
  double lower = 0.0;  ///< <= the collision radius
  double upper = 0.0;  ///< a contact configuration's norm (>= the collision radius)
  int evaluations = 0;
  int depth = 0;
};

/// Lower (and upper) bound of the collision radius of two triangles that do not intersect
/// at rest. Intersecting triangles have radius 0: test with ccd::triangles_intersect first.
TrianglePairRadius triangle_pair_radius(const ModalTriangle& a, const ModalTriangle& b,
                                        const TrianglePairRadiusOptions& options = {});

/// The 1D bound: project on the line through the triangles' centroids (unit n). Contact
/// needs n^T (Xb - Xa) to vanish; it starts at the gap and changes at most at the rate
/// ||n^T (U(Xb) - U(Xa))||_2 per unit ||q_hat|| (Cauchy-Schwarz), and the ratio's minimum
/// over the triangles is at a vertex pair. Cheap (no eigen-decomposition); a lower bound;
/// 0 when the projections overlap.
double one_dimensional_radius(const ModalTriangle& a, const ModalTriangle& b);

/// What the 1D bound reads of one triangle beyond its vertices, computed once per triangle
/// when many pairs share it (the precomputation): the bounds are the same as without it.
struct TriangleSummary {
  double largest_coordinate = 0.0;  ///< largest |rest coordinate|
  double largest_row_norm = 0.0;    ///< largest 2-norm of a row of the three mode blocks
  double largest_block_norm = 0.0;  ///< largest Frobenius norm of a mode block
  /// the three blocks' mean, as computed; row-major: the floor projects whole rows at once
  Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor> mean_modes;
  /// (block_k - mean_modes)(block_k - mean_modes)^T per vertex k: n^T S_k n is the squared
  /// motion of vertex k along n relative to the mean, per unit ||q_hat||
  std::array<Eigen::Matrix3d, 3> deviation_grams;
  /// at least sqrt(n^T S_k n + pad) (the floor's spread) for every vertex k and unit n, where
  /// the floor does not abstain (blocks below its range)
  double largest_spread = 0.0;
  /// the three mode blocks again in single precision, row-major (rows 3 k to 3 k + 2: vertex
  /// k) and padded with zero columns to a multiple of eight: the projected floor reads n^T U_k
  /// as whole rows; empty where the blocks lie outside its range
  Eigen::Matrix<float, 9, Eigen::Dynamic, Eigen::RowMajor> vertex_rows;
  /// What the floors add for underflow, sqrt((r + 16) DBL_MIN) and sqrt((w + 16) FLT_MIN) (w
  /// the rows' padded width), and the projected floor's growth 1 + (w / 8 + 16) 2^-23: they
  /// depend on r only, and a square root per screened pair was a few percent of its time
  double floor_underflow = 0.0;
  double projected_underflow = 0.0;
  double projected_growth = 1.0;
};
TriangleSummary summarize(const ModalTriangle& t);

/// one_dimensional_radius(a, b) from the triangles' summaries (summarize(a), summarize(b):
/// the floors below trust them as they are): the same value where it lies
/// below `cut`; where it does not, a value at least `cut` and never above it (a caller
/// comparing with `cut` decides the same). The ratio of a vertex pair whose floor (below)
/// reaches the cut is not computed: when every one's does, that is the floor, or a quick floor
/// below it (every vertex pair's rate bounded with the triangles' largest spreads, and the
/// least gap) when that reaches the cut before the nine floors are computed. Nor is the ratio
/// of one whose projected floor reaches it: its rate ||n^T (U_b,k - U_a,j)|| in single precision
/// from the summaries' row-major blocks, without the bound's slacks, grown and padded to cover
/// the floats' rounding.
double one_dimensional_radius(const ModalTriangle& a, const ModalTriangle& b, const TriangleSummary& summary_a,
                              const TriangleSummary& summary_b, double cut = INFINITY);

/// What the group floor reads of a group of triangles (a node of the hierarchy): bounds over
/// the group's triangles, computed once per group.
struct TriangleGroupSummary {
  Eigen::Vector3d lowest_centroid = Eigen::Vector3d::Zero();   ///< a box holding every triangle's exact
  Eigen::Vector3d highest_centroid = Eigen::Vector3d::Zero();  ///< centroid
  double reach = 0.0;  ///< at least any vertex's distance from its triangle's exact centroid
  double largest_coordinate = 0.0, largest_row_norm = 0.0, largest_block_norm = 0.0;
  /// at least ||U_k - reference||_2 for every vertex block U_k of the group's triangles
  double deviation = 0.0;
  double rate_underflow = 0.0;  ///< sqrt((r + 16) DBL_MIN): the 1D bound's squares that underflow
};
using GroupReference = Eigen::Ref<const Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>>;
/// The group summary of `count` triangles and their summaries (summarize), against a 3 x r
/// reference block (any: the closer to the vertices' blocks, the tighter the floor).
TriangleGroupSummary summarize_group(const ModalTriangle* triangles, const TriangleSummary* summaries, int count,
                                     const GroupReference& reference);

/// Never above one_dimensional_radius(a, b) as computed for any triangle a of one group and b
/// of the other, from bounds over each group: the least distance of their centroids less the
/// largest distance of a vertex from its centroid (for the gaps), and the references'
/// difference plus the vertex blocks' largest deviations from them (for the rates, in the
/// 2-norm). 0 where it cannot tell (groups that overlap or nearly touch, coordinates of 1e150
/// or more, or all below 2^-400). A caller that
/// screens pairs with one_dimensional_radius(a, b, summary_a, summary_b, cut) can leave out
/// every pair of two groups whose floor reaches the cut: each screening would answer the cut
/// or above, so the pairs bounded, and the radii, stay the same.
double group_pair_floor(const TriangleGroupSummary& a, const TriangleGroupSummary& b, const GroupReference& reference_a,
                        const GroupReference& reference_b);

/// Never above one_dimensional_radius(a, b) as computed, at a fraction of its cost (one
/// projection of a difference per mode against twelve dot products, and nine squares; the
/// value may vary in its last bits with the buffers' alignment, never above the 1D bound):
/// each vertex pair's rate replaced by ||n^T (mean_b - mean_a)|| + sqrt(n^T S_b,k n) +
/// sqrt(n^T S_a,j n), which bounds it, grown to cover the rounding of both (the constants in
/// the source). A pair whose floor reaches a running minimum's lower bound has its 1D bound
/// there too.
double one_dimensional_radius_floor(const ModalTriangle& a, const ModalTriangle& b, const TriangleSummary& summary_a,
                                    const TriangleSummary& summary_b);

}  // namespace sscc
