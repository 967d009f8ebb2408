#include "slow_query_search.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>

#include "agreement.hpp"
#include "query_generators.hpp"

namespace sscc::validation {

namespace {

/// Repeats per timing: the best of them is the query's time (noise only adds).
constexpr int kTimingRepeats = 3;

double kernel_us(const Query& q) {
  double best = INFINITY;
  for (int r = 0; r < kTimingRepeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    run_kernel(q);
    best = std::min(best, std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

double& coordinate(Query& q, int index) { return q.points[index / 3][index % 3]; }

/// Clamps the magnitude of a nonzero x into [2^-range, 2^range] (range below 1074).
double within_range(double x, int range) {
  if (x == 0.0 || range >= 1074) return x;
  int e = 0;
  std::frexp(x, &e);
  if (e - 1 > range) return std::copysign(std::ldexp(1.0, range), x);
  if (e - 1 < -range) return std::copysign(std::ldexp(1.0, -range), x);
  return x;
}

void mutate(Query& q, std::mt19937_64& rng, int range) {
  std::uniform_int_distribution<int> pick(0, 23);
  double& x = coordinate(q, pick(rng));
  switch (std::uniform_int_distribution<int>(0, 4)(rng)) {
    case 0: {  // one mantissa or exponent bit
      std::uint64_t bits = 0;
      std::memcpy(&bits, &x, sizeof bits);
      bits ^= std::uint64_t{1} << std::uniform_int_distribution<int>(0, 62)(rng);
      double y = 0.0;
      std::memcpy(&y, &bits, sizeof y);
      if (std::isfinite(y)) x = y;
      break;
    }
    case 1: {  // a power of two of either sign
      const int limit = std::min(range, 1074);
      x = std::ldexp(rng() & 1 ? 1.0 : -1.0, std::uniform_int_distribution<int>(-limit, std::min(limit, 1023))(rng));
      break;
    }
    case 2:
      x = std::uniform_int_distribution<int>(-2, 2)(rng);
      break;
    case 3:
      x = coordinate(q, pick(rng));
      break;
    default:
      x = -x;
      break;
  }
  x = within_range(x, range);
}

}  // namespace

SlowQuery search_slow_query(Kind kind, const SlowQuerySearchOptions& options, std::ostream& progress) {
  std::mt19937_64 rng(options.seed + (kind == Kind::kEdgeEdge ? 1 : 0));
  SlowQuery best{integer_grid_query(kind, rng), 0.0, true};
  best.us = kernel_us(best.query);
  for (long i = 0; i < options.iterations; ++i) {
    Query candidate = best.query;
    const int changes = std::uniform_int_distribution<int>(1, 3)(rng);
    for (int c = 0; c < changes; ++c) mutate(candidate, rng, options.exponent_range);
    const double us = kernel_us(candidate);
    if (us > best.us) best = {candidate, us, true};
    if ((i + 1) % 500 == 0)
      progress << "  slow-query search " << to_string(kind) << ": " << (i + 1) << " steps, slowest " << best.us
               << " us\n";
  }
  best.us = kernel_us(best.query);  // re-timed, away from the search's noise
  best.agrees = disagreement_with_reference(best.query).empty();
  return best;
}

long report_slow_query_search(const SlowQuerySearchOptions& options, std::ostream& out, std::ostream& progress) {
  long disagreements = 0;
  for (Kind kind : {Kind::kVertexFace, Kind::kEdgeEdge}) {
    progress << "slow-query search " << to_string(kind) << ": " << options.iterations << " steps, exponents within +-"
             << options.exponent_range << "\n";
    const SlowQuery q = search_slow_query(kind, options, progress);
    char line[160];
    std::snprintf(line, sizeof line,
                  "slowest %s (exponents within +-%d, %ld steps): us=%.1f agrees=%s: ", to_string(kind),
                  options.exponent_range, options.iterations, q.us, q.agrees ? "yes" : "NO");
    out << line << describe(q.query) << '\n';
    disagreements += q.agrees ? 0 : 1;
  }
  return disagreements;
}

}  // namespace sscc::validation
