// The descent rule of every node-pair traversal (self and between objects): split the node
// with more triangles, so that the two sides stay of similar size; a leaf never splits.
// Private to the library.
#pragma once

#include "sscc/bvh/subspace_bvh.hpp"

namespace sscc::detail {

/// Whether the descent from pair (a, b) splits a (else b): the node with more triangles, a on
/// ties; a leaf never splits. The precomputation's pair certificates follow the same rule.
inline bool splits_first(const SubspaceBvh::Node& na, const SubspaceBvh::Node& nb) {
  return !na.is_leaf() && (nb.is_leaf() || na.triangle_end - na.triangle_begin >= nb.triangle_end - nb.triangle_begin);
}

/// For nodes a (of tree_a) and b (of tree_b), not both leaves: calls visit(c, b) for every
/// child c of a, or visit(a, c) for every child c of b, whichever node has more triangles.
template <typename Visit>
void descend_larger(const SubspaceBvh& tree_a, int a, const SubspaceBvh& tree_b, int b, Visit visit) {
  const SubspaceBvh::Node& na = tree_a.nodes()[a];
  const SubspaceBvh::Node& nb = tree_b.nodes()[b];
  const bool split_a = splits_first(na, nb);
  const SubspaceBvh::Node& split = split_a ? na : nb;
  for (int c = split.first_child; c < split.first_child + split.child_count; ++c) {
    split_a ? visit(c, b) : visit(a, c);
  }
}

}  // namespace sscc::detail
