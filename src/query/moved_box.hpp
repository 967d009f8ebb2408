// A node's box at a step's end from a box at its start, without computing a vertex: what
// lets a simulator's next step reuse the node boxes of the last one (self_ccd.cpp,
// coherent_sweep). Private to the library.
//
// Guarantee (conservative, under rounding): let `start` hold the computed positions
// x~_v(q_hat0) of node n's vertices (SubspaceModel::position: rest + U_hat_v q_hat, an r-term
// dot product). Then moved_box(start, bound_n, delta, delta_norm, s, r) holds x~_v(q_hat1) for
// each of them, where delta = fl(q_hat1 - q_hat0), delta_norm its norm as computed
// (stableNorm) and s = max(||q_hat0||, ||q_hat1||) as computed.
//
// Proof, coordinate k, u the unit roundoff (epsilon / 2), gamma_m = m u / (1 - m u), m_k the
// node's mean mode row and rate_k >= ||U_hat_v,k - m_k|| for its vertices (subspace_bvh.cpp):
// - Exactly, x_v(q_hat1) - x_v(q_hat0) = U_v,k (q_hat1 - q_hat0), and q_hat1 - q_hat0 = delta
//   + e with |e| <= u |delta| componentwise (one subtraction each): |U_v,k e| <= u ||U_v,k||
//   ||delta||, with ||U_v,k|| <= ||m_k|| + rate_k.
// - U_v,k delta = m_k delta + (U_v,k - m_k) delta: the second term is at most rate_k ||delta||;
//   the first is the shift, computed with error at most gamma_r ||m_k|| ||delta|| (in any
//   order of summation).
// - Each computed position is within gamma_(r+1) (|p_v,k| + ||U_v,k|| ||q_hat||) of the exact
//   one, |p_v,k| <= |centre_k| + half_k.
// - So x~_v,k(q_hat1) - x~_v,k(q_hat0) is within shift_k +- P_k, P_k = rate_k D + R ((||m_k||
//   + rate_k)(D + 2 s) + 2 (|centre_k| + half_k)), for D >= ||delta|| and any R >= gamma_(r+1) +
//   2u. The code takes R = 4 (r + 4) epsilon = 8 (r + 4) u, several times that: the slack covers
//   the rounding of s and of D = delta_norm (1 + R) + (r + 2) denorm_min (stableNorm's error is
//   under (r + 2) u relative, and a few denorm_min absolute when the norm is subnormal).
// - The box's two operations per face (start + shift, then -+ pad) round by at most
//   u (|start_k| + |shift_k|) + u |result| each; pad_k = (P_k + R (max |start_k| + |shift_k|))
//   (1 + R) covers them (the factor (1 + R) the pad's own share, 2u pad_k, and the rounding
//   of pad_k's few operations, relative error under 8u).
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>

#include "sscc/bvh/subspace_bvh.hpp"
#include "sscc/geometry/aabb.hpp"

namespace sscc::detail {

inline Aabb moved_box(const Aabb& start, const SubspaceBvh::SubspaceBound& bound, const Eigen::VectorXd& delta,
                      double delta_norm, double s, int r) {
  const double relative = 4.0 * (r + 4) * std::numeric_limits<double>::epsilon();
  const double d = delta_norm * (1.0 + relative) + (r + 2) * std::numeric_limits<double>::denorm_min();
  Aabb end;
  for (int k = 0; k < 3; ++k) {
    const double shift = bound.mean_modes.row(k).dot(delta);
    const double mean_norm = bound.mean_modes.row(k).cwiseAbs().sum();  // >= its 2-norm, no underflow
    const double magnitude = std::max(std::fabs(start.lo[k]), std::fabs(start.hi[k])) + std::fabs(shift);
    const double pad =
        (bound.rate[k] * d + relative * ((mean_norm + bound.rate[k]) * (d + 2.0 * s) +
                                         2.0 * (std::fabs(bound.centre[k]) + bound.half[k]) + magnitude)) *
            (1.0 + relative) +
        std::numeric_limits<double>::min();
    end.lo[k] = start.lo[k] + shift - pad;
    end.hi[k] = start.hi[k] + shift + pad;
  }
  return end;
}

}  // namespace sscc::detail
