// `sscc demo`: the main job. A scene of modal objects simulated step by step, its CCD run
// every step with certificates (SSCC) and without (traditional: the same code, the
// certificate tests off), FCL's self-collision on a subsample of steps, a table of the
// results, PNG plots, and the last line
//   demo: scene=NAME objects=N steps=N colliding_steps=N sscc_ms=X traditional_ms=X speedup=X agree=yes|no
// (mean milliseconds per step for the whole scene). The modal basis and the certificates
// are computed on first run and cached.
//
// Scenes: "bunnies" (ear_drop.hpp: a 15k-triangle bunny shipped in data/, dropped and
// struck) and "spring" (spring_scene.hpp: a double-helix spring compressed and released).
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>

#include "sscc/basis/linear_elasticity.hpp"

namespace sscc::validation {

struct DemoOptions {
  std::string scene = "bunnies";
  std::string mesh;       ///< "" : the scene's default (data/bunny15k.off, or the generated spring)
  std::string basis;      ///< a modal .U file (with its .weights); "" : modal analysis, cached
  int modes = 0;          ///< 0: the scene's default (30 bunnies, 20 spring)
  int objects = 0;        ///< 0: the scene's default (16 bunnies, 1 spring)
  int steps = 300;
  double dt = 0.01;       ///< s
  /// Overrides of the scene's defaults. Bunnies: stiff rubber (E = 2e7 Pa, nu = 0.4,
  /// 1100 kg/m^3, damping ratio 0.1: rubber damps its vibrations strongly); spring: steel
  /// (2e11 Pa, 0.3, 7800 kg/m^3, 0.02). With the scenes' impulses, the bunnies' ears and the
  /// spring's coils meet now and then, and most steps stay within the certificates.
  std::optional<double> damping_ratio;
  std::optional<double> youngs_modulus, poisson_ratio, density;
  int fcl_steps = 4;      ///< steps on which FCL's self-collision runs too (0: none)
  std::uint64_t seed = 1;
  std::string cache_dir = "demo-cache";
  std::string output_dir = "demo-output";
};

/// Returns the number of disagreements (0 when the methods agree); errors throw.
long run_demo(const DemoOptions& options, std::ostream& out, std::ostream& progress);

}  // namespace sscc::validation
