#include "demo/ear_drop.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace sscc::validation {

namespace {

/// Fraction of the height, from the bottom, whose vertices take the landing impulse.
constexpr double kContactBand = 0.03;
/// A strike spreads over the vertices within this fraction of the extent of its point.
constexpr double kStrikeRadius = 0.08;
/// Below this landing speed (m/s) a body comes to rest.
constexpr double kRestSpeed = 0.4;

}  // namespace

double enclosed_volume(const TriangleMesh& mesh) {
  double volume = 0.0;
  for (const Triangle& t : mesh.triangles()) {
    volume += mesh.vertices()[t[0]].dot(mesh.vertices()[t[1]].cross(mesh.vertices()[t[2]])) / 6.0;
  }
  return std::fabs(volume);
}

EarDrop::EarDrop(const SubspaceModel& model, double mass, const EarDropOptions& options)
    : DemoScene(model, mass, options.motion, options.response), options_(options) {
  const TriangleMesh& mesh = model.mesh();
  const Eigen::Vector3d& lo = rest_box_.lo;
  const Eigen::Vector3d& hi = rest_box_.hi;
  lowest_ = lo.y();
  const double height = hi.y() - lo.y();
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    const double y = mesh.vertices()[v].y();
    if (y <= lo.y() + kContactBand * height) bottom_.push_back(v);
    if (y >= lo.y() + 0.5 * height) upper_.push_back(v);
  }
  const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(options.motion.objects))));
  const double spacing = pitch(options.spacing);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int i = 0; i < options.motion.objects; ++i) {
    FallingBody body{{modes_at_rest(), {}, 0.0}, false};
    body.frame.rotation = Eigen::AngleAxisd(2 * M_PI * uniform(rng_), Eigen::Vector3d::UnitY()).toRotationMatrix();
    const double drop = options.drop_height_min + (options.drop_height_max - options.drop_height_min) * uniform(rng_);
    body.frame.translation = Eigen::Vector3d(spacing * (i % side), drop - lowest_, spacing * (i / side));
    bodies_.push_back(body);
  }
}

std::vector<ObjectStep> EarDrop::step() {
  std::vector<ObjectStep> steps(bodies_.size());
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const double dt = options_.motion.dt;
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    FallingBody& b = bodies_[i];
    steps[i].q0 = b.modes.q();
    steps[i].frame0 = b.frame;
    // Sliding (after a contact with another body): free in flight, slowed by friction at rest.
    Eigen::Vector3d sliding(b.velocity.x(), 0.0, b.velocity.z());
    if (b.resting) {
      const double speed = sliding.norm(), slowed = std::max(0.0, speed - options_.friction * options_.gravity * dt);
      sliding *= speed > 0.0 ? slowed / speed : 0.0;
      b.velocity.x() = sliding.x();
      b.velocity.z() = sliding.z();
    }
    b.frame.translation += sliding * dt;
    if (!b.resting) {
      b.velocity.y() -= options_.gravity * dt;
      b.frame.translation.y() += b.velocity.y() * dt;
      const double bottom = b.frame.translation.y() + lowest_;
      if (bottom <= 0.0 && b.velocity.y() < 0.0) {
        b.frame.translation.y() = -lowest_;
        const double speed = -b.velocity.y();
        // The ground's impulse, upward in the body frame (the yaw keeps y up).
        b.modes.add_impulse(
            modal_impulse(model_, bottom_, Eigen::Vector3d(0, mass_ * (1 + options_.restitution) * speed, 0)));
        ++events_;
        b.velocity.y() = options_.restitution * speed;
        if (b.velocity.y() < kRestSpeed) {
          b.resting = true;
          b.velocity.y() = 0.0;
          b.next_strike =
              time_ + options_.strike_wait_min + (options_.strike_wait_max - options_.strike_wait_min) * uniform(rng_);
        }
      }
    } else if (time_ >= b.next_strike) {
      const int centre = upper_[std::uniform_int_distribution<std::size_t>(0, upper_.size() - 1)(rng_)];
      const Eigen::Vector3d& c = model_.mesh().vertices()[centre];
      std::vector<int> patch;
      const double extent = model_.mesh().bounding_box_diagonal();
      for (int v : upper_) {
        if ((model_.mesh().vertices()[v] - c).norm() <= kStrikeRadius * extent) patch.push_back(v);
      }
      const Eigen::Vector3d direction = Eigen::Vector3d(uniform(rng_) - 0.5, 0.0, uniform(rng_) - 0.5).normalized();
      b.modes.add_impulse(modal_impulse(model_, patch, mass_ / 20.0 * options_.strike_speed * direction));
      ++events_;
      b.next_strike =
          time_ + options_.strike_wait_min + (options_.strike_wait_max - options_.strike_wait_min) * uniform(rng_);
    }
    b.modes.step();
    steps[i].q1 = b.modes.q();
    steps[i].frame1 = b.frame;
  }
  time_ += dt;
  return steps;
}

std::vector<ResponseBody> EarDrop::response_bodies() {
  std::vector<ResponseBody> bodies;
  for (FallingBody& b : bodies_) {
    const Eigen::Vector3d mobility = b.resting ? Eigen::Vector3d(1, 0, 1) : Eigen::Vector3d::Ones();
    bodies.push_back({&model_, &b.modes, &b.frame, &b.velocity, mobility, mass_});
  }
  return bodies;
}

}  // namespace sscc::validation
