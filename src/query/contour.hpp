// Boundary chains of triangle sets and the continuous star-shaped contour test, the second
// half of the normal-cone cull (query/patch_cull.hpp states the theorem both serve).
// Private to the library.
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

#include "sscc/bvh/subspace_bvh.hpp"

namespace sscc::detail {

/// A directed mesh edge (from, to), vertex indices.
using DirectedEdge = std::array<int, 2>;

/// The boundary of the 2-chain whose triangles' directed edges are given: each undirected
/// edge keeps its net coefficient (count of (a, b) minus count of (b, a)), and appears that
/// many times in the direction of its sign. Twins cancel; an edge shared by two triangles of
/// the same orientation appears twice. Sorted by (from, to).
std::vector<DirectedEdge> boundary_chain(std::vector<DirectedEdge> edges);

/// Whether the chain is one closed walk through distinct vertices (every vertex has exactly
/// one outgoing and one incoming edge, all connected). Empty chains are not.
bool is_simple_cycle(const std::vector<DirectedEdge>& chain);

/// Whether the boundary of the sum of two 2-chains whose boundaries a and b (sorted) are simple
/// cycles is one simple cycle, in O(k log k) for k edges: then `sum` holds it (unsorted), a
/// and b without the edges whose reverses the other holds. True only when it is; false may
/// also be a simple sum of chains glued along several paths (a handle), only a lost cull.
///
/// Why c >= 1 cancelled edges and c + 1 shared vertices make one simple cycle: the cancelled
/// edges P of a (their reverses in b) form m >= 1 disjoint paths over c + m vertices, all
/// shared (were P all of a, its c vertices could not be c + 1 shared ones), so m = 1 and no
/// shared vertex is off P. P's inner vertices lose all four edges; each end keeps one edge of
/// a and one of b, one entering and one leaving (a's edge on P enters it exactly when b's
/// reverse leaves it); every other vertex keeps its two edges of one chain. a without P is one
/// path between P's ends, b without P's reverse another, disjoint but for those ends; they
/// are not one edge each, running opposite ways (that pair would have cancelled into P).
bool union_is_simple_cycle(const std::vector<DirectedEdge>& a, const std::vector<DirectedEdge>& b,
                           std::vector<DirectedEdge>& sum);

/// Each node's boundary chain and whether it is a simple cycle, from connectivity alone
/// (fixed for the hierarchy; built once). Children's chains summed give the parent's. Also
/// each node's parent, for the patches of patch_radius.hpp.
class NodeBoundaries {
 public:
  explicit NodeBoundaries(const SubspaceBvh& bvh);
  const std::vector<DirectedEdge>& chain(int n) const { return chains_[n]; }
  bool simple_cycle(int n) const { return simple_cycle_[n] != 0; }
  /// Node n's parent; -1 for the root.
  int parent(int n) const { return parents_[n]; }

 private:
  std::vector<std::vector<DirectedEdge>> chains_;
  std::vector<char> simple_cycle_;
  std::vector<int> parents_;
};

/// Whether the boundary chain `chain` (a cycle: every vertex entered as often as left), seen
/// along d (unit length), stays strictly star-shaped and winds exactly once about the point
/// c(t) moving linearly from the mean of its vertices at t = 0 to that at t = 1, for every t
/// in [0, 1], for the positions exactly as given (it is then one simple closed polygon in
/// projection: query/patch_cull.hpp):
/// every edge (a, b) has d . ((a - c) x (b - c))(t) > 0 (a quadratic, certified through its
/// Bernstein coefficients, normal_cone.hpp), and the edges crossing one ray from c(0) number
/// exactly one (each crossing is counter-clockwise, so that is the winding number; a vertex
/// whose side of the ray rounding could change makes the test fail). Positions of the
/// chain's vertices must be valid in x0 and x1.
bool winds_once_star_shaped(const Eigen::Vector3d& d, const std::vector<DirectedEdge>& chain,
                            const std::vector<Eigen::Vector3d>& x0, const std::vector<Eigen::Vector3d>& x1);

}  // namespace sscc::detail
