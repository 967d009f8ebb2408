// Which node pairs the pair certificates resolve below themselves: the precomputation stores
// children for near pairs only, and the query's estimate of its uncertified work weighs them.
// Private to the library.
#pragma once

#include <algorithm>

#include "sscc/bvh/subspace_bvh.hpp"
#include "sscc/certificates/certificates.hpp"

namespace sscc::detail {

/// Whether the rest boxes of nodes x and y lie within kNearPairMargin of the larger one's
/// largest half extent of each other.
inline bool near_at_rest(const SubspaceBvh& bvh, int x, int y) {
  const SubspaceBvh::SubspaceBound a = bvh.subspace_bound(x), b = bvh.subspace_bound(y);
  const double margin = kNearPairMargin * std::max(a.half.maxCoeff(), b.half.maxCoeff());
  return ((a.centre - b.centre).cwiseAbs() - a.half - b.half).maxCoeff() <= margin;
}

}  // namespace sscc::detail
