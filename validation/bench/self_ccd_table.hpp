// The self-CCD table of `sscc bench`: on every mesh of ../shared/data/meshes, polynomial
// modes, random trajectories at a few amplitudes, the traditional query (plain swept boxes),
// the query with normal cones, with the displacement bounds, with both (the library's defaults
// without certificates), SSCC (the certificates, computed once per mesh and cached) and FCL's
// traversal, one thread each, on the same steps; time (the median of a few warm runs of each),
// node tests and triangle-pair tests per step, and whether the queries agree.
// Step counts are small so that the table takes minutes (FCL is slow on the 75k bunny).
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace sscc::validation {

struct SelfCcdTableOptions {
  std::vector<std::string> meshes;  ///< mesh files
  std::vector<double> amplitudes = {0.01, 0.05, 0.2};
  int steps = 3;      ///< per mesh and amplitude, for traditional and cones
  int repeats = 5;    ///< timed runs of each method per step, each after an untimed one; the median is kept
  int fcl_steps = 2;  ///< the first steps of the same trajectory, for FCL
  std::string basis = "polynomial:27";
  std::uint64_t seed = 1;
  std::string cache_dir = "demo-cache";  ///< each mesh's certificate file, computed when absent or stale
};

struct SelfCcdTableRow {
  std::string mesh;
  int triangles = 0;
  double amplitude = 0.0;
  /// Mean per step; bounds: the displacement bounds alone (no certificates, no cones); both:
  /// the cones and the displacement bounds (SelfCcdOptions' defaults without certificates).
  double traditional_ms = 0.0, cones_ms = 0.0, bounds_ms = 0.0, both_ms = 0.0, sscc_ms = 0.0, fcl_ms = 0.0;
  /// Node (box) tests per step.
  double traditional_nodes = 0.0, cones_nodes = 0.0, bounds_nodes = 0.0, both_nodes = 0.0, sscc_nodes = 0.0;
  double traditional_pairs = 0.0, cones_pairs = 0.0;  ///< triangle-pair tests per step
  double cones_plane_culled = 0.0;                    ///< of the cones' pairs, those their planes separated, per step
  double root_radius = 0.0;
  int root_certified_steps = 0;  ///< steps SSCC decided by the root's certificate alone
  int colliding_steps = 0;
  bool identical = true;  ///< every query reported the traditional one's features on every step
};

/// Runs the table; progress goes to `progress`.
std::vector<SelfCcdTableRow> self_ccd_table(const SelfCcdTableOptions& options, std::ostream& progress);

/// The rows as a Markdown table (with the ratios).
std::string self_ccd_table_markdown(const std::vector<SelfCcdTableRow>& rows);

}  // namespace sscc::validation
