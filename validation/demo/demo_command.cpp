#include "demo/demo_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "demo/sound_file.hpp"
#include "plot.hpp"
#include "precompute_command.hpp"

namespace sscc::validation {

namespace {

namespace fs = std::filesystem;

/// The path of the demo's output file `name` (demo_<scene>_<name>; the scene as run, named
/// after its mesh when one was given).
std::string output_path(const DemoOptions& demo, const SceneRun& run, const std::string& name) {
  return demo.output_dir + "/demo_" + run.scene + "_" + name;
}

void write_time_plot(const DemoOptions& demo, const SceneRun& run, std::ostream& progress) {
  const std::string csv = output_path(demo, run, "time_per_step.csv");
  std::ofstream file(csv);
  file << "step,sscc_ms\n";
  for (std::size_t k = 0; k < run.sscc.ms.size(); ++k) file << k << ',' << run.sscc.ms[k] << '\n';
  file.close();
  // The traditional query's steps (every step, or a regular sample of them).
  const std::string traditional_csv = output_path(demo, run, "traditional_time_per_step.csv");
  std::ofstream traditional(traditional_csv);
  traditional << "step,traditional_ms\n";
  for (std::size_t i = 0; i < run.compared.size(); ++i) {
    traditional << run.compared[i] << ',' << run.traditional.ms[i] << '\n';
  }
  traditional.close();
  const std::string sampled =
      run.traditional_every > 1 ? ", every " + std::to_string(run.traditional_every) + "th step" : "";
  const PlotPanel panel("Continuous collision detection per step, " + run.scene + " scene", "time step",
                        "CCD time per step (ms)", LogScale::kY,
                        {{traditional_csv, 1, "2", "traditional (swept-box BVH" + sampled + ")", "lines lw 2"},
                         {csv, 1, "2", "SSCC (certificates)", "lines lw 2"}});
  render_figure({output_path(demo, run, "time_per_step.png"), 900, 500, {panel}}, progress);
}

void write_radius_plot(const DemoOptions& demo, const SceneRun& run, std::ostream& progress) {
  const SubspaceBvh& bvh = *run.assets.bvh;
  const Certificates& certificates = *run.assets.certificates;
  const std::string csv = output_path(demo, run, "radius_per_level.csv");
  std::ostringstream levels;
  print_radius_per_level(bvh, certificates, levels);
  std::ofstream file(csv);
  file << "level,min_radius,median_radius,max_radius\n";
  std::string line;
  std::istringstream in(levels.str());
  while (std::getline(in, line)) {
    int level = 0, nodes = 0;
    double lo = 0, med = 0, hi = 0;
    if (std::sscanf(line.c_str(), "level %d: nodes=%d min_radius=%lf median_radius=%lf max_radius=%lf", &level, &nodes,
                    &lo, &med, &hi) == 5) {
      file << level << ',' << lo << ',' << med << ',' << hi << '\n';
    }
  }
  file.close();
  const PlotPanel panel("Certificate radius per tree level, " + run.scene + " scene", "tree level (0: root)",
                        "certificate radius ||q||_M", LogScale::kY,
                        {{csv, 1, "2", "min"}, {csv, 1, "3", "median"}, {csv, 1, "4", "max"}});
  render_figure({output_path(demo, run, "radius_per_level.png"), 700, 500, {panel}}, progress);
}

/// Below this step rate (Hz) the steps are too coarse to be heard: no sound file.
constexpr double kLowestAudioRate = 8000.0;

/// Writes the modal sound at the step rate, when that is an audio rate; returns the file, or
/// "" when none was written (and why, on progress).
std::string write_sound(const DemoOptions& demo, const SceneRun& run, std::ostream& progress) {
  const double rate = 1.0 / run.dt;
  if (rate < kLowestAudioRate || run.sound.empty()) return "";
  const std::string path = output_path(demo, run, "sound.wav");
  try {
    write_wav(path, run.sound, static_cast<int>(std::lround(rate)));
  } catch (const std::runtime_error& e) {
    progress << "demo: no sound file: " << e.what() << '\n';
    return "";
  }
  progress << "demo: wrote " << path << '\n';
  return path;
}

void print_contacts(const SceneRun& run, std::ostream& out) {
  const ContactTotals& c = run.contacts;
  char line[768];
  std::snprintf(line, sizeof line,
                "contact response: contacts in %d/%d steps (self features %ld, between objects %ld, ground %ld); "
                "steps whose response used other contacts than SSCC reported: %d\n"
                "interpenetration after the response (exact discrete test at each step's end): %d/%d steps, "
                "longest run %d steps, %d intersecting pairs at the end of the run; deepest penetration along a "
                "contact normal: %.4f mm before the response, %.4f mm after it\n",
                c.steps_with_contacts, run.steps, c.self_features, c.inter_features, c.ground_contacts,
                c.response_mismatches, c.penetrating_steps, run.steps, c.longest_penetrating_run,
                c.final_penetrating_pairs, 1e3 * c.deepest_penetration, 1e3 * c.deepest_residual);
  out << line;
}

}  // namespace

long run_demo(const DemoOptions& demo, std::ostream& out, std::ostream& progress) {
  const SceneRunOptions& o = demo.run;
  fs::create_directories(demo.output_dir);
  const SceneRun run = run_scene(o, progress);
  const SubspaceModel& model = *run.assets.model;
  write_time_plot(demo, run, progress);
  const std::string sound = write_sound(demo, run, progress);
  write_radius_plot(demo, run, progress);

  char line[512];
  out << "\nscene " << run.scene << ": " << run.objects << " objects, " << run.steps << " steps of " << run.dt << " s, "
      << model.mesh().triangle_count() << " triangles and " << model.mode_count() << " modes each\n\n";
  out << "| method | mean ms/step | of it self-collision | median ms/step | max ms/step | colliding steps | self pairs "
         "| inter-object pairs |\n"
      << "|---|---|---|---|---|---|---|---|\n";
  const std::string all_threads = " (" + std::to_string(run.threads) + " threads)";
  const std::string sscc_name = "SSCC" + (run.threads > 1 ? all_threads : "");
  const std::string traditional_name = "traditional" + (run.threads > 1 ? all_threads : "");
  for (const auto& [name, m] :
       {std::make_pair(sscc_name, &run.sscc), std::make_pair(std::string("SSCC (1 thread)"), &run.sscc_one_thread),
        std::make_pair(traditional_name, &run.traditional),
        std::make_pair(std::string("traditional (1 thread)"), &run.traditional_one_thread)}) {
    if (m->ms.empty()) continue;
    std::snprintf(line, sizeof line, "| %s | %.3f | %.3f | %.3f | %.3f | %d | %ld | %ld |\n", name.c_str(), m->mean(),
                  m->self_mean(), m->median(), m->max(), m->colliding_steps, m->self_pairs, m->inter_pairs);
    out << line;
  }
  if (!run.fcl_ms.empty()) {
    MethodTimes fcl;
    fcl.ms = run.fcl_ms;
    std::snprintf(line, sizeof line,
                  "| FCL 0.7 (self only, %zu sampled steps) | %.3f | - | %.3f | %.3f | - | - | - |\n", fcl.ms.size(),
                  fcl.mean(), fcl.median(), fcl.max());
    out << line;
  }
  const int compared = static_cast<int>(run.compared.size());
  std::snprintf(line, sizeof line,
                "\nspeedup SSCC over traditional: %.1fx (mean time per step); steps with every object certified: "
                "%d/%d; object-steps certified by the root: %ld/%ld, traversed: %ld\n",
                run.speedup(), run.all_certified_steps, run.steps, run.object_steps_certified,
                static_cast<long>(run.objects) * run.steps, run.object_steps_traversed);
  out << line;
  if (compared < run.steps) {
    std::snprintf(line, sizeof line,
                  "the traditional query ran on every %dth step (%d of %d): SSCC's mean over every step against "
                  "its mean over those; on those steps alone SSCC was %.1fx faster\n",
                  run.traditional_every, compared, run.steps, run.compared_speedup());
    out << line;
  }
  if (run.threads > 1) {
    std::snprintf(line, sizeof line,
                  "threads: %d against 1, speedup (mean time per step): SSCC %.2fx (%.2fx per thread), traditional "
                  "%.2fx (%.2fx per thread); reports identical on both thread counts on %d/%d steps\n",
                  run.threads, run.thread_speedup(run.sscc_one_thread, run.sscc),
                  run.thread_speedup(run.sscc_one_thread, run.sscc) / run.threads,
                  run.thread_speedup(run.traditional_one_thread, run.traditional),
                  run.thread_speedup(run.traditional_one_thread, run.traditional) / run.threads,
                  run.identical_thread_steps, compared);
    out << line;
  }
  out << "agreement: SSCC and traditional reports identical on " << run.identical_steps << "/" << compared
      << " compared steps";
  if (run.fcl_object_steps > 0) {
    out << "; FCL self-collision identical on " << run.fcl_identical << "/" << run.fcl_object_steps
        << " sampled object-steps, its disagreements settled by the exact kernels: false positives "
        << run.fcl_settled.fcl_false_positives << ", false negatives " << run.fcl_settled.fcl_false_negatives
        << ", unexplained " << run.fcl_settled.unexplained;
  }
  out << "\n";
  print_contacts(run, out);
  out << "largest deformation ||q||_M at a step's end: " << run.largest_norm << " (root certificate radius "
      << run.assets.certificates->node_radius(0) << ")\n";
  out << "impacts and strikes: " << run.impacts << "; total time " << run.seconds << " s; plots and CSV in "
      << demo.output_dir << (sound.empty() ? "" : "; sound in " + sound) << "\n";
  std::snprintf(line, sizeof line,
                "demo: scene=%s objects=%d steps=%d colliding_steps=%d sscc_ms=%.3f traditional_ms=%.3f speedup=%.1f "
                "threads=%d traditional_thread_speedup=%.2f penetrating_steps=%d deepest_penetration_mm=%.4f agree=%s",
                run.scene.c_str(), run.objects, run.steps, run.sscc.colliding_steps, run.sscc.mean(),
                run.traditional.mean(), run.speedup(), run.threads,
                run.thread_speedup(run.traditional_one_thread, run.traditional), run.contacts.penetrating_steps,
                1e3 * run.contacts.deepest_penetration, run.agree() ? "yes" : "no");
  out << line << '\n';
  const int thread_disagreements = run.sscc_one_thread.ms.empty() ? 0 : compared - run.identical_thread_steps;
  return (compared - run.identical_steps) + thread_disagreements + run.fcl_settled.unexplained;
}

}  // namespace sscc::validation
