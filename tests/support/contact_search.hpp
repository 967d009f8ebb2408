// A numerical search for the smallest ||q_hat|| that brings two modal triangles into
// contact, independent of the library's bounds: for fixed barycentric points Xa, Xb the
// smallest q_hat with (U_b(Xb) - U_a(Xa)) q_hat = Xa - Xb has squared norm
// d^T (B B^T)^(-1) d (B = U_b(Xb) - U_a(Xa), d = Xa - Xb), so every point pair gives a contact
// configuration and its norm is an upper bound of the true minimum. Sampling a barycentric
// grid on both triangles and refining the best samples by shrinking random moves approaches
// the minimum from above.
#pragma once

#include <Eigen/Core>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "sscc/certificates/triangle_pair_bound.hpp"

namespace sscc::test {

/// ||q_hat|| of the smallest contact of the points with barycentric weights wa, wb
/// (infinity when the relative modes cannot close the gap).
inline double point_pair_contact_norm(const ModalTriangle& a, const Eigen::Vector3d& wa, const ModalTriangle& b,
                                      const Eigen::Vector3d& wb) {
  const Eigen::Vector3d xa = wa[0] * a.rest[0] + wa[1] * a.rest[1] + wa[2] * a.rest[2];
  const Eigen::Vector3d xb = wb[0] * b.rest[0] + wb[1] * b.rest[1] + wb[2] * b.rest[2];
  const Eigen::MatrixXd relative = (wb[0] * b.modes[0] + wb[1] * b.modes[1] + wb[2] * b.modes[2]) -
                                   (wa[0] * a.modes[0] + wa[1] * a.modes[1] + wa[2] * a.modes[2]);
  const Eigen::Vector3d d = xa - xb;
  if (d.squaredNorm() == 0.0) return 0.0;
  // Least-norm solution through complete orthogonal decomposition: exact when solvable.
  const Eigen::VectorXd q = relative.completeOrthogonalDecomposition().solve(d);
  if ((relative * q - d).norm() > 1e-9 * d.norm()) return INFINITY;
  return q.norm();
}

/// The smallest contact norm found by grid sampling (`grid` subdivisions of each triangle's
/// barycentric simplex) and local refinement.
inline double searched_contact_norm(const ModalTriangle& a, const ModalTriangle& b, int grid, std::uint64_t seed) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i <= grid; ++i) {
    for (int j = 0; i + j <= grid; ++j) {
      points.emplace_back(double(i) / grid, double(j) / grid, double(grid - i - j) / grid);
    }
  }
  struct Sample {
    double norm;
    Eigen::Vector3d wa, wb;
  };
  std::vector<Sample> samples;
  for (const auto& wa : points) {
    for (const auto& wb : points) samples.push_back({point_pair_contact_norm(a, wa, b, wb), wa, wb});
  }
  std::sort(samples.begin(), samples.end(), [](const Sample& x, const Sample& y) { return x.norm < y.norm; });
  double best = samples.front().norm;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  const auto project = [](Eigen::Vector3d w) {  // onto the simplex, by clamping and rescaling
    w = w.cwiseMax(0.0);
    return Eigen::Vector3d(w / w.sum());
  };
  for (std::size_t s = 0; s < std::min<std::size_t>(8, samples.size()); ++s) {
    Sample current = samples[s];
    for (double step = 1.0 / grid; step > 1e-7; step *= 0.7) {
      for (int attempt = 0; attempt < 12; ++attempt) {
        const Eigen::Vector3d wa = project(current.wa + step * Eigen::Vector3d(normal(rng), normal(rng), normal(rng)));
        const Eigen::Vector3d wb = project(current.wb + step * Eigen::Vector3d(normal(rng), normal(rng), normal(rng)));
        const double norm = point_pair_contact_norm(a, wa, b, wb);
        if (norm < current.norm) current = {norm, wa, wb};
      }
    }
    best = std::min(best, current.norm);
  }
  return best;
}

}  // namespace sscc::test
