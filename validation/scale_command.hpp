// `sscc scale`: how the pipeline grows with the mesh. For one mesh (a geodesic sphere of
// about N triangles, from the stress suite's generators, or a mesh file): the model with the 27
// polynomial modes (unit weights, as `sscc precompute` builds it), the hierarchy, the default
// certificates, a detector, then a seeded random trajectory of query steps at a multiple of
// the root's radius (the traversal then runs on most steps), printing the line
//   scale: triangles=N vertices=N nodes=N hierarchy_s=X certificates_s=X detector_s=X
//          prepare_s=X query_ms_per_step=X colliding_steps=N total_s=X peak_rss_mb=X
//          root_radius=X pairs_screened=N screened_per_pair=X
// (one line; prepare_s: SelfCcd::prepare, what the first query would otherwise build). Peak memory is the process's
// (getrusage), so run one size per process: scripts/scale.sh does, and prints the table of several sizes.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>

namespace sscc::validation {

struct ScaleOptions {
  long triangles = 10000;  ///< about this many, on a geodesic sphere
  std::string mesh;        ///< a mesh file instead ("" for the sphere)
  int modes = 27;          ///< polynomial modes
  int steps = 100;
  /// The trajectory's amplitude in root radii (trajectory.hpp: ||q||_M stays near it).
  double amplitude = 2.0;
  std::uint64_t seed = 1;
};

/// Returns 0 (errors throw).
long run_scale(const ScaleOptions& options, std::ostream& out, std::ostream& progress);

}  // namespace sscc::validation
