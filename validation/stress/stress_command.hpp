// `sscc stress`: the whole pipeline (model, hierarchy, certificates precomputed, written and
// read back, the certified and traditional queries, query_positions, a scene step) held to
// an independent reference under conditions chosen to break it: meshes far from the origin,
// tiny and huge, bases of rank 1 to 300 of every kind, weights and columns spanning many
// decades, steps on and just inside certificate boundaries, steps that start touching,
// degenerate and non-manifold meshes, 1 to 10^6 triangles. The reference is the per-feature
// brute force (feature_brute_force.hpp) where it is affordable, the library's exhaustive
// query on larger meshes, and on the largest only the traditional query (the certified
// query and query_positions must equal it). Each case ends identical (every step, every
// report) or refused (an exception naming the problem), else it is a mismatch. Then a long
// scene run (load_run.hpp). Deterministic for a seed.
#pragma once

#include <cstdint>
#include <ostream>

namespace sscc::validation {

struct StressOptions {
  bool quick = false;        ///< a few small cases and a short load run: seconds (the test suite's run)
  std::uint64_t seed = 1;    ///< every random choice
  long load_steps = 100000;  ///< steps of the long scene run (quick: kQuickLoadSteps)
  long only_case = 0;        ///< 1-based: only that case of the table (no long run); 0: all
};

/// Prints the table of cases and, last, `stress: cases=N identical=N refused=N mismatches=N`;
/// returns the mismatches.
long run_stress(const StressOptions& options, std::ostream& out, std::ostream& progress);

}  // namespace sscc::validation
