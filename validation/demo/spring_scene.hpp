// The demo's second scene, in the spirit of the SSCC paper's clattering spring: springs
// (spring_mesh.hpp) held compressed and released, then struck down onto their top coil
// after every interval, so that compressions run through them and neighbouring coils clash;
// free linear modal vibration between (modal_dynamics.hpp). The springs stand on the ground
// (the plane of the rest mesh's lowest point), which holds their bottom coils up, and their
// coils respond to each other's contacts (contact_response.hpp). The compression is the static
// response to a load pressing the end coils together, scaled to shorten the spring by a
// fraction of its height; a strike is the impulse m v of the spring's mass m at a speed v
// drawn from the strike speed range, spread over the top coil's vertices. Springs stand
// side by side, still.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "demo/demo_scene.hpp"

namespace sscc::validation {

struct SpringSceneOptions {
  SceneMotionOptions motion;
  /// The shortening at release, a fraction of the height: the coils stand half a pitch
  /// minus two tube radii apart (44% of the half pitch for the default shape), so the default
  /// 0.25 keeps them apart at release and lets the released motion bring some together.
  double initial_compression = 0.25;
  double strike_speed_min = 7.0;  ///< m/s
  double strike_speed_max = 12.0;
  double strike_interval = 2.5;  ///< s between strikes of one spring
  double spacing = 1.3;          ///< side-by-side pitch, in units of the spring's largest extent
  ContactResponseOptions response;
};

/// Events: strikes.
class SpringScene : public DemoScene {
 public:
  /// The basis must be the modal one (weights omega^2 / 2), the mesh's axis z; mass in kg.
  SpringScene(const SubspaceModel& model, double mass, const SpringSceneOptions& options);
  std::vector<ObjectStep> step() override;

 private:
  void strike(Body& s);
  std::vector<ResponseBody> response_bodies() override;
  std::vector<PlaneContact> ground_contacts() override;

  SpringSceneOptions options_;
  std::vector<int> top_;     ///< the vertices a strike hits
  std::vector<int> bottom_;  ///< the vertices that can reach the ground
  std::vector<Body> springs_;
};

}  // namespace sscc::validation
