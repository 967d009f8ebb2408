#include "degenerate_benchmark.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <random>

#include "agreement.hpp"
#include "fcl_kernels.hpp"
#include "query_generators.hpp"

namespace sscc::validation {

namespace {

using Clock = std::chrono::steady_clock;

double elapsed_us(Clock::time_point start) {
  return std::chrono::duration<double, std::micro>(Clock::now() - start).count();
}

struct Set {
  const char* name;
  Query (*generate)(Kind, std::mt19937_64&);
};

Query grid(Kind kind, std::mt19937_64& rng) { return integer_grid_query(kind, rng); }

volatile long fcl_sink = 0;  // keeps the timed FCL calls from being optimised away

}  // namespace

TimeDistribution distribution_of(std::vector<double> t) {
  TimeDistribution d;
  if (t.empty()) return d;
  std::sort(t.begin(), t.end());
  double sum = 0.0;
  for (double x : t) sum += x;
  d.mean_us = sum / t.size();
  d.median_us = t[t.size() / 2];
  d.p99_us = t[std::min(t.size() - 1, t.size() * 99 / 100)];
  d.max_us = t.back();
  return d;
}

std::vector<DegenerateSetTiming> run_degenerate_benchmark(long queries, std::uint64_t seed, std::ostream& out,
                                                          std::ostream& progress) {
  const std::array<Set, 3> sets = {Set{"near-degenerate", near_degenerate_query}, Set{"integer-grid", grid},
                                   Set{"resting-contact", resting_contact_query}};
  std::vector<DegenerateSetTiming> timings;
  std::mt19937_64 rng(seed);
  for (const Set& set : sets) {
    for (Kind kind : {Kind::kVertexFace, Kind::kEdgeEdge}) {
      progress << "degenerate benchmark: " << set.name << " " << to_string(kind) << " (" << queries << " queries)\n";
      std::vector<Query> qs;
      for (long i = 0; i < queries; ++i) qs.push_back(set.generate(kind, rng));
      DegenerateSetTiming timing{set.name, kind, queries, {}, -1.0, 0};
      for (const Query& q : qs) timing.disagreements += disagreement_with_reference(q).empty() ? 0 : 1;
      std::vector<double> all;
      std::array<std::vector<double>, ccd::kDecidedByCount> by_stage;
      for (const Query& q : qs) {
        const auto start = Clock::now();
        const ccd::CcdResult r = run_kernel(q);
        const double us = elapsed_us(start);
        all.push_back(us);
        by_stage[static_cast<int>(r.decided_by)].push_back(us);
      }
      timing.sscc = distribution_of(all);
      if (fcl_available()) {
        const auto start = Clock::now();
        long hits = 0;
        for (const Query& q : qs) hits += run_fcl(q) ? 1 : 0;
        timing.fcl_mean_us = elapsed_us(start) / std::max(1L, queries);
        fcl_sink = fcl_sink + hits;
      }
      char line[320];
      std::snprintf(line, sizeof line,
                    "degenerate %s %s: queries=%ld disagreements=%ld median_us=%.3f mean_us=%.3f "
                    "p99_us=%.3f max_us=%.1f fcl_mean_us=%.3f",
                    set.name, to_string(kind), queries, timing.disagreements, timing.sscc.median_us,
                    timing.sscc.mean_us, timing.sscc.p99_us, timing.sscc.max_us, timing.fcl_mean_us);
      out << line << '\n';
      for (int s = 0; s < ccd::kDecidedByCount; ++s) {
        if (by_stage[s].empty()) continue;
        const TimeDistribution d = distribution_of(by_stage[s]);
        std::snprintf(line, sizeof line,
                      "degenerate %s %s stage %s: queries=%zu median_us=%.3f mean_us=%.3f p99_us=%.3f max_us=%.1f",
                      set.name, to_string(kind), ccd::to_string(static_cast<ccd::DecidedBy>(s)), by_stage[s].size(),
                      d.median_us, d.mean_us, d.p99_us, d.max_us);
        out << line << '\n';
      }
      timings.push_back(timing);
    }
  }
  return timings;
}

}  // namespace sscc::validation
