// Pairs of leaves that hold no triangle pair a query considers: every triangle of one shares
// a vertex with every triangle of the other, or the pair is excluded (excluded_pairs.hpp).
// Neighbouring leaves of a fine mesh often are such pairs (a third of the leaf pairs the
// dragon's traversal reaches at amplitude 0.05); their box tests and triangle loops can find
// nothing, so the traversal skips them first. Exact: a pair is listed only when each of its
// triangle pairs is checked not considered. Private to the library.
#pragma once

#include <vector>

#include "sscc/bvh/subspace_bvh.hpp"

namespace sscc::detail {

class UnconsideredLeafPairs {
 public:
  /// Lists, for each leaf, the leaves that share a vertex with it and hold no considered
  /// pair with it (O(triangles times the leaves around each)).
  explicit UnconsideredLeafPairs(const SubspaceBvh& bvh);
  /// Whether leaves a and b of the hierarchy (a != b) hold no considered triangle pair; false
  /// for nodes that are not leaves.
  bool contains(int a, int b) const {
    for (int k = offsets_[a]; k < offsets_[a + 1]; ++k) {
      if (partners_[k] == b) return true;
    }
    return false;
  }

 private:
  std::vector<int> offsets_;   // per node, into partners_ (node count + 1 values)
  std::vector<int> partners_;  // each leaf's partners, sorted
};

}  // namespace sscc::detail
