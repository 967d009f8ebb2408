#include "demo/demo_command.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

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
  const std::vector<double>& sscc = run.sscc.ms;
  const std::vector<double>& traditional = run.traditional.ms;
  const std::string csv = output_path(demo, run, "time_per_step.csv");
  std::ofstream file(csv);
  file << "step,sscc_ms,traditional_ms\n";
  for (std::size_t k = 0; k < sscc.size(); ++k) file << k << ',' << sscc[k] << ',' << traditional[k] << '\n';
  file.close();
  const PlotPanel panel(
      "Continuous collision detection per step, " + run.scene + " scene", "time step", "CCD time per step (ms)",
      LogScale::kY,
      {{csv, 1, "3", "traditional (swept-box BVH)", "lines lw 2"}, {csv, 1, "2", "SSCC (certificates)", "lines lw 2"}});
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

}  // namespace

long run_demo(const DemoOptions& demo, std::ostream& out, std::ostream& progress) {
  const SceneRunOptions& o = demo.run;
  fs::create_directories(demo.output_dir);
  const SceneRun run = run_scene(o, progress);
  const SubspaceModel& model = *run.assets.model;
  write_time_plot(demo, run, progress);
  write_radius_plot(demo, run, progress);

  char line[512];
  out << "\nscene " << run.scene << ": " << run.objects << " objects, " << run.steps << " steps of " << run.dt << " s, "
      << model.mesh().triangle_count() << " triangles and " << model.mode_count() << " modes each\n\n";
  out << "| method | mean ms/step | median ms/step | max ms/step | colliding steps | self pairs | inter-object pairs "
         "|\n"
      << "|---|---|---|---|---|---|---|\n";
  const std::string all_threads = " (" + std::to_string(run.threads) + " threads)";
  const std::string sscc_name = "SSCC" + (run.threads > 1 ? all_threads : "");
  const std::string traditional_name = "traditional" + (run.threads > 1 ? all_threads : "");
  for (const auto& [name, m] :
       {std::make_pair(sscc_name, &run.sscc), std::make_pair(std::string("SSCC (1 thread)"), &run.sscc_one_thread),
        std::make_pair(traditional_name, &run.traditional),
        std::make_pair(std::string("traditional (1 thread)"), &run.traditional_one_thread)}) {
    if (m->ms.empty()) continue;
    std::snprintf(line, sizeof line, "| %s | %.3f | %.3f | %.3f | %d | %ld | %ld |\n", name.c_str(), m->mean(),
                  m->median(), m->max(), m->colliding_steps, m->self_pairs, m->inter_pairs);
    out << line;
  }
  if (!run.fcl_ms.empty()) {
    MethodTimes fcl;
    fcl.ms = run.fcl_ms;
    std::snprintf(line, sizeof line, "| FCL 0.7 (self only, %zu sampled steps) | %.3f | %.3f | %.3f | - | - | - |\n",
                  fcl.ms.size(), fcl.mean(), fcl.median(), fcl.max());
    out << line;
  }
  std::snprintf(line, sizeof line,
                "\nspeedup SSCC over traditional: %.1fx (mean time per step); steps with every object certified: "
                "%d/%d; object-steps certified by the root: %ld/%ld, traversed: %ld\n",
                run.speedup(), run.all_certified_steps, run.steps, run.object_steps_certified,
                static_cast<long>(run.objects) * run.steps, run.object_steps_traversed);
  out << line;
  if (run.threads > 1) {
    std::snprintf(line, sizeof line,
                  "threads: %d against 1, speedup (mean time per step): SSCC %.2fx (%.2fx per thread), traditional "
                  "%.2fx (%.2fx per thread); reports identical on both thread counts on %d/%d steps\n",
                  run.threads, run.thread_speedup(run.sscc_one_thread, run.sscc),
                  run.thread_speedup(run.sscc_one_thread, run.sscc) / run.threads,
                  run.thread_speedup(run.traditional_one_thread, run.traditional),
                  run.thread_speedup(run.traditional_one_thread, run.traditional) / run.threads,
                  run.identical_thread_steps, run.steps);
    out << line;
  }
  out << "agreement: SSCC and traditional reports identical on " << run.identical_steps << "/" << run.steps << " steps";
  if (run.fcl_object_steps > 0) {
    out << "; FCL self-collision identical on " << run.fcl_identical << "/" << run.fcl_object_steps
        << " sampled object-steps, its disagreements settled by the exact kernels: false positives "
        << run.fcl_settled.fcl_false_positives << ", false negatives " << run.fcl_settled.fcl_false_negatives
        << ", unexplained " << run.fcl_settled.unexplained;
  }
  out << "\nimpacts and strikes: " << run.impacts << "; total time " << run.seconds << " s; plots and CSV in "
      << demo.output_dir << "\n";
  std::snprintf(line, sizeof line,
                "demo: scene=%s objects=%d steps=%d colliding_steps=%d sscc_ms=%.3f traditional_ms=%.3f speedup=%.1f "
                "threads=%d traditional_thread_speedup=%.2f agree=%s",
                run.scene.c_str(), run.objects, run.steps, run.sscc.colliding_steps, run.sscc.mean(),
                run.traditional.mean(), run.speedup(), run.threads,
                run.thread_speedup(run.traditional_one_thread, run.traditional), run.agree() ? "yes" : "no");
  out << line << '\n';
  const int thread_disagreements = run.sscc_one_thread.ms.empty() ? 0 : run.steps - run.identical_thread_steps;
  return (run.steps - run.identical_steps) + thread_disagreements + run.fcl_settled.unexplained;
}

}  // namespace sscc::validation
