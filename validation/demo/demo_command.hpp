// `sscc demo`: the main job. A scene of modal objects simulated step by step, its CCD run
// every step with certificates (SSCC) and without (traditional: the same code, the
// certificate tests off; on every step, or a regular sample), the objects responding to the
// contacts found, FCL's self-collision on a subsample of steps, a table of the results, PNG
// plots, the modal sound as a WAV when the steps are at an audio rate, and the last line
//   demo: scene=NAME objects=N steps=N colliding_steps=N sscc_ms=X traditional_ms=X speedup=X
//         threads=N traditional_thread_speedup=X penetrating_steps=N deepest_penetration_mm=X agree=yes|no
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
