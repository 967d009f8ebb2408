// The steps a stress case is queried on: on and just inside certificate boundaries (the
// root's and, in the full run, the smallest node radius and a random node's), steps that
// stay inside, leave and enter, steps from rest (a mesh touching at rest starts touching),
// a step that does not move, and random steps of growing amplitude.
#pragma once

#include <Eigen/Core>

#include <random>
#include <string>
#include <vector>

#include "sscc/certificates/certificates.hpp"
#include "sscc/model/subspace_model.hpp"

namespace sscc::validation {

struct StressStep {
  std::string kind;  ///< "0 -> (1-1e-12) R_root", ...
  Eigen::VectorXd q0, q1;
};

/// How many steps: kQuick (the test suite's run), kFull (small meshes, the brute force),
/// kLarge (thousands of triangles: no step at the global radius, whose contacts number in the
/// millions, but larger random amplitudes), kLargest (10^5 triangles and more: a few steps).
enum class StepBudget { kQuick, kFull, kLarge, kLargest };

std::vector<StressStep> stress_steps(const SubspaceModel& model, const Certificates& certificates, StepBudget budget,
                                     std::mt19937_64& rng);

}  // namespace sscc::validation
