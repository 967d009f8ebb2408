// Linear modal dynamics of a reduced deformable object: q_i'' + 2 zeta omega_i q_i' +
// omega_i^2 q_i = f_i for mass-normalised modes (the modal basis' weights are omega_i^2 / 2),
// integrated exactly per step for piecewise constant forces, so the step can be as long as
// the demo needs without instability. Impulses change the modal velocities at once.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "sscc/model/subspace_model.hpp"

namespace sscc::validation {

/// What every demo scene's motion is made of: how many objects, the time step, the modes'
/// damping, the seed of its random events.
struct SceneMotionOptions {
  int objects = 1;
  double dt = 0.01;  ///< s
  double damping_ratio = 0.01;
  std::uint64_t seed = 1;
};

class ModalDynamics {
 public:
  /// omega_squared: the modes' eigenvalues (rad^2/s^2); damping ratio zeta in [0, 1); dt in s.
  ModalDynamics(const Eigen::VectorXd& omega_squared, double damping_ratio, double dt);

  const Eigen::VectorXd& q() const { return q_; }
  const Eigen::VectorXd& velocity() const { return v_; }
  /// Holds the object at q, at rest (to be let go by the next step).
  void hold_at(const Eigen::VectorXd& q);
  /// Adds an impulse in modal coordinates (Phi^T J for nodal impulses J).
  void add_impulse(const Eigen::VectorXd& modal_impulse) { v_ += modal_impulse; }
  /// Moves the modes by dq at once, keeping their velocities (a contact's position correction).
  void displace(const Eigen::VectorXd& dq) { q_ += dq; }
  /// The modes' accelerations under no force, -omega^2 q - 2 zeta omega q'.
  Eigen::VectorXd acceleration() const;
  /// Advances one step under no force.
  void step();

 private:
  // Per mode, the exact 2 x 2 propagator of (q, q') over one step.
  Eigen::VectorXd qq_, qv_, vq_, vv_;
  Eigen::VectorXd omega_squared_, damping_;  // omega^2 and 2 zeta omega per mode
  Eigen::VectorXd q_, v_;
};

/// The modal impulse Phi^T J of an impulse `total` (N s, in the body frame) spread evenly
/// over `vertices`, for a model whose basis holds mass-normalised modes Phi (its weights
/// omega^2 / 2: Phi = U_hat W^(1/2)).
Eigen::VectorXd modal_impulse(const SubspaceModel& model, const std::vector<int>& vertices,
                              const Eigen::Vector3d& total);

}  // namespace sscc::validation
