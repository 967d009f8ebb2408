// `sscc selfccd`: whole-mesh continuous self-collision over a seeded random trajectory,
// by several methods side by side (the traversal with certificates "sscc", without them
// "traditional", exhaustive all-pairs testing, FCL), with their agreement and the
// per-step speedup of sscc over traditional; disagreements with FCL are settled by the
// exact kernels.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "model_loading.hpp"

namespace sscc::validation {

struct SelfCcdValidationOptions {
  ModelSource model;
  int steps = 20;
  double amplitude = 0.1;    ///< typical ||q||_M (see trajectory.hpp)
  double burst = 1.0;        ///< peak of the amplitude envelope (see trajectory.hpp)
  std::string certificates;  ///< certificate file, needed by the method "sscc"
  std::uint64_t seed = 1;
  std::vector<std::string> methods = {"traditional"};  ///< sscc, traditional, exhaustive, fcl
};

/// Prints the report; returns the number of disagreements between the sscc methods plus
/// FCL disagreements the exact kernels do not settle against FCL (0 when all is well).
long run_selfccd_validation(const SelfCcdValidationOptions& options, std::ostream& out, std::ostream& progress);

}  // namespace sscc::validation
