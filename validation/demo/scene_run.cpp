#include "demo/scene_run.hpp"

#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

#include "demo/ear_drop.hpp"
#include "demo/spring_scene.hpp"
#include "fcl_self_ccd.hpp"
#include "sscc/scene/scene.hpp"
#include "sscc/threads.hpp"
#include "statistics.hpp"

namespace sscc::validation {

namespace {

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// A scene's defaults.
struct Preset {
  std::string mesh, generated_mesh, basis_kind;
  int modes, objects;
  ElasticMaterial material;
  double damping_ratio;
  bool spring_motion;
};

Preset preset(const std::string& scene) {
  const ElasticMaterial rubber{2.0e7, 0.4, 1100.0}, steel{2.0e11, 0.3, 7800.0};
  if (scene == "bunnies") return {"", "", "modal", 30, 16, rubber, 0.1, false};
  if (scene == "spring") return {"", "spring", "modal", 20, 1, steel, 0.02, true};
  if (scene == "dragon") {
    return {
        data_dir() + "/../../shared/data/meshes/ChineseDragon-10kv.off", "", "polynomial", 27, 1, rubber, 0.1, false};
  }
  throw std::invalid_argument("unknown scene '" + scene + "' (bunnies, spring, dragon)");
}

bool same_reports(const SceneReport& a, const SceneReport& b) {
  if (a.contacts != b.contacts || a.features != b.features) return false;
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    if (a.objects[i].report.pairs != b.objects[i].report.pairs) return false;
    if (a.objects[i].report.features != b.objects[i].report.features) return false;
  }
  return true;
}

void add_run(MethodTimes& m, const SceneReport& r, double ms) {
  m.ms.push_back(ms);
  m.self_ms.push_back(1e3 * r.stats.self_seconds);
  m.colliding_steps += r.collided();
  for (const ObjectSelfResult& o : r.objects) m.self_pairs += static_cast<long>(o.report.pairs.size());
  m.inter_pairs += static_cast<long>(r.contacts.size());
}

/// The discrete query at each object's end configuration (self-collision only).
double discrete_step(const SelfCcd& detector, const std::vector<ObjectStep>& steps, const SelfCcdOptions& options,
                     std::vector<SelfCcdReport>& reports) {
  const auto t = std::chrono::steady_clock::now();
  reports.clear();
  for (const ObjectStep& s : steps) reports.push_back(detector.query_discrete(s.q1, options));
  return milliseconds_since(t);
}

}  // namespace

double MethodTimes::mean() const {
  double s = 0.0;
  for (double x : ms) s += x;
  return ms.empty() ? 0.0 : s / static_cast<double>(ms.size());
}

double MethodTimes::median() const { return validation::median(ms); }

double MethodTimes::max() const { return ms.empty() ? 0.0 : *std::max_element(ms.begin(), ms.end()); }

double SceneRun::speedup() const { return traditional.mean() / std::max(sscc.mean(), 1e-9); }
double SceneRun::discrete_speedup() const { return discrete_traditional.mean() / std::max(discrete_sscc.mean(), 1e-9); }
double SceneRun::thread_speedup(const MethodTimes& one_thread, const MethodTimes& all) const {
  return one_thread.ms.empty() ? 0.0 : one_thread.mean() / std::max(all.mean(), 1e-9);
}
bool SceneRun::agree() const {
  return identical_steps == steps && fcl_settled.unexplained == 0 &&
         (sscc_one_thread.ms.empty() || identical_thread_steps == steps) &&
         (discrete_sscc.ms.empty() || identical_discrete_steps == steps);
}

SceneRun run_scene(const SceneRunOptions& o, std::ostream& progress) {
  if (o.steps < 1) throw std::invalid_argument("--steps must be positive");
  if (!(o.dt > 0.0)) throw std::invalid_argument("--dt must be positive");
  const Preset p = preset(o.scene);
  const auto start = std::chrono::steady_clock::now();
  SceneRun run;
  run.scene = o.scene;
  run.steps = o.steps;
  run.dt = o.dt;
  const ElasticMaterial material{o.youngs_modulus.value_or(p.material.youngs_modulus),
                                 o.poisson_ratio.value_or(p.material.poisson_ratio),
                                 o.density.value_or(p.material.density)};
  DemoAssetOptions asset_options;
  asset_options.mesh = o.mesh.empty() ? p.mesh : o.mesh;
  asset_options.generated_mesh = p.generated_mesh;
  asset_options.basis = o.basis;
  asset_options.basis_kind = p.basis_kind;
  asset_options.modes = o.modes > 0 ? o.modes : p.modes;
  asset_options.material = material;
  asset_options.cache_dir = o.cache_dir;
  asset_options.fresh_certificates = o.fresh_certificates;
  asset_options.scale = o.scale;
  asset_options.exclude_rest_contacts = o.exclude_rest_contacts;
  run.assets = load_demo_assets(asset_options, progress);
  if (!o.mesh.empty()) run.scene = run.assets.name;  // a custom mesh's scene is not "bunnies"
  const SubspaceModel& model = *run.assets.model;
  const SelfCcd detector(*run.assets.bvh, *run.assets.certificates);

  run.objects = o.objects > 0 ? o.objects : p.objects;
  Scene scene;
  for (int i = 0; i < run.objects; ++i) scene.add_object(detector);
  const double mass = material.density * enclosed_volume(model.mesh());
  const double damping = o.damping_ratio.value_or(p.damping_ratio);
  std::unique_ptr<DemoScene> motion_source;
  const SceneMotionOptions motion{run.objects, o.dt, damping, o.seed};
  if (p.spring_motion) {
    SpringSceneOptions s;
    s.motion = motion;
    motion_source = std::make_unique<SpringScene>(model, mass, s);
  } else {
    EarDropOptions d;
    d.motion = motion;
    motion_source = std::make_unique<EarDrop>(model, mass, d);
  }
  const std::function<std::vector<ObjectStep>()> next = [&] { return motion_source->step(); };
  progress << "scene " << run.scene << ": " << run.objects << " objects x " << o.steps << " steps of " << o.dt << " s; "
           << model.mesh().triangle_count() << " triangles, " << model.mode_count()
           << " modes; root certificate radius " << run.assets.certificates->node_radius(0) << '\n';

  SceneOptions with, without;
  without.use_certificates = false;
  without.use_normal_cones = false;  // traditional: the plain swept-box query
  run.threads = default_threads();
  SceneOptions with_one_thread = with, without_one_thread = without;
  with_one_thread.threads = without_one_thread.threads = 1;
  SelfCcdOptions discrete_with, discrete_without;
  discrete_without.use_certificates = false;
  std::vector<std::vector<ObjectStep>> sampled;  // the steps FCL sees
  std::vector<SceneReport> sampled_reports;
  const int fcl_every = o.fcl_steps > 0 ? std::max(1, o.steps / o.fcl_steps) : 0;
  std::vector<SelfCcdReport> discrete_a, discrete_b;
  for (int k = 0; k < o.steps; ++k) {
    const std::vector<ObjectStep> steps = next();
    if (k == 0) {
      // Continuous collision detection assumes a start free of contact: checked exactly.
      for (std::size_t i = 0; i < steps.size(); ++i) {
        if (detector.query_discrete(steps[i].q0, discrete_without).collided()) {
          throw std::runtime_error(
              "scene " + run.scene + ": object " + std::to_string(i) +
              " starts in contact with itself; the continuous queries assume a contact-free start (if it touches "
              "itself at rest, --exclude-rest-contacts ignores those pairs)");
        }
      }
    }
    auto t = std::chrono::steady_clock::now();
    const SceneReport fast = scene.step(steps, with);
    add_run(run.sscc, fast, milliseconds_since(t));
    t = std::chrono::steady_clock::now();
    const SceneReport slow = scene.step(steps, without);
    add_run(run.traditional, slow, milliseconds_since(t));
    run.identical_steps += same_reports(fast, slow);
    if (run.threads > 1) {  // the same step on one thread, side by side
      t = std::chrono::steady_clock::now();
      const SceneReport fast_one = scene.step(steps, with_one_thread);
      add_run(run.sscc_one_thread, fast_one, milliseconds_since(t));
      t = std::chrono::steady_clock::now();
      const SceneReport slow_one = scene.step(steps, without_one_thread);
      add_run(run.traditional_one_thread, slow_one, milliseconds_since(t));
      run.identical_thread_steps += same_reports(fast_one, fast) && same_reports(slow_one, slow);
    }
    run.object_steps_certified += fast.stats.objects_certified;
    run.object_steps_traversed += fast.stats.objects_traversed;
    run.all_certified_steps += fast.stats.objects_traversed == 0;
    if (o.discrete) {
      run.discrete_sscc.ms.push_back(discrete_step(detector, steps, discrete_with, discrete_a));
      run.discrete_traditional.ms.push_back(discrete_step(detector, steps, discrete_without, discrete_b));
      bool same = true;
      for (std::size_t i = 0; i < discrete_a.size(); ++i) same = same && discrete_a[i].pairs == discrete_b[i].pairs;
      run.identical_discrete_steps += same;
    }
    if (o.record_steps) run.recorded.push_back(steps);
    if (fcl_every > 0 && k % fcl_every == fcl_every / 2 && static_cast<int>(sampled.size()) < o.fcl_steps) {
      sampled.push_back(steps);
      sampled_reports.push_back(fast);
    }
    if ((k + 1) % 50 == 0 || k + 1 == o.steps) {
      progress << "scene " << run.scene << ": step " << (k + 1) << "/" << o.steps << ", SSCC " << run.sscc.mean()
               << " ms, traditional " << run.traditional.mean() << " ms per step so far\n"
               << std::flush;
    }
  }
  run.impacts = motion_source->events();

  if (!sampled.empty()) {
    FclSelfCcd fcl(model.mesh(), model.excluded_pairs());
    for (std::size_t s = 0; s < sampled.size(); ++s) {
      double step_ms = 0.0;
      for (int i = 0; i < run.objects; ++i) {
        const std::vector<Eigen::Vector3d> x0 = model.deformed_positions(sampled[s][i].q0);
        const std::vector<Eigen::Vector3d> x1 = model.deformed_positions(sampled[s][i].q1);
        const auto t = std::chrono::steady_clock::now();
        const PairList fcl_pairs = fcl.step(x0, x1);
        step_ms += milliseconds_since(t);
        PairList ours;
        for (const auto& pair : sampled_reports[s].objects[i].report.pairs) ours.emplace_back(pair.first, pair.second);
        ++run.fcl_object_steps;
        if (fcl_pairs == ours) {
          ++run.fcl_identical;
        } else {
          run.fcl_settled += settle_with_exact_kernels(model.mesh(), x0, x1, fcl_pairs, ours);
        }
      }
      run.fcl_ms.push_back(step_ms);
      progress << "scene " << run.scene << ": FCL on sampled step " << (s + 1) << "/" << sampled.size() << ": "
               << step_ms << " ms\n";
    }
  }
  run.seconds = milliseconds_since(start) / 1e3;
  return run;
}

}  // namespace sscc::validation
