// `sscc demo`: the main job. A scene of modal objects simulated step by step, its CCD run
// every step with certificates (SSCC) and without (traditional: the same code, the
// certificate tests off), FCL's self-collision on a subsample of steps, a table of the
// results, PNG plots, and the last line
//   demo: scene=NAME objects=N steps=N colliding_steps=N sscc_ms=X traditional_ms=X speedup=X agree=yes|no
// (mean milliseconds per step for the whole scene). The modal basis and the certificates
// are computed on first run and cached.
//
// Scenes: scene_run.hpp.
#pragma once

#include <ostream>
#include <string>

#include "demo/scene_run.hpp"

namespace sscc::validation {

struct DemoOptions {
  SceneRunOptions run;
  std::string output_dir = "demo-output";
};

/// Returns the number of disagreements (0 when the methods agree); errors throw.
long run_demo(const DemoOptions& options, std::ostream& out, std::ostream& progress);

}  // namespace sscc::validation
