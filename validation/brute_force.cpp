#include "brute_force.hpp"

#include <algorithm>

#include "sscc/ccd/kernels.hpp"

namespace sscc::validation {

double triangle_pair_first_contact(const std::vector<Eigen::Vector3d>& x0, const std::vector<Eigen::Vector3d>& x1,
                                   const Triangle& a, const Triangle& b, const ccd::CcdOptions& options) {
  double earliest = 2.0;
  const auto consider = [&](const ccd::CcdResult& r) {
    if (r.hit) earliest = std::min(earliest, r.toi);
  };
  for (int side = 0; side < 2; ++side) {
    const Triangle& s = side == 0 ? a : b;
    const Triangle& f = side == 0 ? b : a;
    for (int v : s) {
      consider(ccd::vertex_face_ccd(x0[v], x0[f[0]], x0[f[1]], x0[f[2]], x1[v], x1[f[0]], x1[f[1]], x1[f[2]], options));
    }
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const int a0 = a[i], a1 = a[(i + 1) % 3], b0 = b[j], b1 = b[(j + 1) % 3];
      consider(ccd::edge_edge_ccd(x0[a0], x0[a1], x0[b0], x0[b1], x1[a0], x1[a1], x1[b0], x1[b1], options));
    }
  }
  return earliest;
}

}  // namespace sscc::validation
