// The normal-cone cull of patch_cull.hpp for reduced models, decided from the step's norm in
// O(1) per node: each patch proven at rest gets a radius S, and a step whose ends' scaled
// norms stay below S satisfies the theorem's hypotheses (patch_cull.hpp) for the positions the
// query computes, at every t. No normal or contour is formed per step. Private to the library;
// SelfCcd::query uses it when SelfCcdOptions::use_normal_cones.
//
// THEOREM. Let S be a set of triangles whose boundary chain is a simple cycle, d a unit vector
// and q_hat any coordinates with ||q_hat|| <= s (scaled coordinates: x_v = p_v + U_hat_v q_hat).
// The positions a query computes are x_v(q_hat) + e_v with |e_v| <= eta(s) = eta0 + eta1 s
// (below). Both hypotheses of patch_cull.hpp hold for every straight-line step whose ends have
// norm at most s, for the computed positions at every t, if s is below both radii:
//  (i)  triangle T (edges e1 = x1 - x0, e2 = x2 - x0 at rest, E1 = U_hat_1 - U_hat_0 and
//       E2 = U_hat_2 - U_hat_0, 3 x r) has d . n_T > 0 for every such configuration when
//         c_T > A_T s + B_T s^2 + 2 eta (L0 + L1 s) + 4 eta^2,
//       c_T = d . (e1 x e2), A_T = |E2^T (d x e1) + E1^T (e2 x d)|, B_T at least the largest
//       |d . ((E1 q) x (E2 q))| over unit q: that value, a 4 x 4 eigenproblem's with a margin
//       for its rounding (patch_radius.cpp, largest_quadratic), capped by the product of the
//       two smallest of ||P E1||_2, ||P E2||_2, ||P E3||_2 (E3 = E2 - E1; P = I - d d^T, the
//       projection across d; ||.||_2 the largest singular value), L0 = |e1| + |e2|,
//       L1 = ||E1||_F + ||E2||_F.
//       Why: d . n(q_hat) = c_T + q_hat . (E2^T (d x e1) + E1^T (e2 x d)) + d . ((E1 q_hat) x
//       (E2 q_hat)), and (E1 q) x (E2 q) = (E1 q) x (E3 q) = (E2 q) x (E3 q); the components
//       along d do not enter d . (a x b) = d . (P a x P b), so each is at most
//       ||P Ei||_2 ||P Ej||_2 ||q||^2 (Frobenius norms, the bound before, are up to sqrt(3)
//       larger each: measured, the knot's cones query at amplitude 0.05 went from 90.1k node
//       tests per step to 82.5k, the elephant's from 41.2k to 33.1k); a computed edge is off by
//       at most 2 eta, which moves the cross product by at most 2 eta (|e1(q_hat)| +
//       |e2(q_hat)|) + 4 eta^2. The product bound is reached only where one edge's rates turn
//       the other's by a quarter turn about d; the exact value is smaller elsewhere (measured,
//       node tests of the cones query per step, 20 steps at amplitude 0.05, the product bound
//       against the exact value: the knot 63.7k against 52.1k, the dragon 141.6k against
//       128.5k, the elephant 28.6k against 26.5k). The exact value is formed only for the
//       triangles whose root with the product bound would lower their set's radius.
//       The condition is a quadratic in s: below its positive root it holds.
//  (ii) the projection along d of the boundary stays one simple closed polygon for every t of
//       the step when it is one at rest and, for every boundary vertex p and boundary edge
//       (a, b) not containing p, with nu the unit direction of the projection plane from p's
//       closest point on the edge to p (at rest, in projection), both ends e of the edge have
//         nu . (p - e) > N_pe s + 2 eta,   N_pe = ||(U_hat_p - U_hat_e)^T nu||.
//       Why: nu . (p - e) changes by nu^T (U_hat_p - U_hat_e) q_hat, at most N_pe s, and by the
//       rounding at most 2 eta; while both stay positive, p lies beyond the line
//       nu . x = max(nu . a, nu . b), which no point of the edge crosses, so p is not on the
//       edge in projection (nu is in the plane, so nu . x is the same for x and its
//       projection). So along the path from rest to the step's start (q_hat scaled from 0,
//       then the rounding switched on, every vertex moving linearly) and along the step, no
//       vertex ever lies on an edge not containing it in projection, and simple_contour.hpp's
//       lemma carries the rest polygon's simplicity to every t. Only the parting along nu
//       counts: sliding along the edge, or along d, does not close the gap.
//       Small fans: a vertex-edge pair whose vertex is next to the edge along the cycle
//       (edges (p, a) and (a, b) consecutive: p against (a, b), or b against (p, a)) is left
//       out when their shared vertex a lies in at most two triangles of S: below (i)'s
//       radius, (i) keeps the vertex off the edge. The cycle passes a once, so the edges at a
//       of S's triangles, but (p, a) and (a, b), cancel in pairs, and only triangles at a
//       hold them. One triangle at a holds both: it is (p, a, b), positive in projection, so p
//       is off the line through a and b. Two share the cancelling edge: (p, a, c) and
//       (a, b, c) in the cycle's orientation. Each, positive in projection, turns the ray
//       from a along one of its edges at a counter-clockwise onto the other by an angle in
//       (0, pi): the ray a b onto a c, then a c onto a p, in total by an angle in (0, 2 pi).
//       So the rays from a to p and to b differ: neither of p and b (apart from a in
//       projection) lies on the other's edge. Measured, node tests of the cones query per
//       step, 20 steps at amplitude 0.05, before and after: the knot 66.4k against 63.7k,
//       the dragon 151.7k against 141.6k, the lion 47.5k against 39.3k.
// The radius of S is the smallest of the roots of (i) over its triangles and of (ii) over its
// boundary's vertex-edge pairs, 0 when a hypothesis fails at rest.
//
// FLOATING POINT. eta bounds the rounding of SubspaceModel::position (an r-term dot product and
// an addition per coordinate, as the certificates allow for: triangle_pair_bound.cpp), doubled.
// The rest quantities (c_T, the gaps nu . (p - e), the norms) are computed in floating
// point and moved by kRadiusMargin relative to their magnitudes, far beyond their rounding, so
// each is a bound of the exact value in the safe direction; the rest polygon's simplicity is
// decided by simple_contour.hpp's certified test; each radius is lowered by the same margin.
// The rates' norms are scaled ones (stableNorm): plain norms square the entries, which
// underflow to 0 for bases of entries near 1e-160 and below, moved by coordinates near 1e160,
// and would leave the radii unbounded; products in the subnormal range, which err absolutely,
// are covered by kUnderflowAllowance (normal_cone.hpp), added to each rate and to the
// quadratic term, whose products of two rates underflow first. A basis whose blocks' norms lie
// outside 2^-200..2^200 (entries near 1e-160, or near 1e170, whose products overflow) is
// bounded as the basis times 2^-k instead, which every entry holds exactly (else it is not
// scaled), k the exponent of its largest block's norm: the computed positions are the same
// products with the coordinates times 2^k, so a radius R' of those is the radius R' 2^-k of
// the original, exact in the normal range (0 below it, infinity above it, where every finite
// norm is below the original's radius). A mode-free set (every rate 0) gets an infinite radius
// without dividing by zero.
// The step's norm s is computed in floating point too (relative error near 1e-15, inside the
// margin). d must be unit to rounding: the contour's gaps are taken in the projection
// I - d d^T, which with |d| off 1 keeps part of the extent along d (and the normals' quadratic
// term is not scaled by |d|). The mean normal, the normalized sum of the set's area-weighted
// normals, is unless the sum's squares are subnormal (total area below about 1e-154,
// coordinates near 1e-80): its plain norm is then off by up to tens of percent (measured:
// radii 1.2% above the theorem's), and such a set gets no radius. A cone's axis is a centre
// of length at least 1e-2, normalized (cone_axis.hpp): unit to rounding whatever the normals'
// scale.
//
// Which sets: every node of at least kSmallestConeNode triangles whose boundary is a simple cycle;
// the union of every two patches sharing an edge (the largest nodes with a radius, each holding
// the nodes below it): a node pair under two such patches is culled by their union's radius; and
// the union of two adjacent nodes (leaves too, under patches or not), each of at least
// kSmallestPairPart triangles and a simple cycle, within kLargestUnionRatio in size (as the
// traversal pairs them), kept where it beats their patches' union (0 unless both lie under
// patches). Two nodes are adjacent when triangles of theirs share a vertex. Where their union's
// boundary is not one simple cycle (union_is_simple_cycle: nodes that meet at vertices only, or
// pinched), the set is the union bridged by every other triangle at a vertex both nodes hold: the
// theorem proves no two of its triangles sharing no vertex touch, the pair's among them. A set
// whose boundary is still not one simple cycle gets no radius. Each set is bounded along its
// area-weighted mean normal at rest and, where some triangle leans more than 60 degrees from
// that, along the axis of a nearly smallest cone around its normals too (axis_to_try,
// cone_axis.hpp), and keeps the larger radius: on a curved set the mean leans past a right
// angle from some triangle where the axis may not.
// Measured, node tests per step of the cones query, 20 steps at amplitudes 0.01 / 0.05 (`sscc
// selfccd --mesh ../shared/data/meshes/M.off --steps 20 --amplitude A --methods cones --threads
// 1`): with the mean normal alone against with the axis too, the knot 8.7k / 52.1k against
// 7.3k / 51.0k, the dragon 47.1k / 128.5k against 29.6k / 123.1k, the elephant 16.3k / 26.5k
// against 9.8k / 22.9k, the lion 16.6k / 38.0k against 7.6k / 34.6k, the 75k bunny 12.7k /
// 33.2k against 6.6k / 27.1k; before and after the bridged sets and the pairs outside patches (the node pairs'
// radii tested on every step either way), the knot 11.8k / 69.6k against 8.9k / 66.4k, the
// dragon 61.8k / 156.2k against 50.4k / 151.7k, the elephant 20.2k / 31.6k against 16.5k / 29.0k,
// the lion 20.0k / 51.5k against 17.2k / 47.5k (about a third of the node pairs the traversal
// visited on the knot at 0.05 met at vertices only).
//
// Cost: built once per hierarchy, on every thread (SelfCcd::prepare, which builds them with
// the rest of the culls' data for the `selfccd` command's four option sets, two threads, took
// 1.67 s for the 15k-triangle lion, 1.97 s for the 20k dragon and 10.3 s for the 75k bunny;
// 1.37 s, 1.59 s and 9.58 s before the cones' axes, timed alternately); a query tests a node
// in O(1) and a node pair with at most two lookups in short contiguous lists
// (PairRadiusTable).
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <utility>
#include <vector>

#include "query/contour.hpp"
#include "sscc/bvh/subspace_bvh.hpp"

namespace sscc::detail {

/// Relative margin of every rest quantity and radius (see FLOATING POINT above): far above the
/// few roundings each carries (about 1e-15 relative), far below what matters for culling.
/// Smaller than the rounding: radii that could cull a contact; larger: smaller radii.
inline constexpr double kRadiusMargin = 1e-9;

/// Radii of node pairs, listed under the pair's smaller node with its partners contiguous:
/// the query looks up every node pair it visits, and a node has few partners (measured: with
/// a hash map the lookups took 5% of the lion's cones query at amplitude 0.01).
class PairRadiusTable {
 public:
  PairRadiusTable() = default;
  /// `pairs`: (a << 32 | b, radius) with a < b < node_count, each pair once.
  PairRadiusTable(int node_count, std::vector<std::pair<std::uint64_t, double>> pairs);
  /// The radius of nodes a and b (either order), 0 when they have none.
  double radius(int a, int b) const {
    if (a > b) std::swap(a, b);
    for (int i = offsets_[a]; i < offsets_[a + 1]; ++i) {
      if (partners_[i] == b) return radii_[i];
    }
    return 0.0;
  }
  int size() const { return static_cast<int>(partners_.size()); }
  /// visit(a, b, radius) for every pair, a < b.
  template <typename Visit>
  void for_each(Visit visit) const {
    for (int a = 0; a + 1 < static_cast<int>(offsets_.size()); ++a) {
      for (int i = offsets_[a]; i < offsets_[a + 1]; ++i) visit(a, partners_[i], radii_[i]);
    }
  }

 private:
  std::vector<int> offsets_{0};  // node a's partners: [offsets_[a], offsets_[a + 1])
  std::vector<int> partners_;
  std::vector<double> radii_;
};

/// Node pairs whose smaller part has fewer triangles get no radius of their own: a pair of
/// single triangles sharing an edge holds no considered pair. Leaves of two to four triangles
/// are paired (measured with the table below, Valgrind's instruction counts of the cones
/// query, 10 steps, pairs of nodes of at least 2 triangles against at least 5: the lion at
/// amplitude 0.01 221M against 239M, at 0.05 745M against 870M, the elephant at 0.01 101M
/// against 108M, the knot 98.7M against 99.7M; 1 instead of 2 saved 0.3% more). Higher: fewer
/// culls along the patches' seams; lower: pairs that cull nothing.
inline constexpr int kSmallestPairPart = 2;

class PatchRadii {
 public:
  PatchRadii(const SubspaceBvh& bvh, const NodeBoundaries& boundaries);

  /// Node n's radius: no two of its triangles sharing no vertex touch during a step whose
  /// ends' scaled norms are below it (0 when none is proven).
  double node_radius(int n) const { return node_radius_[n]; }
  /// Whether node n's radius is the one its mean normal at rest proves (not a cone's axis,
  /// cone_axis.hpp, which proved a larger one): the direction the cones formed per step take
  /// (patch_cull.hpp). False for nodes without a radius.
  bool proven_along_mean(int n) const { return along_mean_[n] != 0; }
  /// The radius of the disjoint nodes a and b together: no triangle of a touches one of b
  /// sharing no vertex with it during a step whose ends' scaled norms are below it (0 when
  /// none is proven): the larger of the union of the patches holding them and, for adjacent
  /// nodes of similar sizes, of their own union.
  double pair_radius(int a, int b) const;
  /// Whether s is below pair_radius(a, b), with the lookups skipped where per-node maxima
  /// already rule it out (the traversal asks for every node pair it visits).
  bool pair_below(int a, int b, double s) const {
    const int patch_a = patch_[a], patch_b = patch_[b];
    if (patch_a >= 0 && patch_b >= 0 && s < largest_patch_pair_[patch_a] && s < largest_patch_pair_[patch_b] &&
        s < patch_pair_radius(patch_a, patch_b)) {
      return true;
    }
    return s < largest_node_pair_[a] && s < largest_node_pair_[b] && s < node_pair_radius(a, b);
  }

  /// The fraction of the nodes with a radius whose radius exceeds s (0 when none has one):
  /// how much of the hierarchy a step of norm s can cull.
  double fraction_above(double s) const;
  /// The same for the radii of the node pairs.
  double node_pair_fraction_above(double s) const;
  /// The same for the patches' radii: how much a step of norm s culls at the top of the
  /// proven nodes, where the cones formed from the positions cull most.
  double patch_fraction_above(double s) const;
  /// The fraction of the mesh's triangles under patches of more than kRefitTriangleLimit
  /// triangles whose radius exceeds s: what a step of norm s leaves to those patches' subspace
  /// boxes (NodeBounds::kHybrid), never refitted below them.
  double large_patch_coverage_above(double s) const;

  /// Patches (nodes with a radius whose ancestors have none), pairs of adjacent patches and
  /// pairs of adjacent nodes with a radius of their own, for tests and statistics.
  int patch_count() const { return patch_count_; }
  int patch_pair_count() const { return patch_pairs_.size(); }
  int node_pair_count() const { return node_pairs_.size(); }

 private:
  /// The union of the patches holding a and b (a patch's own radius when they share one).
  double patch_pair_radius(int patch_a, int patch_b) const {
    return patch_a == patch_b ? node_radius_[patch_a] : patch_pairs_.radius(patch_a, patch_b);
  }
  /// The radius of the union of the patches holding nodes a and b (0 unless both have one).
  double patches_pair_radius(int a, int b) const {
    return patch_[a] >= 0 && patch_[b] >= 0 ? patch_pair_radius(patch_[a], patch_[b]) : 0.0;
  }
  double node_pair_radius(int a, int b) const { return node_pairs_.radius(a, b); }

  std::vector<double> node_radius_;
  std::vector<char> along_mean_;  // proven_along_mean per node
  std::vector<int> patch_;        // per node: the largest node holding it with a radius, or -1
  PairRadiusTable patch_pairs_;   // adjacent patches
  PairRadiusTable node_pairs_;    // adjacent nodes under patches, where their union beats their patches'
  // Per patch, the largest radius patch_pair_radius can return for it; per node, the largest
  // of its node pairs (0 for none).
  std::vector<double> largest_patch_pair_, largest_node_pair_;
  int patch_count_ = 0;
  // The positive radii of the nodes, the node pairs and the patches, ascending.
  std::vector<double> sorted_radii_, sorted_pair_radii_, sorted_patch_radii_;
  // The radii of the patches of more than kRefitTriangleLimit triangles, ascending, each with
  // the fraction of the mesh's triangles in it and the patches after it.
  std::vector<std::pair<double, double>> large_patch_coverage_;
};

}  // namespace sscc::detail
