// Normal-cone culling for continuous self-collision: a proof, per node (or pair of nodes) of
// the hierarchy, that no two non-adjacent triangles under it touch at any t of the step.
// Private to the library; SelfCcd's traversal calls it when SelfCcdOptions::use_normal_cones.
//
// THEOREM. Let S be a set of oriented triangles of the mesh (a 2-chain) moving linearly over
// t in [0, 1], and d a fixed unit vector. Suppose, for every t in [0, 1]:
//  (i)  every triangle T of S has d . n_T(t) > 0 (n_T = (x1 - x0) x (x2 - x0)): its
//       projection on the plane orthogonal to d is a non-degenerate, positively oriented
//       triangle;
//  (ii) the boundary chain dS (each edge with its net coefficient: (a, b) and (b, a) cancel;
//       an edge in two triangles of one orientation counts twice) projects, along d, to one
//       simple closed polygon: its vertices are distinct and no two of its projected edges
//       share a point except consecutive edges at their common vertex.
// Then no two triangles of S that share no vertex touch at any t in [0, 1].
//
// Two tests decide (ii) for every t of the step: the star-shaped test (contour.hpp: every
// boundary edge turns counter-clockwise about a moving centre c(t), and the walk winds once)
// and, when it fails, the general one (simple_contour.hpp: simple at t = 0, and no vertex
// ever crosses an edge). Why the first implies (ii): dS is a cycle (every vertex is entered as
// often as it is left), so it splits into closed walks; every boundary edge turns
// counter-clockwise about pi(c) by an angle in (0, pi); a closed walk's angles sum to 2 pi w
// with w >= 1, and each edge crosses the ray at most once, from its clockwise side, so at
// t = 0 the crossings number the sum of the w's: one walk, winding once. The angles never
// reach 0 or pi, so the total stays 2 pi for every t. A closed walk sweeping a total of exactly
// 2 pi strictly monotonically meets every direction from pi(c) once: its vertices are
// distinct, and the projected boundary is a simple closed polygon.
//
// PROOF. Fix t; project along d (pi). By (i) each projected triangle covers its interior once, positively; for a point
// p not on a projected edge, the number of triangles whose projection contains p is the sum of their boundaries'
// winding numbers about p, which is the winding number of pi(dS) about p (winding numbers are
// additive over chains and twins cancel): a simple closed polygon winds 0 or +-1 about a
// point off it and the count is not negative, so it is 0 or 1: projected interiors are disjoint,
// and no open set is covered twice. Now let T1, T2 in S share no vertex and touch at x;
// p = pi(x). (a) If p is interior to pi(T1) (or pi(T2)), pi(T2) (a non-degenerate triangle
// containing p) overlaps it in an open set: covered twice. (b) Otherwise x lies on an edge or
// vertex of both. Let f1 be the smallest feature of T1 containing x. If f1 is an edge not in
// dS, its twin T1' (of opposite orientation; T1' != T2 since it shares f1's vertices with T1)
// projects on the other side of pi(f1), so T1 and T1' cover a disc about p and T2's wedge at p
// is covered twice. If f1 is a vertex v with no edge of dS at it, the triangles around v have
// a link (their edges opposite v) that is a cycle (the edges at v cancel), every link edge
// turns counter-clockwise about p (each such triangle is positive), so the fan covers a
// punctured disc about p at least once and T2 (which does not contain v) covers part of it a
// second time. The same holds for f2. What remains is f1 and f2 both on dS (an edge of dS, or
// a vertex on one): two distinct, non-consecutive parts of the simple boundary polygon (they
// share no vertex) meeting at p, which (ii) excludes. So no such x exists.
//
// What the hypotheses cover: degenerate or zero-area triangles fail (i) (a strict
// inequality); duplicated vertices (two indices, one position) are distinct vertices, covered
// by (b); a T-junction leaves both sides' edges in dS running opposite ways along one segment,
// which (ii) rejects; non-manifold edges (three or more triangles) leave net coefficients that
// either make dS revisit a vertex or double-cover a side of the edge, both excluded above;
// inconsistently oriented neighbours both project positively only if they overlap, and their
// shared edge does not cancel; a closed surface has an empty boundary (k = 0) and a
// set with several components or holes several loops: never culled. Contact here is touching
// (distance 0): queries with a minimum separation d > 0 do not use this cull.
//
// FLOATING POINT: (i) and (ii) are decided for the vertex positions exactly as the query
// computes them, each quadratic through its three Bernstein coefficients with certified signs
// (normal_cone.hpp), or for (i) through a cone of directions bounding the coefficients whose
// angles carry a slack far above their rounding (normal_cone.hpp, kAngleSlack); d and c are
// arbitrary doubles, so their rounding does not matter. The winding number is counted exactly
// as the crossings of one ray, every vertex's side certified (contour.hpp); the general test's
// box culls are padded for the rounding of the projection (simple_contour.hpp). Whether a node's
// chain is one simple cycle (NodeBoundaries) is only a cheap filter: (ii) implies it.
//
// LITERATURE. Volino and Magnenat-Thalmann (1994) introduced the test: normals in a cone of
// half-angle below 90 degrees plus a projected contour that does not cross itself, for one
// configuration. Provot (1997) used it hierarchically on cloth, bottom-up cones over zones.
// Tang et al. (2009) made the cones continuous: a deforming triangle's normal is a quadratic
// in t whose Bernstein coefficients bound it, as here, but kept no contour test (it is
// approximate; the SSCC paper, section 7, says the same of the usual version). Wang et al.
// (2018) made the contour test cheap and sound with unprojected normal cones: star-shapedness
// of the contour, decided by point-plane classifications of the contour's edges against a
// point, in linear time. We follow that choice of a star-shaped contour, but continuously in
// t (each edge's orientation about a linearly moving centre is a quadratic with Bernstein
// coefficients, the same predicate as a triangle's normal), with the winding number checked
// (a star-shaped walk could wind twice), the boundary chain from static connectivity, and
// every sign certified in floating point. Jagged boundaries of small patches are rarely
// star-shaped about any point, so where that test fails the general one decides (ii) from
// the polygon's simplicity at t = 0 and the vertex-edge events of the step (the 2D analogue
// of continuous collision detection on the contour). Schvartzman et al. (2009) bound normals of reduced
// deformations in O(r) per node; we compute them from the vertex positions the query already
// forms.
#pragma once

#include <Eigen/Core>

#include <array>
#include <functional>
#include <vector>

#include "query/contour.hpp"
#include "query/cull_record.hpp"
#include "query/normal_cone.hpp"
#include "query/simple_contour.hpp"
#include "query/sweep.hpp"
#include "sscc/query/self_ccd.hpp"

namespace sscc::detail {

/// Nodes with fewer triangles are not tested on their own: a leaf's few pairs cost less than
/// the contour test (measured on the lion and the elephant: testing leaves made the query
/// slower). Lower: more culls, each saving less than it costs; higher: fewer culls.
inline constexpr int kSmallestConeNode = kMaxLeafTriangles + 1;
/// Pairs of nodes are tested together only when each has at least this many triangles: the
/// union's contour costs more than descending to a few leaf pairs (measured: unions of small
/// nodes doubled the query's time on the elephant at amplitude 0.01; from 32 the cost and the
/// saving about balance). Lower: more pair culls, costlier; higher: fewer.
inline constexpr int kSmallestUnionPart = 32;

/// Pairs are tested together only when the larger part has at most this many times the
/// smaller's triangles. After a pair fails, the traversal splits the larger part, and each
/// such test costs the larger part's boundary again while the union rarely passes where the
/// whole failed (measured: without it the bunny at amplitude 0.2 spent more on union tests
/// than the culls saved). Higher: more tests of lopsided pairs; lower: none after a failure.
inline constexpr int kLargestUnionRatio = 4;

/// Meshes whose patches proven at rest (the largest nodes the cull accepts for the rest shape
/// held still) average fewer triangles than this are not given the cull: each accepted patch
/// saves about what the normals of its triangles cost. Measured on the meshes of
/// ../shared/data/meshes (mean patch at rest; the cones query's speed against the plain
/// traversal at amplitudes 0.01 / 0.05 / 0.2): the elephant 11.3 triangles, 0.89x / 0.94x /
/// 0.94x; the dragon 11.9, 1.04x / 1.00x / 0.97x; the knot 18.3, 1.12x / 1.11x / 1.01x; the
/// lion 28.5, 1.25x / 1.24x / 1.09x; the 75k bunny 110, 1.58x / 1.38x / 1.00x. Once the node
/// tests became cheaper (sweep.hpp: the interpolated boxes), the knot's cull cost more than it
/// saved: Valgrind's instructions of its cones query over 5 steps at 0.01 / 0.05 / 0.2, 43.3M
/// / 194M / 291M without it against 43.3M / 229M / 379M with it (at 16, the bound before); the
/// default demo's 15k bunny (40.2) keeps it. Lower: the cull where it costs more than it saves;
/// higher: not where it pays.
inline constexpr double kSmallestMeanRestPatch = 20.0;

/// The mean triangle count of the largest nodes cannot_self_touch accepts for the rest shape
/// (0 when none).
double mean_patch_at_rest(const SubspaceBvh& bvh, const NodeBoundaries& boundaries);

/// The cull for one query. Positions x0, x1 belong to the caller, who computes a triangle's
/// vertices when asked through `ensure_triangle` (the triangle's position in the hierarchy's
/// order); nothing here outlives the query. Cones are built bottom-up, once per node reached:
/// a leaf's from its triangles' Bernstein coefficients, a parent's from its children's cones
/// (normal_cone.hpp), so a node's cone costs O(1) once its children's are known and a pair's
/// union costs O(1); the union's boundary costs O(k log k) for k boundary edges.
class PatchCull {
  /// A node's normal cone and the sum of its triangles' coefficient vectors (area-weighted
  /// normals, the axis of its parent's cone).
  struct NodeCone {
    NormalCone cone;
    Eigen::Vector3d normal_sum;
  };

 public:
  using EnsureTriangle = std::function<void(int)>;
  /// The per-node caches of one query, kept for the next by whoever lends them (the
  /// constructor resets them): reused, they cost no allocation (step_buffers.hpp).
  struct Caches {
    LazyBoxes<NodeCone> cones;
    LazyBoxes<char> self_verdicts;          // cannot_self_touch's answers, once per node
    std::vector<DirectedEdge> union_chain;  // scratch of cannot_touch
  };
  PatchCull(const SubspaceBvh& bvh, const NodeBoundaries& boundaries, const std::vector<Eigen::Vector3d>& x0,
            const std::vector<Eigen::Vector3d>& x1, EnsureTriangle ensure_triangle, Caches& caches);

  /// Whether node n's triangles provably never touch one another during the step (tried for
  /// nodes of at least kSmallestConeNode triangles).
  bool cannot_self_touch(int n);
  /// Whether the union of the disjoint nodes a and b provably has no touching pair (tried when
  /// cannot_self_touch has already proven each, with at least kSmallestUnionPart triangles).
  bool cannot_touch(int a, int b);

 private:
  const NodeCone& cone(int n);
  /// Condition (ii) of the theorem for a simple cycle: the cheap star-shaped test, else the
  /// general one.
  bool contour_stays_simple(const Eigen::Vector3d& d, const std::vector<DirectedEdge>& chain) const;
  int triangle_count(int n) const;
  NodeCone leaf_cone(const SubspaceBvh::Node& leaf);

  const SubspaceBvh& bvh_;
  const NodeBoundaries& boundaries_;
  const std::vector<Eigen::Vector3d>& x0_;
  const std::vector<Eigen::Vector3d>& x1_;
  EnsureTriangle ensure_triangle_;

  LazyBoxes<NodeCone>& cones_;
  CullRecord self_tests_, pair_tests_;  // the contour tests, self and pair apart (cull_record.hpp)
  LazyBoxes<char>& self_verdicts_;
  std::vector<DirectedEdge>& union_chain_;
};

}  // namespace sscc::detail
