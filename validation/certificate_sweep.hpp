// `sscc certificates`: run time against error for the certificates. For each epsilon, the
// precomputation (time, root radius) and SSCC on one trajectory against the traditional
// query on the same trajectory (identical reports required, culling rate, query time,
// speedup), as report lines, CSV and a plot.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "model_loading.hpp"

namespace sscc::validation {

struct CertificateSweepOptions {
  ModelSource model;
  std::vector<double> epsilons = {0.5, 0.2, 0.1, 0.05, 0.02, 0.01};
  int steps = 100;
  double amplitude = 0.05;
  double burst = 1.0;
  std::uint64_t seed = 1;
  std::string output_dir = "validation-output";
};

/// Returns the number of steps where SSCC and the traditional query disagree (0 when all is
/// well).
long run_certificate_sweep(const CertificateSweepOptions& options, std::ostream& out, std::ostream& progress);

}  // namespace sscc::validation
