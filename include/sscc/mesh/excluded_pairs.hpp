// Triangle pairs that self-collision queries ignore besides the adjacent ones: on request,
// the non-adjacent pairs that already touch in the rest shape. Scanned and modelled meshes
// often touch themselves at rest (a finger laid on a palm, a fold, a seam); continuous
// collision detection assumes a contact-free start, and certificates of such a mesh are 0
// wherever those pairs are, so simulators exclude them as they exclude adjacent pairs.
//
// Semantics, the same in every query, the certificates, exhaustive testing and the FCL
// comparison: a triangle pair is *considered* when it is neither adjacent nor excluded. A
// considered pair is reported when one of its vertex-face or edge-edge features touches; a
// feature is tested when some considered pair contains it. So an excluded pair is never
// reported, while a feature it shares with a considered pair still is (with that pair).
//
// Guarantee of touching_at_rest(): exact. Every non-adjacent pair whose closed triangles
// share a point at the rest positions (ccd::triangles_intersect, exact predicates), and no
// other, is in the set.
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "sscc/mesh/triangle_mesh.hpp"

namespace sscc {

class ExcludedPairs {
 public:
  /// No pair excluded.
  ExcludedPairs() = default;
  /// The given pairs of a mesh of `triangle_count` triangles (in either order, repeats
  /// merged). Throws std::invalid_argument for an index out of range or a pair (t, t).
  ExcludedPairs(int triangle_count, std::vector<std::pair<int, int>> pairs);

  /// The non-adjacent pairs of `mesh` that share a point at its rest positions (exact).
  static ExcludedPairs touching_at_rest(const TriangleMesh& mesh);

  bool empty() const { return pairs_.empty(); }
  int size() const { return static_cast<int>(pairs_.size()); }
  /// Sorted, first < second.
  const std::vector<std::pair<int, int>>& pairs() const { return pairs_; }
  /// The number of triangles of the mesh the set was made for (0 for the empty set).
  int triangle_count() const { return offsets_.empty() ? 0 : static_cast<int>(offsets_.size()) - 1; }

  /// Whether the pair (a, b), in either order, is excluded. Inline: the queries ask it for
  /// every non-adjacent triangle pair whose boxes meet; most triangles have no partner.
  bool contains(int a, int b) const {
    if (pairs_.empty()) return false;
    const int* begin = partners_.data() + offsets_[a];
    const int* end = partners_.data() + offsets_[a + 1];
    return begin != end && std::binary_search(begin, end, b);
  }

 private:
  std::vector<std::pair<int, int>> pairs_;
  std::vector<int> offsets_;   // CSR: the partners of triangle t, sorted, are
  std::vector<int> partners_;  // partners_[offsets_[t] .. offsets_[t + 1])
};

}  // namespace sscc
