// Both kernels decide a question about four points moving linearly over t in [0, 1]:
//   vertex-face: x0, x1, x2 = the triangle f0, f1, f2; x3 = the vertex v;
//   edge-edge:   x0, x1 = edge a; x2, x3 = edge b.
// With e1 = x1 - x0, e2 = x2 - x0, e3 = x3 - x0, the four are coplanar where the cubic
// det(e1, e2, e3) vanishes, and every 2D orientation the inside tests need, in the
// coordinate plane that drops axis k, is a combination of the k-th components of the cross
// products e1 x e2, e1 x e3 and e2 x e3 (quadratics in t):
//   vertex-face: orient(f0, f1, v) = K13, orient(f1, f2, v) = K12 + K23 - K13,
//                orient(f2, f0, v) = -K23;
//   edge-edge:   orient(a0, a1, b0) = K12, orient(a0, a1, b1) = K13,
//                orient(b0, b1, a0) = K23, orient(b0, b1, a1) = K12 + K23 - K13.
#pragma once

#include <Eigen/Core>

#include <array>

namespace sscc::ccd {

enum class PrimitivePair { kVertexFace, kEdgeEdge };

struct FourPointMotion {
  PrimitivePair pair;
  std::array<Eigen::Vector3d, 4> t0;
  std::array<Eigen::Vector3d, 4> t1;
};

/// Number of 2D orientations per coordinate plane the inside test uses.
inline int orientation_count(PrimitivePair pair) { return pair == PrimitivePair::kVertexFace ? 3 : 4; }

}  // namespace sscc::ccd
