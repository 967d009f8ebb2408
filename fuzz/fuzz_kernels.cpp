// Any 24 doubles as a vertex-face and an edge-edge query (the eight points at t = 0, then at
// t = 1): no crash, no NaN out (toi in [0, 1], finite parameters), and the decision unchanged
// when every coordinate is scaled by the same power of two (exact unless it overflows or
// underflows, which the target checks first).
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "sscc/ccd/kernels.hpp"

namespace {

using Points = std::array<Eigen::Vector3d, 8>;

sscc::ccd::CcdResult run(bool vertex_face, const Points& p) {
  return vertex_face ? sscc::ccd::vertex_face_ccd(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7])
                     : sscc::ccd::edge_edge_ccd(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]);
}

/// The points scaled by 2^k, or false when that is not exact (overflow, or a coordinate
/// losing bits below the normal range).
bool scaled(const Points& p, int k, Points& out) {
  for (int i = 0; i < 8; ++i) {
    for (int c = 0; c < 3; ++c) {
      const double x = std::ldexp(p[i][c], k);
      if (!std::isfinite(x) || std::ldexp(x, -k) != p[i][c]) return false;
      out[i][c] = x;
    }
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 24 * sizeof(double) + 1) return 0;
  Points p;
  for (int i = 0; i < 8; ++i) std::memcpy(p[i].data(), data + 24 * i, 24);
  for (const Eigen::Vector3d& x : p) {
    if (!x.allFinite()) return 0;  // refused with std::invalid_argument by contract
  }
  const int k = static_cast<int>(static_cast<std::int8_t>(data[24 * sizeof(double)]));
  for (bool vertex_face : {true, false}) {
    const sscc::ccd::CcdResult r = run(vertex_face, p);
    if (!(r.toi >= 0.0 && r.toi <= 1.0) || !std::isfinite(r.params[0]) || !std::isfinite(r.params[1])) std::abort();
    Points q;
    if (scaled(p, k, q) && run(vertex_face, q).hit != r.hit) std::abort();
  }
  return 0;
}
