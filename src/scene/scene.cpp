#include "sscc/scene/scene.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>

#include "common/finite.hpp"
#include "scene/inter_object_ccd.hpp"

namespace sscc {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void check_frame(const RigidFrame& frame, int object) {
  const std::string where = "Scene::step: object " + std::to_string(object) + ": ";
  if (!all_finite(frame.rotation) || !all_finite(frame.translation)) {
    throw std::invalid_argument(where + "the rigid frame has a NaN or infinity");
  }
  const double deviation = (frame.rotation.transpose() * frame.rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (!(deviation <= kRotationTolerance) || !(frame.rotation.determinant() > 0.0)) {
    throw std::invalid_argument(where + "the frame's rotation is not a rotation (R^T R - I reaches " +
                                std::to_string(deviation) + ", or det R <= 0)");
  }
}

bool is_static(const ObjectStep& s) { return s.q0 == s.q1 && s.frame0 == s.frame1; }

/// Keeps only what happens at the step's earliest time of impact.
void keep_earliest(SceneReport& report) {
  report.earliest_toi = 1.0;
  for (const ObjectSelfResult& o : report.objects) {
    if (o.report.collided()) report.earliest_toi = std::min(report.earliest_toi, o.report.earliest_toi);
  }
  for (const InterObjectContact& c : report.contacts) report.earliest_toi = std::min(report.earliest_toi, c.toi);
  const double t = report.earliest_toi;
  for (ObjectSelfResult& o : report.objects) {
    if (!o.report.collided() || o.report.earliest_toi == t) continue;
    o.report.pairs.clear();
    o.report.features.clear();
    o.report.earliest_toi = 1.0;
  }
  report.contacts.erase(std::remove_if(report.contacts.begin(), report.contacts.end(),
                                       [&](const InterObjectContact& c) { return c.toi != t; }),
                        report.contacts.end());
  report.features.erase(std::remove_if(report.features.begin(), report.features.end(),
                                       [&](const InterObjectFeature& f) { return f.toi != t; }),
                        report.features.end());
}

void sort_inter(SceneReport& report) {
  std::sort(report.contacts.begin(), report.contacts.end(), [](const auto& x, const auto& y) {
    return std::make_tuple(x.object_a, x.triangle_a, x.object_b, x.triangle_b) <
           std::make_tuple(y.object_a, y.triangle_a, y.object_b, y.triangle_b);
  });
  std::sort(report.features.begin(), report.features.end(), [](const auto& x, const auto& y) {
    return std::make_tuple(x.kind, x.object_first, x.first, x.object_second, x.second) <
           std::make_tuple(y.kind, y.object_first, y.first, y.object_second, y.second);
  });
}

}  // namespace

bool SceneReport::collided() const {
  if (!contacts.empty()) return true;
  return std::any_of(objects.begin(), objects.end(), [](const ObjectSelfResult& o) { return o.report.collided(); });
}

int Scene::add_object(const SelfCcd& detector, SceneObjectOptions options) {
  objects_.push_back({&detector, options});
  return static_cast<int>(objects_.size()) - 1;
}

namespace {

/// Validates the steps and builds each object's world motion on first use.
class Motions {
 public:
  Motions(const std::vector<const SelfCcd*>& detectors, const std::vector<ObjectStep>& steps)
      : detectors_(detectors), steps_(steps), motions_(steps.size()) {
    if (steps.size() != detectors.size()) {
      throw std::invalid_argument("Scene::step: " + std::to_string(steps.size()) + " object steps given for " +
                                  std::to_string(detectors.size()) + " objects");
    }
    for (std::size_t i = 0; i < steps.size(); ++i) {
      check_frame(steps[i].frame0, static_cast<int>(i));
      check_frame(steps[i].frame1, static_cast<int>(i));
      const SubspaceModel& model = detectors[i]->bvh().model();
      try {
        model.scaled_coordinates(steps[i].q0);
        model.scaled_coordinates(steps[i].q1);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("Scene::step: object " + std::to_string(i) + ": " + e.what());
      }
    }
  }
  detail::ObjectMotion& operator[](int i) {
    if (!motions_[i]) motions_[i] = std::make_unique<detail::ObjectMotion>(detectors_[i]->bvh(), steps_[i]);
    return *motions_[i];
  }
  long vertices_computed() const {
    long n = 0;
    for (const auto& m : motions_) n += m ? m->vertices_computed() : 0;
    return n;
  }

 private:
  const std::vector<const SelfCcd*>& detectors_;
  const std::vector<ObjectStep>& steps_;
  std::vector<std::unique_ptr<detail::ObjectMotion>> motions_;
};

}  // namespace

SceneReport Scene::step(const std::vector<ObjectStep>& steps, const SceneOptions& options) const {
  const auto start = std::chrono::steady_clock::now();
  std::vector<const SelfCcd*> detectors;
  for (const Object& o : objects_) detectors.push_back(o.detector);
  Motions motions(detectors, steps);
  SceneReport report;
  report.objects.resize(objects_.size());
  SelfCcdOptions self_options;
  self_options.mode = options.mode;
  self_options.use_certificates = options.use_certificates;
  self_options.use_normal_cones = options.use_normal_cones;
  self_options.kernel = options.kernel;
  bool stop = false;
  const auto self_start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < objects_.size() && !stop; ++i) {
    ObjectSelfResult& result = report.objects[i];
    const bool moved = !is_static(steps[i]);
    if (!objects_[i].options.self_collision) {
      result.outcome = SelfTestOutcome::kSwitchedOff;
    } else if (!moved) {  // nothing can come into contact
      result.outcome = SelfTestOutcome::kStatic;
      ++report.stats.objects_static;
    } else {
      result.report = objects_[i].detector->query(steps[i].q0, steps[i].q1, self_options);
      const bool certified = result.report.stats.root_certified;
      result.outcome = certified ? SelfTestOutcome::kCertified : SelfTestOutcome::kTraversed;
      ++(certified ? report.stats.objects_certified : report.stats.objects_traversed);
      stop = options.mode == SelfCcdMode::kAnyHit && result.report.collided();
    }
  }
  report.stats.self_seconds = seconds_since(self_start);
  const auto inter_start = std::chrono::steady_clock::now();
  for (int a = 0; a < object_count() && !stop; ++a) {
    if (!objects_[a].options.inter_object) continue;
    for (int b = a + 1; b < object_count() && !stop; ++b) {
      if (!objects_[b].options.inter_object) continue;
      ++report.stats.object_pairs;
      if (is_static(steps[a]) && is_static(steps[b])) {
        ++report.stats.object_pairs_culled;
        continue;
      }
      detail::InterObjectCcd pair(motions[a], a, motions[b], b, options);
      if (!pair.roots_meet()) {
        ++report.stats.object_pairs_culled;
        report.stats.inter_box_tests += pair.box_tests();
        continue;
      }
      pair.run();
      report.stats.inter_box_tests += pair.box_tests();
      report.stats.inter_triangle_pairs += pair.triangle_pairs();
      report.stats.inter_kernel_calls += pair.kernel_calls();
      report.features.insert(report.features.end(), pair.features().begin(), pair.features().end());
      const std::vector<InterObjectContact> contacts = pair.contacts();
      report.contacts.insert(report.contacts.end(), contacts.begin(), contacts.end());
      stop = pair.stopped();
    }
  }
  report.stats.inter_vertices_computed = motions.vertices_computed();
  report.stats.inter_seconds = seconds_since(inter_start);
  sort_inter(report);
  if (options.mode == SelfCcdMode::kEarliest) {
    keep_earliest(report);
  } else {
    report.earliest_toi = 1.0;
    for (const ObjectSelfResult& o : report.objects) {
      if (o.report.collided()) report.earliest_toi = std::min(report.earliest_toi, o.report.earliest_toi);
    }
    for (const InterObjectContact& c : report.contacts) report.earliest_toi = std::min(report.earliest_toi, c.toi);
  }
  report.stats.seconds = seconds_since(start);
  return report;
}

std::vector<InterObjectContact> Scene::inter_object_exhaustive(const std::vector<ObjectStep>& steps,
                                                               const SceneOptions& options) const {
  std::vector<const SelfCcd*> detectors;
  for (const Object& o : objects_) detectors.push_back(o.detector);
  Motions motions(detectors, steps);
  SceneReport report;
  for (int a = 0; a < object_count(); ++a) {
    for (int b = a + 1; b < object_count(); ++b) {
      if (!objects_[a].options.inter_object || !objects_[b].options.inter_object) continue;
      detail::InterObjectCcd pair(motions[a], a, motions[b], b, options);
      pair.run_exhaustive();
      const std::vector<InterObjectContact> contacts = pair.contacts();
      report.contacts.insert(report.contacts.end(), contacts.begin(), contacts.end());
    }
  }
  sort_inter(report);
  return report.contacts;
}

}  // namespace sscc
