#include "load_run.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <random>
#include <stdexcept>
#include <vector>

#include "feature_brute_force.hpp"
#include "progress_bar.hpp"
#include "sscc/bvh/subspace_bvh.hpp"
#include "sscc/certificates/certificates.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "sscc/scene/scene.hpp"
#include "sscc/threads.hpp"
#include "stress_inputs.hpp"

namespace sscc::validation {

namespace {

constexpr int kObjects = 2;
constexpr int kModes = 9;
/// Centre spacing of the unit spheres: a 0.6 gap at rest.
constexpr double kSpacing = 2.6;
/// Sway of each object along the row (radians per step, and amplitude in radii): neighbours,
/// a radian apart in phase, come within 0.36 of each other, which deformation closes now and then.
constexpr double kSwayRate = 0.05;
constexpr double kSwayAmplitude = 0.25;
/// The coordinates' walk: q <- kMemory q + noise, ||q||_M hovering near kWalkNorm root radii
/// (most steps certified, some traversed, a few colliding).
constexpr double kMemory = 0.98;
constexpr double kWalkNorm = 0.5;

/// The resident set size now, in kB (the peak would remember whatever ran before).
long resident_kb() {
  long pages = 0, resident = 0;
  std::ifstream statm("/proc/self/statm");
  if (!(statm >> pages >> resident)) throw std::runtime_error("cannot read /proc/self/statm");
  return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

std::string scene_difference(const SceneReport& serial, const SceneReport& parallel) {
  for (std::size_t o = 0; o < serial.objects.size(); ++o) {
    if (serial.objects[o].outcome != parallel.objects[o].outcome) {
      return "object " + std::to_string(o) + ": self-test outcome differs";
    }
    const std::string self = report_difference(serial.objects[o].report, parallel.objects[o].report);
    if (!self.empty()) return "object " + std::to_string(o) + ": " + self;
  }
  if (!(serial.contacts == parallel.contacts)) return "contacts between objects differ";
  if (!(serial.features == parallel.features)) return "features between objects differ";
  if (serial.collided() && serial.earliest_toi != parallel.earliest_toi) return "earliest time differs";
  return "";
}

}  // namespace

LoadRunResult run_load(const LoadRunOptions& options, std::ostream& progress) {
  const auto start = std::chrono::steady_clock::now();
  LoadRunResult result;
  const TriangleMesh mesh = stress_sphere(6, 8);
  const SubspaceModel model(mesh, polynomial_basis(mesh, kModes), Eigen::VectorXd::Ones(kModes));
  const SubspaceBvh bvh(model);
  const SelfCcd detector(bvh, Certificates::precompute(bvh));
  Scene scene;
  for (int o = 0; o < kObjects; ++o) scene.add_object(detector);
  result.objects = kObjects;
  result.triangles = mesh.triangle_count();
  result.modes = kModes;
  result.threads = default_threads();
  const double root = detector.certificates()->node_radius(0);
  const double noise_scale = kWalkNorm * root * std::sqrt(1 - kMemory * kMemory) / std::sqrt(double(kModes));

  std::mt19937_64 rng(options.seed);
  std::normal_distribution<double> normal;
  std::vector<Eigen::VectorXd> q(kObjects, Eigen::VectorXd::Zero(kModes));
  const auto frame_at = [](int object, long step) {
    RigidFrame frame;
    frame.translation.x() = kSpacing * object + kSwayAmplitude * std::sin(kSwayRate * step + object);
    return frame;
  };
  SceneOptions serial;
  serial.threads = 1;
  result.warm_up_steps = std::max(1L, options.steps / 10);
  std::vector<ObjectStep> steps(kObjects);
  ProgressBar bar(progress, "load");
  for (long s = 0; s < options.steps; ++s) {
    for (int o = 0; o < kObjects; ++o) {
      steps[o].q0 = q[o];
      for (int i = 0; i < kModes; ++i) q[o][i] = kMemory * q[o][i] + noise_scale * normal(rng);
      steps[o].q1 = q[o];
      steps[o].frame0 = frame_at(o, s);
      steps[o].frame1 = frame_at(o, s + 1);
    }
    const SceneReport parallel = scene.step(steps);
    const SceneReport one_thread = scene.step(steps, serial);
    result.colliding_steps += one_thread.collided();
    const std::string difference = scene_difference(one_thread, parallel);
    if (!difference.empty()) {
      if (result.mismatched_steps == 0) result.first_difference = "step " + std::to_string(s) + ": " + difference;
      ++result.mismatched_steps;
    }
    ++result.steps;
    if (result.steps == result.warm_up_steps) result.rss_warm_kb = resident_kb();
    bar.update(static_cast<double>(result.steps), static_cast<double>(options.steps), "scene steps");
  }
  bar.finish(std::to_string(result.steps) + " scene steps");
  result.rss_end_kb = resident_kb();
  result.rss_growth_kb = result.rss_end_kb - result.rss_warm_kb;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace sscc::validation
