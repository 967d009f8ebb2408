#include "sscc/scene/scene.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>

#include "common/finite.hpp"
#include "common/parallel_tasks.hpp"
#include "scene/inter_object_ccd.hpp"
#include "sscc/common/timing.hpp"

namespace sscc {

namespace {

void check_frame(const RigidFrame& frame, int object) {
  const std::string where = "Scene::step: object " + std::to_string(object) + ": ";
  if (!all_finite(frame.rotation) || !all_finite(frame.translation)) {
    throw std::invalid_argument(where + "the rigid frame has a NaN or infinity");
  }
  const double deviation =
      (frame.rotation.transpose() * frame.rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
#ifdef SSCC_MUTANT_ACCEPT_REFLECTIONS
  if (!(deviation <= kRotationTolerance)) {
#else
  if (!(deviation <= kRotationTolerance) || !(frame.rotation.determinant() > 0.0)) {
#endif
    throw std::invalid_argument(where + "the frame's rotation is not a rotation (R^T R - I reaches " +
                                std::to_string(deviation) + ", or det R <= 0)");
  }
}

bool is_static(const ObjectStep& s) { return s.q0 == s.q1 && s.frame0 == s.frame1; }

/// The angle (radians, in [0, pi]) of the rotation from the step's first frame to its last:
/// atan2 of the sine (half the skew part's norm) and the cosine ((trace - 1) / 2), accurate
/// at every angle.
double step_rotation(const ObjectStep& s) {
  const Eigen::Matrix3d relative = s.frame1.rotation * s.frame0.rotation.transpose();
  const Eigen::Vector3d skew(relative(2, 1) - relative(1, 2), relative(0, 2) - relative(2, 0),
                             relative(1, 0) - relative(0, 1));
  return std::atan2(0.5 * skew.norm(), 0.5 * (relative.trace() - 1.0));
}

void check_object_frame_rotation(const ObjectStep& s, double bound, int object) {
  const double angle = step_rotation(s);
  if (angle > bound) {
    throw std::invalid_argument("Scene::step: object " + std::to_string(object) + ": its frame turns by " +
                                std::to_string(angle) + " rad over the step, more than max_object_frame_rotation (" +
                                std::to_string(bound) +
                                " rad) for a self test in the object's frame; take smaller steps, or set "
                                "SceneObjectOptions::self_motion = SelfMotion::kWorldLinear");
  }
}

/// Whether the object's self test runs on world-space straight-line paths, which differ from
/// the object-frame motion (up to a translation linear in t) only when the frame turns.
bool self_test_in_world(const SceneObjectOptions& options, const ObjectStep& s) {
  return options.self_motion == SelfMotion::kWorldLinear && s.frame0.rotation != s.frame1.rotation;
}

/// The earliest time of impact over the objects' self contacts and the contacts between
/// objects (1 when nothing collided).
double earliest_toi(const SceneReport& report) {
  double earliest = 1.0;
  for (const ObjectSelfResult& o : report.objects) {
    if (o.report.collided()) earliest = std::min(earliest, o.report.earliest_toi);
  }
  for (const InterObjectContact& c : report.contacts) earliest = std::min(earliest, c.toi);
  return earliest;
}

/// Keeps only what happens at the step's earliest time of impact.
void keep_earliest(SceneReport& report) {
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
    return std::make_tuple(x.object_first, x.first, x.object_second, x.second) <
           std::make_tuple(y.object_first, y.first, y.object_second, y.second);
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
  objects_.push_back({detector, options});
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

namespace {

/// The self query on the world-space straight-line paths of the object's vertices
/// (SelfCcd::query_positions: no certificates), whose world positions are computed as between
/// objects.
SelfCcdReport world_linear_self_test(const SelfCcd& detector, const ObjectStep& s, const SelfCcdOptions& options) {
  detail::ObjectMotion motion(detector.bvh(), s);
  const int vertices = detector.bvh().model().mesh().vertex_count();
  std::vector<Eigen::Vector3d> x0(vertices), x1(vertices);
  for (int v = 0; v < vertices; ++v) {
    x0[v] = motion.start(v);
    x1[v] = motion.end(v);
  }
  return detector.query_positions(x0, x1, options);
}

/// What one object pair's traversal found.
struct PairOutcome {
  std::vector<InterObjectFeature> features;
  std::vector<InterObjectContact> contacts;
  long box_tests = 0, triangle_pairs = 0, kernel_calls = 0;
  bool stopped = false;
};

/// An object pair whose root sweeps meet (object_b >= 0), or an object whose self test
/// needs a traversal (object_b < 0): the tasks of a step, in the serial order.
struct SceneTask {
  int object_a, object_b;
};

}  // namespace

SceneReport Scene::step(const std::vector<ObjectStep>& steps, const SceneOptions& options) const {
  const auto start = std::chrono::steady_clock::now();
  std::vector<const SelfCcd*> detectors;
  for (const Object& o : objects_) detectors.push_back(&o.detector);
  Motions motions(detectors, steps);
  const int n = object_count();
  for (int i = 0; i < n; ++i) {
    const SceneObjectOptions& o = objects_[i].options;
    if (o.self_collision && o.self_motion == SelfMotion::kObjectFrame) {
      check_object_frame_rotation(steps[i], options.max_object_frame_rotation, i);
    }
  }
  SelfCcdOptions self_options = options;
  self_options.threads = 1;
  const bool any_hit = options.mode == SelfCcdMode::kAnyHit;

  // Decided before any thread starts: switched-off, static and root-certified objects,
  // object pairs whose root sweeps do not meet. The rest become tasks in the serial order.
  std::vector<ObjectSelfResult> self(n);
  std::vector<SceneTask> tasks;
  const auto self_start = std::chrono::steady_clock::now();
  for (int i = 0; i < n; ++i) {
    if (!objects_[i].options.self_collision) {
      self[i].outcome = SelfTestOutcome::kSwitchedOff;
    } else if (is_static(steps[i])) {  // nothing can come into contact
      self[i].outcome = SelfTestOutcome::kStatic;
    } else if (self_test_in_world(objects_[i].options, steps[i])) {  // no certificate covers it
      tasks.push_back({i, -1});
    } else if (objects_[i].detector.root_certifies(steps[i].q0, steps[i].q1, self_options)) {
      self[i].report = objects_[i].detector.query(steps[i].q0, steps[i].q1, self_options);
      self[i].outcome = SelfTestOutcome::kCertified;
    } else {
      tasks.push_back({i, -1});
    }
  }
  double self_seconds = seconds_since(self_start);
  struct PairEntry {
    int a, b;
    bool culled;
    long box_tests;
  };
  std::vector<PairEntry> pairs;
  const auto inter_start = std::chrono::steady_clock::now();
  for (int a = 0; a < n; ++a) {
    if (!objects_[a].options.inter_object) continue;
    for (int b = a + 1; b < n; ++b) {
      if (!objects_[b].options.inter_object) continue;
      if (is_static(steps[a]) && is_static(steps[b])) {
        pairs.push_back({a, b, true, 0});
        continue;
      }
      detail::InterObjectCcd pair(motions[a], a, motions[b], b, options);
      const bool meet = pair.roots_meet();
      pairs.push_back({a, b, !meet, pair.box_tests()});
      if (meet) tasks.push_back({a, b});
    }
  }
  double inter_seconds = seconds_since(inter_start);

  // The tasks: self tests that would traverse on every thread (SelfCcd::query_threads: far
  // past their certificates, or without any), when fewer than the threads, run first, one after another, each
  // on every thread; on one thread beside small tasks, such a self test keeps the other
  // threads waiting for it (the default demo on two threads: SSCC 1.38 and 1.44 ms per step
  // against 1.69 and 1.48 ms before this rule). The other tasks then share the threads, each
  // on one, the wide ones first when there are as many as the threads; the objects' motions
  // are per thread (they cache as they go).
  const int all_threads = detail::resolve_threads(options.threads);
  SelfCcdOptions every_thread = self_options;
  every_thread.threads = all_threads;
  std::vector<int> wide, narrow;
  for (int k = 0; k < static_cast<int>(tasks.size()); ++k) {
    const SceneTask& task = tasks[k];
    const bool is_wide = task.object_b < 0 && all_threads > 1 &&
                         !self_test_in_world(objects_[task.object_a].options, steps[task.object_a]) &&
                         objects_[task.object_a].detector.query_threads(steps[task.object_a].q0,
                                                                        steps[task.object_a].q1, every_thread) > 1;
    (is_wide ? wide : narrow).push_back(k);
  }
  std::vector<int> shared;  // the tasks run one per thread, in this order
  if (static_cast<int>(wide.size()) >= all_threads) shared = wide, wide.clear();
  shared.insert(shared.end(), narrow.begin(), narrow.end());
  const int threads = std::max(1, std::min(all_threads, static_cast<int>(shared.size())));
  std::vector<PairOutcome> outcomes(tasks.size());
  std::vector<double> task_seconds(tasks.size(), 0.0);
  std::vector<std::unique_ptr<Motions>> thread_motions(threads);
  detail::FirstHitTask first_hit;
  const auto run = [&](int k, int thread, int query_threads) {
    if (any_hit && first_hit.cancels(k)) return;
    const auto task_start = std::chrono::steady_clock::now();
    const SceneTask& task = tasks[k];
    bool hit = false;
    if (task.object_b < 0) {
      ObjectSelfResult& result = self[task.object_a];
      SelfCcdOptions traversal = self_options;
      traversal.threads = query_threads;
      const Object& object = objects_[task.object_a];
      const ObjectStep& s = steps[task.object_a];
      if (self_test_in_world(object.options, s)) {
        result.report = world_linear_self_test(object.detector, s, traversal);
      } else {
        result.report = object.detector.query(s.q0, s.q1, traversal);
      }
      result.outcome = result.report.stats.root_certified ? SelfTestOutcome::kCertified : SelfTestOutcome::kTraversed;
      hit = result.report.collided();
    } else {
      if (!thread_motions[thread]) thread_motions[thread] = std::make_unique<Motions>(detectors, steps);
      Motions& m = *thread_motions[thread];
      detail::InterObjectCcd pair(m[task.object_a], task.object_a, m[task.object_b], task.object_b, options);
      pair.run();
      PairOutcome& outcome = outcomes[k];
      outcome.features = pair.features();
      outcome.contacts = pair.contacts();
      outcome.box_tests = pair.box_tests();
      outcome.triangle_pairs = pair.triangle_pairs();
      outcome.kernel_calls = pair.kernel_calls();
      outcome.stopped = pair.stopped();
      hit = outcome.stopped;
    }
    task_seconds[k] = seconds_since(task_start);
    if (any_hit && hit) first_hit.hit(k);
  };
  // Each task's error is kept by its index and the first in task order rethrown, as on one
  // thread, whatever order the tasks ran in.
  std::vector<std::exception_ptr> errors(tasks.size());
  const auto run_keeping_error = [&](int k, int thread, int query_threads) {
    try {
      run(k, thread, query_threads);
    } catch (...) {
      errors[k] = std::current_exception();
    }
  };
  for (int k : wide) run_keeping_error(k, 0, all_threads);
  if (shared.size() == 1 && tasks[shared[0]].object_b < 0) {
    run_keeping_error(shared[0], 0, all_threads);  // the query decides how many it uses
  } else {
    detail::run_tasks(static_cast<int>(shared.size()), threads,
                      [&](int i, int thread) { run_keeping_error(shared[i], thread, 1); });
  }
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }

  // Merged in the serial order: self tests, then object pairs, up to the first hit in the
  // any-hit mode (what comes after it is left out, as the serial step never reaches it).
  SceneReport report;
  report.objects.resize(n);
  bool stop = false;
  for (int i = 0; i < n && !stop; ++i) {
    report.objects[i] = std::move(self[i]);
    const SelfTestOutcome outcome = report.objects[i].outcome;
    report.stats.objects_static += outcome == SelfTestOutcome::kStatic;
    report.stats.objects_certified += outcome == SelfTestOutcome::kCertified;
    report.stats.objects_traversed += outcome == SelfTestOutcome::kTraversed;
    stop = any_hit && report.objects[i].report.collided();
  }
  std::size_t k = 0;
  while (k < tasks.size() && tasks[k].object_b < 0) self_seconds += task_seconds[k++];
  for (const PairEntry& entry : pairs) {
    if (stop) break;
    ++report.stats.object_pairs;
    report.stats.inter_box_tests += entry.box_tests;
    if (entry.culled) {
      ++report.stats.object_pairs_culled;
      continue;
    }
    inter_seconds += task_seconds[k];
    const PairOutcome& outcome = outcomes[k++];
    report.stats.inter_box_tests += outcome.box_tests;
    report.stats.inter_triangle_pairs += outcome.triangle_pairs;
    report.stats.inter_kernel_calls += outcome.kernel_calls;
    report.features.insert(report.features.end(), outcome.features.begin(), outcome.features.end());
    report.contacts.insert(report.contacts.end(), outcome.contacts.begin(), outcome.contacts.end());
    stop = outcome.stopped;
  }
  report.stats.inter_vertices_computed = motions.vertices_computed();
  for (const auto& m : thread_motions) report.stats.inter_vertices_computed += m ? m->vertices_computed() : 0;
  report.stats.self_seconds = self_seconds;
  report.stats.inter_seconds = inter_seconds;
  sort_inter(report);
  report.earliest_toi = earliest_toi(report);
  if (options.mode == SelfCcdMode::kEarliest) keep_earliest(report);
  report.stats.seconds = seconds_since(start);
  return report;
}

std::vector<InterObjectContact> Scene::inter_object_exhaustive(const std::vector<ObjectStep>& steps,
                                                               const SceneOptions& options) const {
  std::vector<const SelfCcd*> detectors;
  for (const Object& o : objects_) detectors.push_back(&o.detector);
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
