#include "demo/scene_run.hpp"

#include <algorithm>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>

#include "demo/ear_drop.hpp"
#include "demo/spring_scene.hpp"
#include "fcl_self_ccd.hpp"
#include "progress_bar.hpp"
#include "sscc/scene/scene.hpp"
#include "sscc/threads.hpp"
#include "statistics.hpp"

namespace sscc::validation {

namespace {

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Restitution of the spring's coils and ground (steel on steel rebounds; the ears of the
/// rubber bunnies do not): the fraction of a contact's approach speed returned.
constexpr double kSteelRestitution = 0.3;
/// s between strikes of the spring: two or three strikes in its one second.
constexpr double kSpringStrikeInterval = 0.4;
/// m/s, the slowest strike of the spring (its mass at this speed, on the top coil). Its coils
/// did not touch when struck at 3 to 4.5 m/s and did at 7 m/s (||q||_M 475, four times the
/// root radius), when most steps need most of the traversal; at this speed the clatter is
/// that of the bottom coil on the ground, and the modes leave the root certificate for a
/// while after each strike.
constexpr double kSpringStrikeSpeed = 2.0;
/// The fastest strike, a multiple of the slowest.
constexpr double kStrikeSpeedSpread = 1.5;

/// A scene's defaults.
struct Preset {
  std::string mesh, generated_mesh, basis_kind;
  int modes, objects;
  ElasticMaterial material;
  double damping_ratio;
  bool spring_motion;
  int steps = 300;
  double dt = 0.01;  ///< s
  int traditional_every = 1;
};

/// The audio rate (Hz) of the spring's steps and of its sound.
constexpr int kAudioRate = 44100;
/// The audio-rate spring compares with the traditional query on every this many steps: 44,100
/// traditional queries of 15 ms each would take 11 minutes, a regular sample of them 13 s.
constexpr int kSpringTraditionalEvery = 50;

Preset preset(const std::string& scene) {
  const ElasticMaterial rubber{2.0e7, 0.4, 1100.0}, steel{2.0e11, 0.3, 7800.0};
  if (scene == "bunnies") return {"", "", "modal", 30, 16, rubber, 0.1, false};
  if (scene == "spring") {
    return {"", "spring", "modal", 20, 1, steel, 0.02, true, kAudioRate, 1.0 / kAudioRate, kSpringTraditionalEvery};
  }
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

/// Whether the response turned exactly the reported contacts into constraints.
bool used_reported_contacts(const ResponseRecord& used, const SceneReport& report) {
  if (used.inter != report.features || used.self.size() != report.objects.size()) return false;
  for (std::size_t i = 0; i < used.self.size(); ++i) {
    if (used.self[i] != report.objects[i].report.features) return false;
  }
  return true;
}

/// Adds one step's response to the totals, with the exact discrete test of every object at
/// its configuration after the response; `run_length` counts the penetrating steps in a row.
/// The test runs after steps with contacts and while an interpenetration lasts: a step that
/// starts free of interpenetration and has no contact (continuous detection misses none)
/// ends free of it.
void add_response(ContactTotals& totals, const ResponseRecord& used, const SceneReport& report,
                  const std::vector<Eigen::VectorXd>& configurations, const SelfCcd& detector, int& run_length) {
  totals.steps_with_contacts += used.constraints() > 0;
  for (const auto& self : used.self) totals.self_features += static_cast<long>(self.size());
  totals.inter_features += static_cast<long>(used.inter.size());
  totals.ground_contacts += used.ground;
  totals.response_mismatches += !used_reported_contacts(used, report);
  totals.deepest_penetration = std::max(totals.deepest_penetration, used.deepest_penetration);
  totals.deepest_residual = std::max(totals.deepest_residual, used.residual_penetration);
  if (used.constraints() == 0 && run_length == 0) return;
  int pairs = 0;
  for (const Eigen::VectorXd& q : configurations) pairs += static_cast<int>(detector.query_discrete(q).pairs.size());
  run_length = pairs > 0 ? run_length + 1 : 0;
  totals.penetrating_steps += pairs > 0;
  totals.longest_penetrating_run = std::max(totals.longest_penetrating_run, run_length);
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

double MethodTimes::mean() const { return validation::mean(ms); }

double MethodTimes::self_mean() const { return validation::mean(self_ms); }

double MethodTimes::median() const { return validation::median(ms); }

double MethodTimes::max() const { return ms.empty() ? 0.0 : *std::max_element(ms.begin(), ms.end()); }

double SceneRun::speedup() const { return traditional.mean() / std::max(sscc.mean(), 1e-9); }
double SceneRun::compared_speedup() const {
  double sum = 0.0;
  for (int k : compared) sum += sscc.ms[static_cast<std::size_t>(k)];
  return compared.empty() ? 0.0 : traditional.mean() / std::max(sum / static_cast<double>(compared.size()), 1e-9);
}
double SceneRun::discrete_speedup() const { return discrete_traditional.mean() / std::max(discrete_sscc.mean(), 1e-9); }
double SceneRun::thread_speedup(const MethodTimes& one_thread, const MethodTimes& all) const {
  return one_thread.ms.empty() ? 0.0 : one_thread.mean() / std::max(all.mean(), 1e-9);
}
bool SceneRun::agree() const {
  const int compared_steps = static_cast<int>(compared.size());
  return identical_steps == compared_steps && fcl_settled.unexplained == 0 &&
         (sscc_one_thread.ms.empty() || identical_thread_steps == compared_steps) &&
         (discrete_sscc.ms.empty() || identical_discrete_steps == steps);
}

SceneRun run_scene(const SceneRunOptions& o, std::ostream& progress) {
  if (o.steps < 0) throw std::invalid_argument("--steps must be positive");
  if (!(o.dt >= 0.0)) throw std::invalid_argument("--dt must be positive");
  if (o.traditional_every < 0) throw std::invalid_argument("the traditional query's interval must be positive");
  if (o.strike_speed && !(*o.strike_speed > 0.0)) throw std::invalid_argument("--strike-speed must be positive");
  const Preset p = preset(o.scene);
  const auto start = std::chrono::steady_clock::now();
  SceneRun run;
  run.scene = o.scene;
  run.steps = o.steps > 0 ? o.steps : p.steps;
  run.dt = o.dt > 0.0 ? o.dt : p.dt;
  run.traditional_every = o.traditional_every > 0 ? o.traditional_every : p.traditional_every;
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
  const SceneMotionOptions motion{run.objects, run.dt, damping, o.seed};
  if (p.spring_motion) {
    SpringSceneOptions s;
    s.motion = motion;
    s.response.restitution = kSteelRestitution;
    // The audio-rate clatter: at rest on the ground, struck every kSpringStrikeInterval.
    s.initial_compression = 0.0;
    s.strike_interval = kSpringStrikeInterval;
    s.strike_speed_min = o.strike_speed.value_or(kSpringStrikeSpeed);
    s.strike_speed_max = kStrikeSpeedSpread * s.strike_speed_min;
    motion_source = std::make_unique<SpringScene>(model, mass, s);
  } else {
    EarDropOptions d;
    d.motion = motion;
    if (o.strike_speed) d.strike_speed = *o.strike_speed;
    motion_source = std::make_unique<EarDrop>(model, mass, d);
  }
  progress << "scene " << run.scene << ": " << run.objects << " objects x " << run.steps << " steps of " << run.dt
           << " s, traditional on every " << run.traditional_every << "; " << model.mesh().triangle_count()
           << " triangles, " << model.mode_count() << " modes; root certificate radius "
           << run.assets.certificates->node_radius(0) << '\n';

  SceneOptions with, without;
  set_traditional(without);
  detector.prepare(with);  // the culls' precomputation, as the certificates: not timed
  run.threads = default_threads();
  SceneOptions with_one_thread = with, without_one_thread = without;
  with_one_thread.threads = without_one_thread.threads = 1;
  SelfCcdOptions discrete_with, discrete_without;
  discrete_without.use_certificates = false;
  std::vector<std::vector<ObjectStep>> sampled;  // the steps FCL sees
  std::vector<SceneReport> sampled_reports;
  const int fcl_every = o.fcl_steps > 0 ? std::max(1, run.steps / o.fcl_steps) : 0;
  ProgressBar bar(progress, "scene " + run.scene);
  std::vector<SelfCcdReport> discrete_a, discrete_b;
  int penetrating_run = 0;
  for (int k = 0; k < run.steps; ++k) {
    const std::vector<ObjectStep> steps = motion_source->step();
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
    if (k % run.traditional_every == 0) {
      run.compared.push_back(k);
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
    }
    // The response to what SSCC found (identical to the traditional report where compared).
    const ResponseRecord used = motion_source->respond(fast, steps);
    add_response(run.contacts, used, fast, motion_source->configurations(), detector, penetrating_run);
    run.sound.push_back(motion_source->modal_sound());
    for (const ObjectStep& step : steps) run.largest_norm = std::max(run.largest_norm, model.weighted_norm(step.q1));
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
    bar.update(k + 1, run.steps, "steps");
  }
  bar.finish(std::to_string(run.steps) + " steps");
  progress << "scene " << run.scene << ": SSCC " << run.sscc.mean() << " ms, traditional " << run.traditional.mean()
           << " ms per step; contacts in " << run.contacts.steps_with_contacts << " steps\n";
  run.impacts = motion_source->events();
  for (const Eigen::VectorXd& q : motion_source->configurations()) {
    run.contacts.final_penetrating_pairs += static_cast<int>(detector.query_discrete(q).pairs.size());
  }

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
