// `sscc kernels`: the leaf kernels held against the public query set, FCL and the exact
// reference, and their run time against error.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace sscc::validation {

struct KernelValidationOptions {
  /// The public query set's folder ("" to skip that report).
  std::string queries_dir;
  /// Random queries of each kind (0 to skip the random report); a tenth as many
  /// near-degenerate ones are added.
  long random = 0;
  /// With `random`: only the minimum-separation sweep, on the same queries as the full report.
  bool separation_only = false;
  std::uint64_t seed = 1;
  /// Where the CSV files and plots of the run-time-against-error sweeps go.
  std::string output_dir = "validation-output";
  /// Timing repeats; the median is reported.
  int repeats = 5;
  /// Hill-climbing steps of the slow-query search per kind (0 to skip it), and the range
  /// of coordinate exponents it may use.
  long search_slow = 0;
  int exponent_range = 1074;
};

/// Mean kernel time per query at one time-of-impact tolerance.
struct ToleranceTiming {
  double tolerance;
  double vertex_face_us, edge_edge_us;
};

/// The kernels' run time against their time-of-impact tolerance (1e-2 .. 1e-12) on
/// `queries` seeded random queries of each kind, median of `repeats`.
std::vector<ToleranceTiming> time_against_toi_tolerance(long queries, std::uint64_t seed, int repeats);

/// Prints the report lines to `out` and progress to `progress`. Returns the number of
/// disagreements with the ground truth or the exact reference (0 when all is well).
long run_kernel_validation(const KernelValidationOptions& options, std::ostream& out, std::ostream& progress);

}  // namespace sscc::validation
