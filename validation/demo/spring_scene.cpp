#include "demo/spring_scene.hpp"

#include <algorithm>
#include <cmath>

namespace sscc::validation {

namespace {

/// Fraction of the height, at each end, whose vertices take a strike or the load.
constexpr double kEndBand = 0.05;

/// The static modal response to a unit load pressing the vertices of `top` down and those of
/// `bottom` up (q_i = f_i / omega_i^2, omega^2 = 2 w), scaled to shorten the spring (the mean
/// z of the top vertices against the bottom ones) by `shortening`.
Eigen::VectorXd compression(const SubspaceModel& model, const std::vector<int>& top, const std::vector<int>& bottom,
                            double shortening) {
  const Eigen::VectorXd force =
      modal_impulse(model, top, Eigen::Vector3d(0, 0, -1)) + modal_impulse(model, bottom, Eigen::Vector3d(0, 0, 1));
  const Eigen::VectorXd q = force.cwiseQuotient(2.0 * model.weights());
  const Eigen::VectorXd q_hat = q.cwiseProduct(model.weights().cwiseSqrt());
  const auto mean_z = [&](const std::vector<int>& vertices) {
    double z = 0.0;
    for (int v : vertices) z += model.scaled_basis().row(3 * v + 2).dot(q_hat);
    return z / static_cast<double>(vertices.size());
  };
  return q * (shortening / (mean_z(bottom) - mean_z(top)));
}

}  // namespace

SpringScene::SpringScene(const SubspaceModel& model, double mass, const SpringSceneOptions& options)
    : DemoScene(model, mass, options.motion, options.response), options_(options) {
  const TriangleMesh& mesh = model.mesh();
  const Eigen::Vector3d& lo = rest_box_.lo;
  const Eigen::Vector3d& hi = rest_box_.hi;
  const double height = hi.z() - lo.z();
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    if (mesh.vertices()[v].z() >= hi.z() - kEndBand * height) top_.push_back(v);
    if (mesh.vertices()[v].z() <= lo.z() + kEndBand * height) bottom_.push_back(v);
  }
  const Eigen::VectorXd held = compression(model, top_, bottom_, options.initial_compression * height);
  const double spacing = pitch(options.spacing);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int i = 0; i < options.motion.objects; ++i) {
    Body s{modes_at_rest(), {}, options.strike_interval * (0.5 + 0.5 * uniform(rng_))};
    s.modes.hold_at(held);
    s.frame.translation = Eigen::Vector3d(spacing * i, 0.0, 0.0);
    springs_.push_back(s);
  }
}

void SpringScene::strike(Body& s) {
  std::uniform_real_distribution<double> uniform(options_.strike_speed_min, options_.strike_speed_max);
  // Down onto the top coil, which passes the blow down the spring.
  s.modes.add_impulse(modal_impulse(model_, top_, Eigen::Vector3d(0, 0, -mass_ * uniform(rng_))));
  ++events_;
}

std::vector<ObjectStep> SpringScene::step() {
  std::vector<ObjectStep> steps(springs_.size());
  for (std::size_t i = 0; i < springs_.size(); ++i) {
    Body& s = springs_[i];
    if (time_ >= s.next_strike) {
      strike(s);
      s.next_strike = time_ + options_.strike_interval;
    }
    steps[i].q0 = s.modes.q();
    steps[i].frame0 = steps[i].frame1 = s.frame;
    s.modes.step();
    steps[i].q1 = s.modes.q();
  }
  time_ += options_.motion.dt;
  return steps;
}

std::vector<ResponseBody> SpringScene::response_bodies() {
  std::vector<ResponseBody> bodies;
  for (Body& s : springs_) bodies.push_back({&model_, &s.modes, &s.frame, nullptr, Eigen::Vector3d::Zero(), mass_});
  return bodies;
}

std::vector<PlaneContact> SpringScene::ground_contacts() {
  std::vector<PlaneContact> contacts;
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  const double ground = rest_box_.lo.z();
  for (std::size_t i = 0; i < springs_.size(); ++i) {
    const Body& s = springs_[i];
    const Eigen::VectorXd q_hat = model_.scaled_coordinates(s.modes.q());
    for (int v : bottom_) {
      const Eigen::Vector3d x = s.frame.rotation * model_.position(v, q_hat) + s.frame.translation;
      if (up.dot(x) < ground) contacts.push_back({static_cast<int>(i), v, up, ground});
    }
  }
  return contacts;
}

}  // namespace sscc::validation
