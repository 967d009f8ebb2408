#include "demo/demo_command.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "demo/demo_assets.hpp"
#include "demo/ear_drop.hpp"
#include "demo/spring_scene.hpp"
#include "fcl_self_ccd.hpp"
#include "fcl_settle.hpp"
#include "plot.hpp"
#include "precompute_command.hpp"
#include "sscc/scene/scene.hpp"

namespace sscc::validation {

namespace {

namespace fs = std::filesystem;

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double mean(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

bool same_reports(const SceneReport& a, const SceneReport& b) {
  if (a.contacts != b.contacts || a.features != b.features) return false;
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    if (a.objects[i].report.pairs != b.objects[i].report.pairs) return false;
    if (a.objects[i].report.features != b.objects[i].report.features) return false;
  }
  return true;
}

long self_pairs(const SceneReport& r) {
  long n = 0;
  for (const ObjectSelfResult& o : r.objects) n += static_cast<long>(o.report.pairs.size());
  return n;
}

/// The scene's motion generator, whichever scene it is.
using StepSource = std::function<std::vector<ObjectStep>()>;

struct MethodTimes {
  std::vector<double> ms;
  int colliding_steps = 0;
  long self_pairs = 0, inter_pairs = 0;
};

void add_run(MethodTimes& m, const SceneReport& r, double ms) {
  m.ms.push_back(ms);
  m.colliding_steps += r.collided();
  m.self_pairs += self_pairs(r);
  m.inter_pairs += static_cast<long>(r.contacts.size());
}

void write_time_plot(const DemoOptions& o, const std::vector<double>& sscc, const std::vector<double>& traditional,
                     std::ostream& progress) {
  const std::string csv = o.output_dir + "/demo_" + o.scene + "_time_per_step.csv";
  std::ofstream file(csv);
  file << "step,sscc_ms,traditional_ms\n";
  for (std::size_t k = 0; k < sscc.size(); ++k) file << k << ',' << sscc[k] << ',' << traditional[k] << '\n';
  file.close();
  const std::string png = o.output_dir + "/demo_" + o.scene + "_time_per_step.png";
  std::ostringstream g;
  g << "set terminal pngcairo size 900,500\nset output '" << png << "'\nset datafile separator ','\n"
    << "set logscale y\nset xlabel 'time step'\nset ylabel 'CCD time per step (ms)'\n"
    << "set title 'Continuous collision detection per step, " << o.scene << " scene'\nset key top left\n"
    << "plot '" << csv << "' using 1:3 skip 1 with lines lw 2 title 'traditional (swept-box BVH)', '" << csv
    << "' using 1:2 skip 1 with lines lw 2 title 'SSCC (certificates)'\n";
  render_plot(g.str(), o.output_dir + "/demo_" + o.scene + "_time_per_step.gnuplot", png, progress);
}

void write_radius_plot(const DemoOptions& o, const SubspaceBvh& bvh, const Certificates& certificates,
                       std::ostream& progress) {
  const std::string csv = o.output_dir + "/demo_" + o.scene + "_radius_per_level.csv";
  std::ostringstream levels;
  print_radius_per_level(bvh, certificates, levels);
  std::ofstream file(csv);
  file << "level,min_radius,median_radius,max_radius\n";
  std::string line;
  std::istringstream in(levels.str());
  while (std::getline(in, line)) {
    int level = 0, nodes = 0;
    double lo = 0, med = 0, hi = 0;
    if (std::sscanf(line.c_str(), "level %d: nodes=%d min_radius=%lf median_radius=%lf max_radius=%lf", &level,
                    &nodes, &lo, &med, &hi) == 5) {
      file << level << ',' << lo << ',' << med << ',' << hi << '\n';
    }
  }
  file.close();
  const std::string png = o.output_dir + "/demo_" + o.scene + "_radius_per_level.png";
  std::ostringstream g;
  g << "set terminal pngcairo size 700,500\nset output '" << png << "'\nset datafile separator ','\n"
    << "set xlabel 'tree level (0: root)'\nset ylabel 'certificate radius ||q||_M'\nset logscale y\n"
    << "set title 'Certificate radius per tree level, " << o.scene << " scene'\nset key top left\n"
    << "plot '" << csv << "' using 1:2 skip 1 with linespoints lw 2 title 'min', '" << csv
    << "' using 1:3 skip 1 with linespoints lw 2 title 'median', '" << csv
    << "' using 1:4 skip 1 with linespoints lw 2 title 'max'\n";
  render_plot(g.str(), o.output_dir + "/demo_" + o.scene + "_radius_per_level.gnuplot", png, progress);
}

}  // namespace

long run_demo(const DemoOptions& o, std::ostream& out, std::ostream& progress) {
  if (o.scene != "bunnies" && o.scene != "spring") {
    throw std::invalid_argument("demo: unknown scene '" + o.scene + "' (bunnies, spring)");
  }
  if (o.steps < 1) throw std::invalid_argument("demo: --steps must be positive");
  const bool bunnies = o.scene == "bunnies";
  const ElasticMaterial material{o.youngs_modulus.value_or(bunnies ? 2.0e7 : 2.0e11),
                                 o.poisson_ratio.value_or(bunnies ? 0.4 : 0.3), o.density.value_or(bunnies ? 1100.0 : 7800.0)};
  const double damping_ratio = o.damping_ratio.value_or(bunnies ? 0.1 : 0.02);
  fs::create_directories(o.output_dir);
  const auto start = std::chrono::steady_clock::now();

  DemoAssetOptions asset_options;
  asset_options.mesh = o.mesh;
  asset_options.generated_mesh = bunnies ? "" : "spring";
  asset_options.basis = o.basis;
  asset_options.modes = o.modes > 0 ? o.modes : (bunnies ? 30 : 20);
  asset_options.material = material;
  asset_options.cache_dir = o.cache_dir;
  const DemoAssets assets = load_demo_assets(asset_options, progress);
  const SubspaceModel& model = *assets.model;
  const SelfCcd detector(*assets.bvh, *assets.certificates);

  const int objects = o.objects > 0 ? o.objects : (bunnies ? 16 : 1);
  Scene scene;
  for (int i = 0; i < objects; ++i) scene.add_object(detector);
  std::unique_ptr<EarDrop> drop;
  std::unique_ptr<SpringScene> spring;
  StepSource next;
  const double mass = material.density * enclosed_volume(model.mesh());
  if (bunnies) {
    EarDropOptions d;
    d.objects = objects;
    d.dt = o.dt;
    d.damping_ratio = damping_ratio;
    d.seed = o.seed;
    drop = std::make_unique<EarDrop>(model, mass, d);
    next = [&] { return drop->step(); };
  } else {
    SpringSceneOptions s;
    s.objects = objects;
    s.dt = o.dt;
    s.damping_ratio = damping_ratio;
    s.seed = o.seed;
    spring = std::make_unique<SpringScene>(model, mass, s);
    next = [&] { return spring->step(); };
  }
  progress << "demo: " << o.scene << ", " << objects << " objects x " << o.steps << " steps of " << o.dt
           << " s; mesh " << model.mesh().triangle_count() << " triangles, " << model.mode_count()
           << " modes; root certificate radius " << assets.certificates->node_radius(0) << '\n';

  SceneOptions with;
  SceneOptions without;
  without.use_certificates = false;
  MethodTimes sscc_run, traditional_run;
  int identical = 0, all_certified_steps = 0;
  long object_steps_certified = 0, object_steps_traversed = 0;
  std::vector<std::vector<ObjectStep>> sampled;  // steps FCL will see
  std::vector<SceneReport> sampled_reports;
  const int fcl_every = o.fcl_steps > 0 ? std::max(1, o.steps / o.fcl_steps) : 0;
  const auto loop_start = std::chrono::steady_clock::now();
  for (int k = 0; k < o.steps; ++k) {
    const std::vector<ObjectStep> steps = next();
    auto t = std::chrono::steady_clock::now();
    const SceneReport fast = scene.step(steps, with);
    add_run(sscc_run, fast, milliseconds_since(t));
    t = std::chrono::steady_clock::now();
    const SceneReport slow = scene.step(steps, without);
    add_run(traditional_run, slow, milliseconds_since(t));
    identical += same_reports(fast, slow);
    object_steps_certified += fast.stats.objects_certified;
    object_steps_traversed += fast.stats.objects_traversed;
    all_certified_steps += fast.stats.objects_traversed == 0;
    if (fcl_every > 0 && k % fcl_every == fcl_every / 2 && static_cast<int>(sampled.size()) < o.fcl_steps) {
      sampled.push_back(steps);
      sampled_reports.push_back(fast);
    }
    if ((k + 1) % 50 == 0 || k + 1 == o.steps) {
      progress << "demo: step " << (k + 1) << "/" << o.steps << ", sscc " << mean(sscc_run.ms) << " ms, traditional "
               << mean(traditional_run.ms) << " ms per step so far, " << milliseconds_since(loop_start) / 1e3
               << " s\n"
               << std::flush;
    }
  }

  // FCL's continuous self-collision of every object on the sampled steps, its
  // disagreements with ours settled by the exact kernels.
  SettledDisagreements settled;
  std::vector<double> fcl_ms;
  int fcl_identical = 0, fcl_object_steps = 0;
  if (!sampled.empty()) {
    FclSelfCcd fcl(model.mesh());
    for (std::size_t s = 0; s < sampled.size(); ++s) {
      double step_ms = 0.0;
      for (int i = 0; i < objects; ++i) {
        const std::vector<Eigen::Vector3d> x0 = model.deformed_positions(sampled[s][i].q0);
        const std::vector<Eigen::Vector3d> x1 = model.deformed_positions(sampled[s][i].q1);
        const auto t = std::chrono::steady_clock::now();
        const PairList fcl_pairs = fcl.step(x0, x1);
        step_ms += milliseconds_since(t);
        PairList ours;
        for (const auto& p : sampled_reports[s].objects[i].report.pairs) ours.emplace_back(p.first, p.second);
        ++fcl_object_steps;
        if (fcl_pairs == ours) {
          ++fcl_identical;
        } else {
          settled += settle_with_exact_kernels(model.mesh(), x0, x1, fcl_pairs, ours);
        }
      }
      fcl_ms.push_back(step_ms);
      progress << "demo: fcl on sampled step " << (s + 1) << "/" << sampled.size() << ": " << step_ms << " ms\n";
    }
  }

  write_time_plot(o, sscc_run.ms, traditional_run.ms, progress);
  write_radius_plot(o, *assets.bvh, *assets.certificates, progress);

  const double sscc_mean = mean(sscc_run.ms), traditional_mean = mean(traditional_run.ms);
  const double speedup = traditional_mean / std::max(sscc_mean, 1e-9);
  const bool agree = identical == o.steps && settled.unexplained == 0;
  char line[512];
  out << "\nscene " << o.scene << ": " << objects << " objects, " << o.steps << " steps of " << o.dt << " s, "
      << model.mesh().triangle_count() << " triangles and " << model.mode_count() << " modes each\n\n";
  out << "| method | mean ms/step | median ms/step | max ms/step | colliding steps | self pairs | inter-object pairs |\n"
      << "|---|---|---|---|---|---|---|\n";
  for (const auto& [name, m] : {std::make_pair("SSCC", &sscc_run), std::make_pair("traditional", &traditional_run)}) {
    std::snprintf(line, sizeof line, "| %s | %.3f | %.3f | %.3f | %d | %ld | %ld |\n", name, mean(m->ms),
                  median(m->ms), *std::max_element(m->ms.begin(), m->ms.end()), m->colliding_steps, m->self_pairs,
                  m->inter_pairs);
    out << line;
  }
  if (!fcl_ms.empty()) {
    std::snprintf(line, sizeof line, "| FCL 0.7 (self only, %zu sampled steps) | %.3f | %.3f | %.3f | - | - | - |\n",
                  fcl_ms.size(), mean(fcl_ms), median(fcl_ms), *std::max_element(fcl_ms.begin(), fcl_ms.end()));
    out << line;
  }
  std::snprintf(line, sizeof line,
                "\nspeedup SSCC over traditional: %.1fx (mean time per step); steps with every object certified: "
                "%d/%d; object-steps certified by the root: %ld/%ld, traversed: %ld\n",
                speedup, all_certified_steps, o.steps, object_steps_certified,
                static_cast<long>(objects) * o.steps, object_steps_traversed);
  out << line;
  out << "agreement: SSCC and traditional reports identical on " << identical << "/" << o.steps << " steps";
  if (fcl_object_steps > 0) {
    out << "; FCL self-collision identical on " << fcl_identical << "/" << fcl_object_steps
        << " sampled object-steps, its disagreements settled by the exact kernels: false positives "
        << settled.fcl_false_positives << ", false negatives " << settled.fcl_false_negatives << ", unexplained "
        << settled.unexplained;
  }
  out << "\nimpacts: " << (drop ? drop->impacts() : spring ? spring->strikes() : 0) << "; total time "
      << milliseconds_since(start) / 1e3 << " s; plots and CSV in " << o.output_dir << "\n";
  std::snprintf(line, sizeof line,
                "demo: scene=%s objects=%d steps=%d colliding_steps=%d sscc_ms=%.3f traditional_ms=%.3f speedup=%.1f "
                "agree=%s",
                o.scene.c_str(), objects, o.steps, sscc_run.colliding_steps, sscc_mean, traditional_mean, speedup,
                agree ? "yes" : "no");
  out << line << '\n';
  return (o.steps - identical) + settled.unexplained;
}

}  // namespace sscc::validation
