// What the demo's scenes share: instances of one modal model moved by linear modal dynamics
// and rigid frames, stepped together and excited by events (landings, strikes). The scene
// runner drives any of them through this interface.
#pragma once

#include <Eigen/Core>

#include <random>
#include <vector>

#include "demo/modal_dynamics.hpp"
#include "sscc/geometry/aabb.hpp"
#include "sscc/model/subspace_model.hpp"
#include "sscc/scene/scene.hpp"

namespace sscc::validation {

class DemoScene {
 public:
  virtual ~DemoScene() = default;
  /// Advances every object one step and returns their motions over it.
  virtual std::vector<ObjectStep> step() = 0;
  /// The events (impacts, strikes) so far.
  int events() const { return events_; }

 protected:
  /// `mass`: one body's mass (kg); the basis must be the modal one (weights omega^2 / 2).
  DemoScene(const SubspaceModel& model, double mass, const SceneMotionOptions& motion);

  /// One object: its modes, its rigid frame and when it is struck next (s).
  struct Body {
    ModalDynamics modes;
    RigidFrame frame;
    double next_strike = 0.0;
  };

  /// A body's modes at rest: the model's frequencies, the motion's damping and time step.
  ModalDynamics modes_at_rest() const;
  /// The distance between neighbouring objects: `spacing` times the mesh's largest extent.
  double pitch(double spacing) const { return spacing * (rest_box_.hi - rest_box_.lo).maxCoeff(); }

  SubspaceModel model_;
  double mass_;
  SceneMotionOptions motion_;
  Aabb rest_box_;  ///< the rest mesh's bounding box
  std::mt19937_64 rng_;
  double time_ = 0.0;
  int events_ = 0;
};

}  // namespace sscc::validation
