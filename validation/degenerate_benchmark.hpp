// Run time of the kernels where geometry is degenerate: the near-degenerate set, an
// integer grid ({-2..2} coordinates) and resting contact (everything in one plane), with
// the time per query by deciding stage and its median, mean, 99th percentile and maximum;
// FCL's mean beside it. Every query is also held against the exact reference.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "query.hpp"

namespace sscc::validation {

/// Per-query times of one method on one set, in us.
struct TimeDistribution {
  double median_us = 0.0, mean_us = 0.0, p99_us = 0.0, max_us = 0.0;
};
TimeDistribution distribution_of(std::vector<double> times_us);

struct DegenerateSetTiming {
  std::string set;
  Kind kind;
  long queries = 0;
  TimeDistribution sscc;
  double fcl_mean_us = -1.0;  ///< -1 without FCL
  long disagreements = 0;     ///< with the exact reference
};

/// `queries` of each set and kind, seeded; prints one line per set, kind and stage to
/// `out`. Returns the timings (bench tables use them).
std::vector<DegenerateSetTiming> run_degenerate_benchmark(long queries, std::uint64_t seed, std::ostream& out,
                                                          std::ostream& progress);

}  // namespace sscc::validation
