// A long run of a small scene: every step on every thread and again on one, the reports
// compared (they must not depend on the thread count), and the process's resident memory
// after a warm-up against the end (a step must not leave anything behind).
#pragma once

#include <cstdint>
#include <ostream>
#include <string>

namespace sscc::validation {

/// Steps of the load run in the quick run.
inline constexpr long kQuickLoadSteps = 500;
/// Largest growth of the resident set size after the warm-up, in kB. The run's working
/// set is reached in the warm-up; a leak of 64 bytes per step over 10^5 steps (5.5 MB) would
/// exceed it, while the allocator's own fluctuation stays far below.
inline constexpr long kRssGrowthLimitKb = 4096;

struct LoadRunOptions {
  long steps = 100000;
  std::uint64_t seed = 1;
};

struct LoadRunResult {
  long steps = 0;
  long warm_up_steps = 0;
  int objects = 0;
  int triangles = 0;
  int modes = 0;
  int threads = 0;
  long colliding_steps = 0;
  long mismatched_steps = 0;
  std::string first_difference;
  long rss_warm_kb = 0;  ///< resident set size after the warm-up
  long rss_end_kb = 0;   ///< and at the end
  long rss_growth_kb = 0;
  double seconds = 0.0;
};

LoadRunResult run_load(const LoadRunOptions& options, std::ostream& progress);

}  // namespace sscc::validation
