// `sscc bench`: the benchmarks, in one run, set beside the SSCC paper's tables.
//
//  - The demo scenes (scene_run.hpp), certificates precomputed afresh to time them:
//    sixteen bunnies (continuous and discrete self-collision, the paper's Table 2 and its
//    Table 1 "bunny (16)" row), the spring (Table 1 "spring"), and the dragon with
//    stiffness-scaled polynomial modes (Table 1 "dragon (polynomial)"; skipped when the
//    mesh in ../shared is absent).
//  - Run time against error of the certificates: for each epsilon, the bunny's
//    precomputation time, root radius, and the self-collision queries of the bunny run
//    replayed with those certificates (time, object-steps certified, node visits against
//    the traditional query's).
//  - Run time against error of the kernels: time per query against the time-of-impact
//    tolerance.
//  - The self-CCD table (self_ccd_table.hpp): traditional, normal cones and FCL on every mesh
//    of ../shared/data/meshes at three amplitudes.
// Writes bench.md (the Markdown tables), CSV files and PNG plots into the output folder and
// prints the tables. Returns the number of disagreements between SSCC and traditional (and
// between cones and traditional in the self-CCD table).
#pragma once

#include <cstdint>
#include <ostream>
#include <string>

namespace sscc::validation {

struct BenchOptions {
  int steps = 300;  ///< per scene
  std::uint64_t seed = 1;
  std::string cache_dir = "demo-cache";
  std::string output_dir = "bench-output";
  long kernel_queries = 20000;  ///< per kind, for the tolerance sweep
  std::string meshes_dir;       ///< the self-CCD table's meshes; "" is ../shared/data/meshes
  int table_steps = 3;          ///< per mesh and amplitude in the self-CCD table
  int table_repeats = 5;        ///< timed runs of each query per step in the self-CCD table (median kept)
  bool self_ccd_table_only = false;
};

long run_bench(const BenchOptions& options, std::ostream& out, std::ostream& progress);

}  // namespace sscc::validation
