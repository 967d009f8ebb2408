// The fraction of an ascending list of radii that exceed a norm: how much of a hierarchy a
// step of that norm can cull (the certificates' and the cones' gating rules, self_ccd.cpp).
#pragma once

#include <algorithm>
#include <vector>

namespace sscc::detail {

/// The fraction of `sorted` (ascending) strictly above s; 0 for an empty list.
inline double fraction_above(const std::vector<double>& sorted, double s) {
  if (sorted.empty()) return 0.0;
  const auto above = sorted.end() - std::upper_bound(sorted.begin(), sorted.end(), s);
  return static_cast<double>(above) / static_cast<double>(sorted.size());
}

}  // namespace sscc::detail
