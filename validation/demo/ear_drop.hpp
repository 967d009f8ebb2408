// The demo's first scene, in the spirit of the SSCC paper's sixteen-bunny "ear drop":
// instances of one modal model on a grid, each dropped from its own height onto a ground
// plane (y = 0, y up) and, once settled, struck at random points of its upper half. Rigid
// motion: a vertical fall with gravity and a bounce (restitution e), a fixed yaw per
// object; the landing impulse m (1 + e) |v| is spread over the lowest vertices, each strike
// over the vertices near its point, and both excite the modes (Phi^T J). Linear modal
// dynamics between events (modal_dynamics.hpp). Contacts of a body with itself or with
// another body change its modes and its translation (contact_response.hpp); a body resting
// on the ground is held vertically, and its sliding is stopped by friction. Seeded;
// deterministic.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <random>
#include <vector>

#include "demo/demo_scene.hpp"

namespace sscc::validation {

struct EarDropOptions {
  SceneMotionOptions motion{16, 0.01, 0.01, 1};
  double restitution = 0.4;
  double drop_height_min = 0.2;  ///< m, lowest point above the ground at release
  double drop_height_max = 1.5;
  double strike_speed = 6.0;     ///< m/s: a strike's impulse is (mass / 20) times this
  double strike_wait_min = 1.0;  ///< s after settling, and between strikes
  double strike_wait_max = 3.0;
  double spacing = 1.3;   ///< grid pitch, in units of the mesh's largest extent
  double gravity = 9.81;  ///< m/s^2
  double friction = 0.5;  ///< Coulomb coefficient of the ground for a resting body's sliding
  ContactResponseOptions response;
};

/// Events: landings and strikes.
class EarDrop : public DemoScene {
 public:
  /// `mass`: the body's mass (kg); the basis must be the modal one (weights omega^2 / 2).
  EarDrop(const SubspaceModel& model, double mass, const EarDropOptions& options);
  std::vector<ObjectStep> step() override;

 private:
  struct FallingBody : Body {
    bool resting = false;
  };

  std::vector<ResponseBody> response_bodies() override;

  EarDropOptions options_;
  std::vector<FallingBody> bodies_;
  std::vector<int> bottom_;  ///< the vertices that touch the ground on landing
  std::vector<int> upper_;   ///< candidates for strike points
  double lowest_ = 0.0;      ///< rest mesh's lowest y
};

/// The volume a closed surface encloses (divergence theorem; approximate for open ones).
double enclosed_volume(const TriangleMesh& mesh);

}  // namespace sscc::validation
