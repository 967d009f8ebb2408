// `sscc kernels`: the leaf kernels held against the public query set, FCL and the exact
// reference, and their run time against error.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>

namespace sscc::validation {

struct KernelValidationOptions {
  /// The public query set's folder ("" to skip that report).
  std::string queries_dir;
  /// Random queries of each kind (0 to skip the random report); a tenth as many
  /// near-degenerate ones are added.
  long random = 0;
  std::uint64_t seed = 1;
  /// Where the CSV files and plots of the run-time-against-error sweeps go.
  std::string output_dir = "validation-output";
  /// Timing repeats; the median is reported.
  int repeats = 5;
};

/// Prints the report lines to `out` and progress to `progress`. Returns the number of
/// disagreements with the ground truth or the exact reference (0 when all is well).
long run_kernel_validation(const KernelValidationOptions& options, std::ostream& out,
                           std::ostream& progress);

}  // namespace sscc::validation
