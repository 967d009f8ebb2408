#include "certificates/box_box_bound.hpp"

#include <algorithm>
#include <cmath>

namespace sscc::detail {

double box_box_radius(const SubspaceBvh& bvh, int a, int b) {
  const SubspaceBvh::SubspaceBound x = bvh.subspace_bound(a);
  const SubspaceBvh::SubspaceBound y = bvh.subspace_bound(b);
  double radius = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double gap = std::fabs(x.centre[k] - y.centre[k]) - x.half[k] - y.half[k];
    if (!(gap > 0.0)) continue;
#ifdef SSCC_MUTANT_BOX_BOX_SINGLE_MODE
    const double rate = (x.mean_modes.row(k) - y.mean_modes.row(k)).lpNorm<Eigen::Infinity>() + x.rate[k] + y.rate[k];
#else
    const double rate = (x.mean_modes.row(k) - y.mean_modes.row(k)).norm() + x.rate[k] + y.rate[k];
#endif
    radius = std::max(radius, rate > 0.0 ? gap / rate : INFINITY);
  }
  // The bound only culls: shrunk so that its own rounding never culls a closer pair.
  return radius * (1.0 - kBoxBoxRoundingShrink);
}

}  // namespace sscc::detail
