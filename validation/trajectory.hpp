// Seeded random trajectories in reduced coordinates for self-CCD validation.
//
// A stationary autoregressive walk in scaled coordinates q_hat = M^(1/2) q:
//   q_hat_0 = amplitude * xi_0 / sqrt(r),
//   q_hat_{k+1} = rho q_hat_k + sqrt(1 - rho^2) amplitude * xi_{k+1} / sqrt(r),
// with xi_k independent standard normal vectors and rho = 0.9, so ||q||_M stays near
// `amplitude` and each step moves by about 0.44 amplitude. Step k goes from q_k to q_{k+1}.
//
// With burst > 1 the walk is scaled by an envelope that rises smoothly from 1 to `burst`
// and back (a raised cosine kBurstWidth steps wide) once every kBurstPeriod steps: most
// steps are modest, and a tenth are excursions, where contacts happen.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "sscc/model/subspace_model.hpp"

namespace sscc::validation {

inline constexpr double kTrajectoryCorrelation = 0.9;
inline constexpr int kBurstPeriod = 100;
inline constexpr int kBurstWidth = 10;

/// steps + 1 configurations (reduced coordinates q, not scaled).
std::vector<Eigen::VectorXd> random_trajectory(const SubspaceModel& model, int steps, double amplitude,
                                               std::uint64_t seed, double burst = 1.0);

}  // namespace sscc::validation
