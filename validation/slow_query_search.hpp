// A search for the kernels' slowest queries: hill climbing on the 24 coordinates of a query
// (mantissa bits, exponents, small integers, copies of other coordinates, which make
// degeneracies), keeping a change when the query gets slower. What it finds is held
// against the exact reference. Slow queries are what stall a simulator's step.
#pragma once

#include <cstdint>
#include <ostream>

#include "query.hpp"

namespace sscc::validation {

struct SlowQuerySearchOptions {
  long iterations = 2000;
  std::uint64_t seed = 1;
  /// Nonzero coordinates stay within 2^-exponent_range .. 2^exponent_range in magnitude
  /// (1074 and above: the whole double range).
  int exponent_range = 1074;
};

struct SlowQuery {
  Query query;
  double us = 0.0;     ///< the kernel's time on it (best of 3)
  bool agrees = true;  ///< with the exact reference
};

/// One search per kind; prints the slowest query of each to `out`.
SlowQuery search_slow_query(Kind kind, const SlowQuerySearchOptions& options, std::ostream& progress);

/// Both kinds; prints a line per kind to `out`. Returns the number of disagreements.
long report_slow_query_search(const SlowQuerySearchOptions& options, std::ostream& out, std::ostream& progress);

}  // namespace sscc::validation
