#include "demo/modal_dynamics.hpp"

#include <cmath>
#include <stdexcept>

namespace sscc::validation {

ModalDynamics::ModalDynamics(const Eigen::VectorXd& omega_squared, double damping_ratio, double dt)
    : qq_(omega_squared.size()),
      qv_(omega_squared.size()),
      vq_(omega_squared.size()),
      vv_(omega_squared.size()),
      omega_squared_(omega_squared),
      damping_(omega_squared.size()),
      q_(Eigen::VectorXd::Zero(omega_squared.size())),
      v_(Eigen::VectorXd::Zero(omega_squared.size())) {
  if (!(damping_ratio >= 0.0 && damping_ratio < 1.0) || !(dt > 0.0)) {
    throw std::invalid_argument("modal dynamics: damping ratio must be in [0, 1) and the time step positive");
  }
  for (Eigen::Index i = 0; i < omega_squared.size(); ++i) {
    if (!(omega_squared[i] > 0.0)) throw std::invalid_argument("modal dynamics: every mode needs omega^2 > 0");
    // Underdamped oscillator: q(t) = e^{-a t} (A cos(w t) + B sin(w t)), a = zeta omega,
    // w = omega sqrt(1 - zeta^2).
    const double omega = std::sqrt(omega_squared[i]);
    const double a = damping_ratio * omega;
    damping_[i] = 2.0 * a;
    const double w = omega * std::sqrt(1.0 - damping_ratio * damping_ratio);
    const double decay = std::exp(-a * dt), c = std::cos(w * dt), s = std::sin(w * dt);
    qq_[i] = decay * (c + a / w * s);
    qv_[i] = decay * s / w;
    vq_[i] = -decay * omega_squared[i] / w * s;
    vv_[i] = decay * (c - a / w * s);
  }
}

void ModalDynamics::hold_at(const Eigen::VectorXd& q) {
  if (q.size() != q_.size()) throw std::invalid_argument("modal dynamics: q has the wrong size");
  q_ = q;
  v_.setZero();
}

Eigen::VectorXd ModalDynamics::acceleration() const {
  return -omega_squared_.cwiseProduct(q_) - damping_.cwiseProduct(v_);
}

void ModalDynamics::step() {
  const Eigen::VectorXd q = qq_.cwiseProduct(q_) + qv_.cwiseProduct(v_);
  v_ = vq_.cwiseProduct(q_) + vv_.cwiseProduct(v_);
  q_ = q;
}

Eigen::VectorXd modal_impulse(const SubspaceModel& model, const std::vector<int>& vertices,
                              const Eigen::Vector3d& total) {
  if (vertices.empty()) throw std::invalid_argument("modal impulse: no vertex to apply it to");
  Eigen::VectorXd impulse = Eigen::VectorXd::Zero(model.mode_count());
  const Eigen::Vector3d share = total / static_cast<double>(vertices.size());
  for (int v : vertices) impulse += model.scaled_basis().middleRows<3>(3 * v).transpose() * share;
  return impulse.cwiseProduct(model.weights().cwiseSqrt());
}

}  // namespace sscc::validation
