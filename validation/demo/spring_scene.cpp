#include "demo/spring_scene.hpp"

#include <algorithm>
#include <cmath>

namespace sscc::validation {

namespace {

/// Fraction of the height, at the top, whose vertices take a strike.
constexpr double kStrikeBand = 0.05;

}  // namespace

SpringScene::SpringScene(const SubspaceModel& model, double mass, const SpringSceneOptions& options)
    : model_(model), mass_(mass), options_(options), rng_(options.motion.seed) {
  const TriangleMesh& mesh = model.mesh();
  const Aabb box = mesh.bounding_box();
  const Eigen::Vector3d& lo = box.lo;
  const Eigen::Vector3d& hi = box.hi;
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    if (mesh.vertices()[v].z() >= hi.z() - kStrikeBand * (hi.z() - lo.z())) top_.push_back(v);
  }
  const Eigen::VectorXd omega_squared = 2.0 * model.weights();
  const double pitch = options.spacing * (hi - lo).maxCoeff();
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int i = 0; i < options.motion.objects; ++i) {
    Spring s{ModalDynamics(omega_squared, options.motion.damping_ratio, options.motion.dt), {}, uniform(rng_) * 0.5};
    s.frame.translation = Eigen::Vector3d(pitch * i, 0.0, 0.0);
    springs_.push_back(s);
  }
}

void SpringScene::strike(Spring& s) {
  std::uniform_real_distribution<double> uniform(options_.strike_speed_min, options_.strike_speed_max);
  // Down onto the top coil, which passes the blow down the spring.
  s.modes.add_impulse(modal_impulse(model_, top_, Eigen::Vector3d(0, 0, -mass_ * uniform(rng_))));
  ++strikes_;
}

std::vector<ObjectStep> SpringScene::step() {
  std::vector<ObjectStep> steps(springs_.size());
  for (std::size_t i = 0; i < springs_.size(); ++i) {
    Spring& s = springs_[i];
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

}  // namespace sscc::validation
