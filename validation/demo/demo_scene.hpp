// What the demo's scenes share: instances of one modal model moved by linear modal dynamics
// and rigid frames, stepped together and excited by events (landings, strikes), responding
// to the contacts the CCD finds in each step (contact_response.hpp). The scene runner drives
// any of them through this interface: step(), the scene's CCD on the returned motions, then
// respond() with its report.
#pragma once

#include <Eigen/Core>

#include <random>
#include <vector>

#include "demo/contact_response.hpp"
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
  /// The contact response to the step just taken: `report` is the scene's CCD of `steps`,
  /// the motions step() returned; ground contacts are the scene's own. Changes the bodies'
  /// modes and frames; returns what it used.
  ResponseRecord respond(const SceneReport& report, const std::vector<ObjectStep>& steps);
  /// Every object's reduced coordinates now (after the response).
  std::vector<Eigen::VectorXd> configurations();
  /// The sound pressure now, up to a constant: the sum of every mode's acceleration over the
  /// objects (every mode radiating alike: a stand-in for a radiation model), the contact
  /// forces of the last response included (their impulses over the step's length): the
  /// clicks of the clatter, since the modes themselves may ring below hearing.
  double modal_sound();
  /// The events (impacts, strikes) so far.
  int events() const { return events_; }

 protected:
  /// `mass`: one body's mass (kg); the basis must be the modal one (weights omega^2 / 2).
  DemoScene(const SubspaceModel& model, double mass, const SceneMotionOptions& motion,
            const ContactResponseOptions& response);

  /// One object: its modes, its rigid frame, when it is struck next (s) and its rigid
  /// translation's velocity (m/s, world).
  struct Body {
    ModalDynamics modes;
    RigidFrame frame;
    double next_strike = 0.0;
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  };

  /// The objects as the response sees them, in order.
  virtual std::vector<ResponseBody> response_bodies() = 0;
  /// The vertices below the ground at the end of the step (none by default).
  virtual std::vector<PlaneContact> ground_contacts() { return {}; }

  /// A body's modes at rest: the model's frequencies, the motion's damping and time step.
  ModalDynamics modes_at_rest() const;
  /// The distance between neighbouring objects: `spacing` times the mesh's largest extent.
  double pitch(double spacing) const { return spacing * (rest_box_.hi - rest_box_.lo).maxCoeff(); }

  SubspaceModel model_;
  double mass_;
  SceneMotionOptions motion_;
  ContactResponseOptions response_;
  double contact_acceleration_ = 0.0;  ///< the last response's, summed over the modes (1/s^2)
  Aabb rest_box_;                      ///< the rest mesh's bounding box
  std::mt19937_64 rng_;
  double time_ = 0.0;
  int events_ = 0;
};

}  // namespace sscc::validation
