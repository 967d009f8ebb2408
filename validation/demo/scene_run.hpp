// One run of a demo scene: its assets (mesh, basis, certificates; cached), its motion
// step by step, the scene's CCD each step with certificates (SSCC) and without
// (traditional), optionally the discrete query at each step's end configuration both
// ways, and FCL's self-collision on a few sampled steps with its disagreements settled by
// the exact kernels. Shared by `sscc demo` and `sscc bench`.
//
// Scenes (defaults per scene; every one can be overridden):
//  - bunnies: data/bunny15k.off, modal basis r = 30, 16 objects dropped and struck
//    (ear_drop.hpp), stiff rubber (E = 2e7 Pa, nu = 0.4, 1100 kg/m^3, damping ratio 0.1);
//  - spring: the generated double-helix spring (spring_mesh.hpp), modal r = 20, one spring
//    struck on its top coil (spring_scene.hpp), steel (2e11 Pa, 0.3, 7800 kg/m^3, 0.02);
//  - dragon: ../shared/data/meshes/ChineseDragon-10kv.off, the 27 polynomial modes
//    stiffness-scaled (24 remain), one dragon dropped and struck, stiff rubber.
// With these materials and impulses the thin parts meet now and then while most steps
// stay within the certificates.
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "demo/demo_assets.hpp"
#include "fcl_settle.hpp"
#include "sscc/scene/scene.hpp"

namespace sscc::validation {

struct SceneRunOptions {
  std::string scene = "bunnies";
  std::string mesh;   ///< "" : the scene's default
  std::string basis;  ///< a .U file with its .weights beside it; "" : generated and cached
  int modes = 0;      ///< 0: the scene's default
  int objects = 0;    ///< 0: the scene's default
  int steps = 300;
  double dt = 0.01;       ///< s
  int fcl_steps = 4;      ///< steps on which FCL's self-collision runs too (0: none)
  bool discrete = false;  ///< also time the discrete query at each step's end, both ways
  std::uint64_t seed = 1;
  std::optional<double> damping_ratio, youngs_modulus, poisson_ratio, density;
  std::string cache_dir = "demo-cache";
  bool fresh_certificates = false;     ///< precompute even when a cached file is valid (to time it)
  bool record_steps = false;           ///< keep every step's object motions (for replays)
  std::string scale;                   ///< --scale auto|S of the mesh ("" : as read); mesh_units.hpp
  bool exclude_rest_contacts = false;  ///< --exclude-rest-contacts: ignore the pairs touching at rest
};

/// Per-step milliseconds and what the method found.
struct MethodTimes {
  std::vector<double> ms;
  std::vector<double> self_ms;  ///< the self-collision part of each step
  int colliding_steps = 0;
  long self_pairs = 0, inter_pairs = 0;
  double mean() const;
  double median() const;
  double max() const;
};

struct SceneRun {
  std::string scene;  ///< the scene's name, or the mesh's for a mesh given with --mesh
  int objects = 0, steps = 0;
  double dt = 0.0;
  DemoAssets assets;
  MethodTimes sscc, traditional;  ///< on every thread (sscc::default_threads())
  int threads = 1;
  MethodTimes sscc_one_thread, traditional_one_thread;  ///< the same steps on one thread, when threads > 1
  int identical_thread_steps = 0;  ///< steps whose one-thread reports equal the all-thread ones (both methods)
  MethodTimes discrete_sscc, discrete_traditional;  ///< empty unless options.discrete
  int identical_steps = 0;                          ///< SSCC and traditional reports identical
  int identical_discrete_steps = 0;
  int all_certified_steps = 0;  ///< no object needed a traversal
  long object_steps_certified = 0, object_steps_traversed = 0;
  int impacts = 0;             ///< landings and strikes
  std::vector<double> fcl_ms;  ///< per sampled step, all objects
  int fcl_object_steps = 0, fcl_identical = 0;
  SettledDisagreements fcl_settled;
  std::vector<std::vector<ObjectStep>> recorded;  ///< with options.record_steps
  double seconds = 0.0;

  double speedup() const;
  /// Mean time per step on one thread over that on every thread (0 when threads == 1).
  double thread_speedup(const MethodTimes& one_thread, const MethodTimes& all) const;
  double discrete_speedup() const;
  bool agree() const;
};

SceneRun run_scene(const SceneRunOptions& options, std::ostream& progress);

}  // namespace sscc::validation
