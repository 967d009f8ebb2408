// The demo's contact response: what a simulator does with the scene's report after each step.
//
// Every feature contact the CCD reported for the step (self-contacts per object, contacts
// between objects) and every ground contact becomes one constraint on the gap between its
// contact points, measured along its normal at the time of impact (contact_geometry.hpp):
// gap = n . sum_i w_i x_i, linear in each object's reduced coordinates q and rigid
// translation, with gradient a = sum_i w_i U_i^T R^T n in q (U_i: vertex i's 3 rows of the
// mass-normalised modes) and (sum_i w_i) n in the translation. The response then, at the end
// of the step, by projected Gauss-Seidel sweeps over the constraints:
//  1. pushes the configuration back until every gap is at least `separation` (a position
//     projection, the mass-weighted least change: dq = lambda a, dt = lambda n / m), and
//  2. applies impulses at the contact points (dv = j a, dV = j n / m, j >= 0) until no
//     contact point approaches along its normal faster than `restitution` times its
//     approach speed before the response.
// Why not penalty forces (the SSCC paper's choice): continuous detection reports a contact
// only in the step where the features meet, after which a penalty force would have to act on
// a pair that is already interpenetrating and that the next step's continuous query no
// longer reports (it starts in contact); at the demo's steps (10 ms for stiff rubber) a
// penalty stiff enough to stop an ear within one step is also unstable. The projection
// removes the interpenetration in the very step it happened, so the next step starts free of
// contact, as continuous detection assumes, and the impulses stop the features from meeting
// again at once; both use only the reported contacts, at their time of impact.
// Rotations of the rigid frames are not changed (the scenes hold their yaw fixed): the
// angular part of an impulse is dropped.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "demo/modal_dynamics.hpp"
#include "sscc/scene/scene.hpp"

namespace sscc::validation {

/// One object as the response sees it: its modes and rigid frame, changed in place.
struct ResponseBody {
  const SubspaceModel* model = nullptr;  ///< modal basis: weights omega^2 / 2, modes mass-normalised
  ModalDynamics* modes = nullptr;
  RigidFrame* frame = nullptr;  ///< at the end of the step
  /// The rigid translation's velocity (m/s, world); null when the frame is held in place.
  Eigen::Vector3d* velocity = nullptr;
  /// Which world axes the rigid translation may move along (1 or 0 per axis): a body resting
  /// on the ground is held vertically.
  Eigen::Vector3d mobility = Eigen::Vector3d::Ones();
  double mass = 1.0;  ///< kg
};

/// A vertex of an object that ended the step below a plane (n . x_world < offset).
struct PlaneContact {
  int object;
  int vertex;
  Eigen::Vector3d normal;  ///< unit, world, out of the ground
  double offset;
};

struct ContactResponseOptions {
  double restitution = 0.0;  ///< fraction of the normal approach speed returned
  /// m: the gap restored along each mesh contact's normal (ground contacts are restored to
  /// zero). Positive, so that the next step starts with the features apart, as continuous
  /// detection assumes; small against the features, so that the push is not felt.
  double separation = 1e-5;
  int iterations = 30;  ///< Gauss-Seidel sweeps for the positions and for the velocities
};

/// What the response used and found, for checks and reports.
struct ResponseRecord {
  std::vector<std::vector<FeatureContact>> self;  ///< per object: the self-contacts turned into constraints
  std::vector<InterObjectFeature> inter;          ///< the contacts between objects turned into constraints
  int ground = 0;                                 ///< ground contacts
  /// m: the largest -gap over the constraints at the end of the step, before the response
  /// (how far the contact points had passed through each other), and after it.
  double deepest_penetration = 0.0;
  double residual_penetration = 0.0;
  int constraints() const;
};

/// Responds to the step's report (`steps`: the motions that were queried; `bodies`: the
/// objects in the report's order, in their state at the end of the step).
ResponseRecord respond_to_contacts(const SceneReport& report, const std::vector<ObjectStep>& steps,
                                   const std::vector<ResponseBody>& bodies, const std::vector<PlaneContact>& ground,
                                   const ContactResponseOptions& options);

}  // namespace sscc::validation
