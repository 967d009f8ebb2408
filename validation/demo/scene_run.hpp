// One run of a demo scene: its assets (mesh, basis, certificates; cached), its motion
// step by step, the scene's CCD each step with certificates (SSCC) and, on every step or a
// regular sample of them, without (traditional), the contact response to SSCC's report
// (contact_response.hpp), the exact discrete test of every object at the end of each step
// (what interpenetration the response left), optionally the discrete query at each step's
// end configuration both ways, and FCL's self-collision on a few sampled steps with its
// disagreements settled by the exact kernels. Shared by `sscc demo` and `sscc bench`.
//
// Scenes (defaults per scene; every one can be overridden):
//  - bunnies: data/bunny15k.off, modal basis r = 30, 16 objects dropped and struck
//    (ear_drop.hpp), stiff rubber (E = 2e7 Pa, nu = 0.4, 1100 kg/m^3, damping ratio 0.1);
//  - spring: the generated double-helix spring (spring_mesh.hpp), modal r = 20, one spring
//    standing on the ground at rest, struck on its top coil every 0.4 s at 2 to 3 m/s
//    (spring_scene.hpp), steel (2e11 Pa, 0.3, 7800 kg/m^3, damping ratio 0.02), at audio
//    rate: 44,100 steps of 1/44,100 s, the traditional query on every 50th step, the modal
//    sound kept (SceneRun::sound);
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
  int steps = 0;      ///< 0: the scene's default
  double dt = 0.0;    ///< s; 0: the scene's default
  /// The traditional query runs on every this many steps (the first included); 0: the
  /// scene's default. SSCC runs on every step.
  int traditional_every = 0;
  int fcl_steps = 4;      ///< steps on which FCL's self-collision runs too (0: none)
  bool discrete = false;  ///< also time the discrete query at each step's end, both ways
  std::uint64_t seed = 1;
  std::optional<double> damping_ratio, youngs_modulus, poisson_ratio, density;
  std::optional<double> strike_speed;  ///< m/s (the spring: the slowest of its strikes); empty: the scene's
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
  double self_mean() const;  ///< of self_ms
  double median() const;
  double max() const;
};

/// What the contact response did over the run, and what interpenetration it left.
struct ContactTotals {
  int steps_with_contacts = 0;  ///< steps whose response had at least one constraint
  long self_features = 0, inter_features = 0, ground_contacts = 0;
  /// Steps whose response used other contacts than SSCC reported (0 unless broken).
  int response_mismatches = 0;
  /// Steps that ended, after the response, with two non-adjacent triangles of an object
  /// intersecting (exact discrete test), and the longest run of such steps in a row.
  int penetrating_steps = 0, longest_penetrating_run = 0;
  int final_penetrating_pairs = 0;  ///< intersecting pairs at the end of the run
  /// m: the deepest penetration of contact points along their normals at the end of a step,
  /// before the response, and the deepest left after it.
  double deepest_penetration = 0.0, deepest_residual = 0.0;
};

struct SceneRun {
  std::string scene;  ///< the scene's name, or the mesh's for a mesh given with --mesh
  int objects = 0, steps = 0;
  double dt = 0.0;
  DemoAssets assets;
  MethodTimes sscc, traditional;  ///< on every thread (sscc::default_threads())
  int threads = 1;
  MethodTimes sscc_one_thread, traditional_one_thread;  ///< the compared steps on one thread, when threads > 1
  int identical_thread_steps = 0;  ///< compared steps whose one-thread reports equal the all-thread ones (both methods)
  MethodTimes discrete_sscc, discrete_traditional;  ///< empty unless options.discrete
  int traditional_every = 1;
  std::vector<int> compared;  ///< the steps on which the traditional query ran
  int identical_steps = 0;    ///< of those, SSCC and traditional reports identical
  int identical_discrete_steps = 0;
  int all_certified_steps = 0;  ///< no object needed a traversal
  long object_steps_certified = 0, object_steps_traversed = 0;
  int impacts = 0;             ///< landings and strikes
  std::vector<double> fcl_ms;  ///< per sampled step, all objects
  int fcl_object_steps = 0, fcl_identical = 0;
  SettledDisagreements fcl_settled;
  std::vector<std::vector<ObjectStep>> recorded;  ///< with options.record_steps
  ContactTotals contacts;
  double largest_norm = 0.0;  ///< the largest ||q||_M an object reached at the end of a step
  std::vector<double> sound;  ///< the modal sound at the end of every step (DemoScene::modal_sound)
  double seconds = 0.0;

  /// Mean SSCC time per step (every step) over mean traditional time per step (the steps it ran on).
  double speedup() const;
  /// The same on the compared steps alone.
  double compared_speedup() const;
  /// Mean time per step on one thread over that on every thread (0 when threads == 1).
  double thread_speedup(const MethodTimes& one_thread, const MethodTimes& all) const;
  double discrete_speedup() const;
  bool agree() const;
};

SceneRun run_scene(const SceneRunOptions& options, std::ostream& progress);

}  // namespace sscc::validation
