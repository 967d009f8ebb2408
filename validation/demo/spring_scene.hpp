// The demo's second scene, in the spirit of the SSCC paper's clattering spring: springs
// (spring_mesh.hpp) struck down onto their top coil, so that a compression runs through
// them and neighbouring coils clash, then free linear modal vibration
// (modal_dynamics.hpp). A strike is the impulse m v of the spring's mass m at a speed v
// drawn from the strike speed range, spread over the top coil's vertices. Each spring is
// struck at its own time and again after every interval; springs stand side by side, still.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "demo/modal_dynamics.hpp"
#include "sscc/model/subspace_model.hpp"
#include "sscc/scene/scene.hpp"

namespace sscc::validation {

struct SpringSceneOptions {
  SceneMotionOptions motion;
  double strike_speed_min = 7.0;  ///< m/s
  double strike_speed_max = 12.0;
  double strike_interval = 2.5;   ///< s between strikes of one spring
  double spacing = 1.3;           ///< side-by-side pitch, in units of the spring's largest extent
};

class SpringScene {
 public:
  /// The basis must be the modal one (weights omega^2 / 2), the mesh's axis z; mass in kg.
  SpringScene(const SubspaceModel& model, double mass, const SpringSceneOptions& options);
  std::vector<ObjectStep> step();
  int strikes() const { return strikes_; }

 private:
  struct Spring {
    ModalDynamics modes;
    RigidFrame frame;
    double next_strike;
  };
  void strike(Spring& s);

  const SubspaceModel& model_;
  double mass_;
  SpringSceneOptions options_;
  std::mt19937_64 rng_;
  std::vector<int> top_;  ///< the vertices a strike hits
  std::vector<Spring> springs_;
  double time_ = 0.0;
  int strikes_ = 0;
};

}  // namespace sscc::validation
