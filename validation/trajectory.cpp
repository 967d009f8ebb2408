#include "trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace sscc::validation {

std::vector<Eigen::VectorXd> random_trajectory(const SubspaceModel& model, int steps, double amplitude,
                                               std::uint64_t seed, double burst) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  const int r = model.mode_count();
  const double scale = amplitude / std::sqrt(static_cast<double>(r));
  const double innovation = std::sqrt(1.0 - kTrajectoryCorrelation * kTrajectoryCorrelation);
  const Eigen::VectorXd unscale = model.weights().cwiseSqrt().cwiseInverse();
  const auto envelope = [&](int k) {
    const double from_peak = std::fabs(k % kBurstPeriod - 0.5 * kBurstPeriod) / (0.5 * kBurstWidth);
    const double pulse = from_peak < 1.0 ? 0.5 * (1.0 + std::cos(M_PI * from_peak)) : 0.0;
    return 1.0 + (burst - 1.0) * pulse;
  };
  std::vector<Eigen::VectorXd> q;
  Eigen::VectorXd q_hat(r);
  for (int j = 0; j < r; ++j) q_hat[j] = scale * normal(rng);
  q.push_back(envelope(0) * q_hat.cwiseProduct(unscale));
  for (int k = 0; k < steps; ++k) {
    for (int j = 0; j < r; ++j) {
      q_hat[j] = kTrajectoryCorrelation * q_hat[j] + innovation * scale * normal(rng);
    }
    q.push_back(envelope(k + 1) * q_hat.cwiseProduct(unscale));
  }
  return q;
}

}  // namespace sscc::validation
