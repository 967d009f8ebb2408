#include "bench/bench_command.hpp"
#include "bench/self_ccd_table.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "degenerate_benchmark.hpp"
#include "demo/scene_run.hpp"
#include "kernel_validation.hpp"
#include "plot.hpp"
#include "progress_bar.hpp"

namespace sscc::validation {

namespace {

namespace fs = std::filesystem;

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

std::string seconds_text(double s) { return s >= 120 ? format("%.1f min", s / 60) : format("%.1f s", s); }

/// A row of our results in the shape of the paper's Table 1.
std::string table1_row(const std::string& name, const SceneRun& run, const std::string& dynamics) {
  const SubspaceModel& m = *run.assets.model;
  std::ostringstream row;
  row << "| **ours: " << name << "** | " << m.mesh().triangle_count() << " | " << m.mode_count() << " | " << run.objects
      << " | " << dynamics << " | " << seconds_text(run.assets.certificate_seconds) << " | "
      << format("%.1f ms", run.traditional.mean()) << " | " << format("%.2f ms", run.sscc.mean()) << " | "
      << format("%.1fx", run.speedup()) << " | " << run.sscc.colliding_steps << "/" << run.steps << " |\n";
  return row.str();
}

/// A scene's times on one thread beside every thread (empty on one thread).
std::string thread_row(const std::string& name, const SceneRun& run) {
  if (run.sscc_one_thread.ms.empty()) return "";
  std::ostringstream row;
  row << "| " << name << " | " << run.threads << " | " << format("%.2f ms", run.sscc_one_thread.mean()) << " | "
      << format("%.2f ms", run.sscc.mean()) << " | "
      << format("%.2fx", run.thread_speedup(run.sscc_one_thread, run.sscc)) << " | "
      << format("%.1f ms", run.traditional_one_thread.mean()) << " | " << format("%.1f ms", run.traditional.mean())
      << " | " << format("%.2fx", run.thread_speedup(run.traditional_one_thread, run.traditional)) << " | "
      << run.identical_thread_steps << "/" << run.steps << " |\n";
  return row.str();
}

struct EpsilonRow {
  double epsilon, precompute_s, root_radius;
  double sscc_self_ms;           ///< mean per step, self-collision of all objects
  long certified, object_steps;  ///< object-steps decided by the root
  double visits_fraction;        ///< node visits against the traditional query's
  bool identical;
};

/// The bunny run's self-collision queries replayed with certificates of each epsilon.
std::vector<EpsilonRow> epsilon_sweep(const SceneRun& run, std::ostream& progress) {
  const SubspaceBvh& bvh = *run.assets.bvh;
  const SelfCcd traditional_detector(bvh);
  SelfCcdOptions traditional;
  set_traditional(traditional);
  std::vector<std::vector<SelfCcdReport>> reference;
  long traditional_visits = 0;
  for (const auto& step : run.recorded) {
    reference.emplace_back();
    for (const ObjectStep& s : step) {
      if (s.q0 == s.q1) continue;
      reference.back().push_back(traditional_detector.query(s.q0, s.q1, traditional));
      traditional_visits += reference.back().back().stats.nodes_visited;
    }
  }
  std::vector<EpsilonRow> rows;
  for (double epsilon : {0.5, 0.2, 0.1, 0.05, 0.02}) {
    CertificateParameters parameters;
    parameters.epsilon = epsilon;
    ProgressBar bar(progress, "bench: epsilon " + std::to_string(epsilon) + ": certificates");
    const Certificates certificates = Certificates::precompute(bvh, parameters, precompute_progress(bar));
    bar.finish();
    const SelfCcd detector(bvh, certificates);
    EpsilonRow row{epsilon, certificates.stats().seconds, certificates.node_radius(0), 0, 0, 0, 0, true};
    long visits = 0;
    double ms = 0.0;
    for (std::size_t k = 0; k < run.recorded.size(); ++k) {
      std::size_t i = 0;
      for (const ObjectStep& s : run.recorded[k]) {
        if (s.q0 == s.q1) continue;
        const auto start = std::chrono::steady_clock::now();
        const SelfCcdReport r = detector.query(s.q0, s.q1);
        ms += 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        row.identical = row.identical && r.pairs == reference[k][i].pairs && r.features == reference[k][i].features;
        ++i;
        row.certified += r.stats.root_certified;
        ++row.object_steps;
        visits += r.stats.nodes_visited;
      }
    }
    row.sscc_self_ms = ms / static_cast<double>(run.recorded.size());
    row.visits_fraction = static_cast<double>(visits) / static_cast<double>(std::max(1L, traditional_visits));
    progress << "bench: epsilon " << epsilon << ": precompute " << row.precompute_s << " s, root radius "
             << row.root_radius << ", SSCC self " << row.sscc_self_ms << " ms per step\n";
    rows.push_back(row);
  }
  return rows;
}

void epsilon_plot(const std::vector<EpsilonRow>& rows, double traditional_self_ms, const std::string& dir,
                  std::ostream& progress) {
  const std::string csv = dir + "/bench_epsilon.csv";
  std::ofstream file(csv);
  file << "epsilon,precompute_s,root_radius,sscc_self_ms,traditional_self_ms,speedup,certified_fraction\n";
  for (const EpsilonRow& r : rows) {
    file << r.epsilon << ',' << r.precompute_s << ',' << r.root_radius << ',' << r.sscc_self_ms << ','
         << traditional_self_ms << ',' << traditional_self_ms / r.sscc_self_ms << ','
         << static_cast<double>(r.certified) / std::max(1L, r.object_steps) << '\n';
  }
  file.close();
  Figure figure{dir + "/bench_epsilon.png", 1100, 450, {}};
  figure.panels.emplace_back("Precomputation (16-bunny model)", "certificate epsilon", "s", LogScale::kX,
                             std::vector<PlotSeries>{{csv, 1, "2", "precompute time"}});
  figure.panels.emplace_back("Self-collision speedup over traditional (same run)", "certificate epsilon", "x",
                             LogScale::kX, std::vector<PlotSeries>{{csv, 1, "6", "speedup"}});
  render_figure(figure, progress);
}

void tolerance_plot(const std::vector<ToleranceTiming>& rows, const std::string& dir, std::ostream& progress) {
  const std::string csv = dir + "/bench_toi_tolerance.csv";
  std::ofstream file(csv);
  file << "tolerance,vertex_face_us,edge_edge_us\n";
  for (const ToleranceTiming& t : rows) file << t.tolerance << ',' << t.vertex_face_us << ',' << t.edge_edge_us << '\n';
  file.close();
  const PlotPanel panel("Kernels: run time against time-of-impact error", "time-of-impact tolerance",
                        "mean time per query (us)", LogScale::kX,
                        {{csv, 1, "2", "vertex-face"}, {csv, 1, "3", "edge-edge"}});
  render_figure({dir + "/bench_toi_tolerance.png", 700, 450, {panel}}, progress);
}

SceneRun bench_scene(const std::string& scene, const BenchOptions& o, bool discrete, std::ostream& progress) {
  SceneRunOptions s;
  s.scene = scene;
  s.steps = o.steps;
  s.dt = 0.01;              // every scene at the same rate, the spring's audio rate aside
  s.traditional_every = 1;  // and compared on every step
  s.seed = o.seed;
  s.cache_dir = o.cache_dir;
  s.fcl_steps = 0;
  s.discrete = discrete;
  s.fresh_certificates = true;
  s.record_steps = scene == "bunnies";
  // The dragon touches itself at rest (its root certificate radius is 0): those pairs are
  // ignored, as --exclude-rest-contacts does, since the scene must start free of contact.
  s.exclude_rest_contacts = scene == "dragon";
  return run_scene(s, progress);
}

/// The self-CCD table on every mesh in the folder (none when it is absent), as Markdown, and
/// the number of rows where cones and traditional disagree.
std::pair<std::string, long> self_ccd_section(const BenchOptions& o, std::ostream& progress) {
  const std::string dir = o.meshes_dir.empty() ? data_dir() + "/../../shared/data/meshes" : o.meshes_dir;
  SelfCcdTableOptions table;
  table.steps = o.table_steps;
  table.repeats = o.table_repeats;
  table.seed = o.seed;
  table.cache_dir = o.cache_dir;
  if (fs::is_directory(dir)) {
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (entry.path().extension() == ".off") table.meshes.push_back(entry.path().string());
    }
  }
  std::sort(table.meshes.begin(), table.meshes.end());
  if (table.meshes.empty()) {
    progress << "bench: no meshes in " << dir << ": no self-CCD table\n";
    return {"", 0};
  }
  const std::vector<SelfCcdTableRow> rows = self_ccd_table(table, progress);
  long disagreements = 0;
  for (const SelfCcdTableRow& r : rows) disagreements += !r.identical;
  std::ostringstream md;
  md << "\nSelf-CCD per mesh (" << table.basis << ", random trajectories, " << table.steps
     << " steps per row, FCL on the first " << std::min(table.fcl_steps, table.steps)
     << "; one thread; mean ms per step, each step's time the median of " << std::max(1, table.repeats)
     << " runs of each query, each after an untimed run of it (warm caches; FCL: one run, its steps back to back); "
        "traditional: swept boxes only, cones: with the normal-cone culls, "
        "bounds: with the displacement bounds, cones + bounds: with both (the library's defaults without "
        "certificates), SSCC: the certificates (computed once per mesh, default parameters), the library's defaults; "
        "the culls' data "
        "built before timing, as the certificates):\n\n"
     << self_ccd_table_markdown(rows);
  return {md.str(), disagreements};
}

}  // namespace

long run_bench(const BenchOptions& o, std::ostream& out, std::ostream& progress) {
  fs::create_directories(o.output_dir);
  const auto start = std::chrono::steady_clock::now();
  if (o.self_ccd_table_only) {
    const auto [md, disagreements] = self_ccd_section(o, progress);
    std::ofstream(o.output_dir + "/bench_self_ccd.md") << md;
    out << md << "\nbench: " << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
        << " s; table in " << o.output_dir << "/bench_self_ccd.md; disagreements " << disagreements << '\n';
    return disagreements;
  }
  const SceneRun bunnies = bench_scene("bunnies", o, true, progress);
  const SceneRun spring = bench_scene("spring", o, false, progress);
  const bool have_dragon = fs::exists(data_dir() + "/../../shared/data/meshes/ChineseDragon-10kv.off");
  if (!have_dragon) progress << "bench: ../shared/data/meshes/ChineseDragon-10kv.off is absent: no dragon row\n";
  const SceneRun dragon = have_dragon ? bench_scene("dragon", o, false, progress) : SceneRun{};
  const std::vector<EpsilonRow> epsilons = epsilon_sweep(bunnies, progress);
  MethodTimes traditional_self;
  traditional_self.ms = bunnies.traditional.self_ms;
  epsilon_plot(epsilons, traditional_self.mean(), o.output_dir, progress);
  progress << "bench: kernels against the time-of-impact tolerance (" << o.kernel_queries << " queries per kind)\n";
  const std::vector<ToleranceTiming> tolerances = time_against_toi_tolerance(o.kernel_queries, o.seed, 3);
  tolerance_plot(tolerances, o.output_dir, progress);
  std::ostringstream degenerate_lines;  // the per-stage lines; the table below summarises them
  const std::vector<DegenerateSetTiming> degenerate =
      run_degenerate_benchmark(o.kernel_queries / 10, o.seed, degenerate_lines, progress);

  std::ostringstream md;
  md << "## Beside the SSCC paper (Barbic and James 2010)\n\n"
     << "Per-step CCD time for all objects of a scene; ours is continuous self-collision detection "
        "(plus inter-object tests for the bunnies), the paper's Table 1 is discrete. Precomputation: the "
        "certificates (ours on 2 cores, the paper's on 8, 2010). Colliding: steps with at least one contact.\n\n"
     << "| example | triangles | r | objects | dynamics | precompute | traditional | SSCC | speedup | colliding |\n"
     << "|---|---|---|---|---|---|---|---|---|---|\n"
     << "| paper: spring (sound) | 16,000 | 20 | 1 | linear | 29 s | 30 ms | 0.32 ms | 127.1x | - |\n"
     << table1_row("spring", spring, "linear modal, struck")
     << "| paper: bunny (16) | 14,964 | 30 | 16 | nonlinear | 113 s | 640 ms | 22 ms | 29.1x | - |\n"
     << table1_row("bunnies", bunnies, "linear modal, dropped and struck")
     << "| paper: dragon (polynomial) | 77,203 | 24 | 1 | linear | 89 min | 381 ms | 3.7 ms | 102.9x | - |\n";
  if (have_dragon) md << table1_row("dragon (polynomial)", dragon, "linear, dropped and struck");
  if (!bunnies.sscc_one_thread.ms.empty()) {
    md << "\nOne thread beside every thread (the same steps, in the same run; speedup: mean time per step on one "
          "thread over that on all; identical: steps whose reports are the same on both):\n\n"
       << "| example | threads | SSCC, 1 thread | SSCC | speedup | traditional, 1 thread | traditional | speedup | "
          "identical |\n|---|---|---|---|---|---|---|---|---|\n"
       << thread_row("spring", spring) << thread_row("bunnies", bunnies);
    if (have_dragon) md << thread_row("dragon (polynomial)", dragon);
  }
  md << "\nTable 2 (sixteen bunnies, average SCD cost per step):\n\n"
     << "| | traditional | SSCC | speedup |\n|---|---|---|---|\n"
     << "| paper: discrete SCD | 640 ms | 22 ms | 29.1x |\n"
     << "| **ours: discrete SCD** | " << format("%.1f ms", bunnies.discrete_traditional.mean()) << " | "
     << format("%.2f ms", bunnies.discrete_sscc.mean()) << " | " << format("%.1fx", bunnies.discrete_speedup())
     << " |\n"
     << "| paper: continuous SCD | 2559 ms | 81 ms | 31.6x |\n"
     << "| **ours: continuous SCD** | " << format("%.1f ms", bunnies.traditional.mean()) << " | "
     << format("%.2f ms", bunnies.sscc.mean()) << " | " << format("%.1fx", bunnies.speedup()) << " |\n";
  md << "\nRun time against error, certificates (the bunny run's self-collision queries replayed; "
        "traditional: "
     << format("%.1f ms", traditional_self.mean()) << " per step):\n\n"
     << "| epsilon | precompute | root radius | SSCC ms/step | speedup | object-steps certified | node visits vs "
        "traditional | reports identical |\n|---|---|---|---|---|---|---|---|\n";
  for (const EpsilonRow& r : epsilons) {
    md << "| " << r.epsilon << " | " << format("%.1f s", r.precompute_s) << " | " << format("%.4g", r.root_radius)
       << " | " << format("%.3f", r.sscc_self_ms) << " | " << format("%.1fx", traditional_self.mean() / r.sscc_self_ms)
       << " | " << r.certified << "/" << r.object_steps << " | " << format("%.1f%%", 100 * r.visits_fraction) << " | "
       << (r.identical ? "yes" : "no") << " |\n";
  }
  md << "\nRun time against error, kernels (" << o.kernel_queries << " random queries of each kind):\n\n"
     << "| time-of-impact tolerance | vertex-face | edge-edge |\n|---|---|---|\n";
  for (const ToleranceTiming& t : tolerances) {
    md << "| " << format("%.0e", t.tolerance) << " | " << format("%.3f us", t.vertex_face_us) << " | "
       << format("%.3f us", t.edge_edge_us) << " |\n";
  }
  const auto [self_ccd_md, self_ccd_disagreements] = self_ccd_section(o, progress);
  md << self_ccd_md;
  md << "\nKernels on degenerate geometry (" << o.kernel_queries / 10
     << " queries per set and kind, each timed alone; FCL beside it, which misses contacts there):\n\n"
     << "| set | kind | median | mean | p99 | max | FCL mean | disagreements with the exact reference |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const DegenerateSetTiming& t : degenerate) {
    md << "| " << t.set << " | " << to_string(t.kind) << " | " << format("%.2f us", t.sscc.median_us) << " | "
       << format("%.2f us", t.sscc.mean_us) << " | " << format("%.1f us", t.sscc.p99_us) << " | "
       << format("%.1f us", t.sscc.max_us) << " | " << format("%.2f us", t.fcl_mean_us) << " | " << t.disagreements
       << " |\n";
  }
  std::ofstream(o.output_dir + "/bench.md") << md.str();
  out << md.str();
  long disagreements = self_ccd_disagreements + (bunnies.steps - bunnies.identical_steps) +
                       (bunnies.steps - bunnies.identical_discrete_steps) + (spring.steps - spring.identical_steps) +
                       (dragon.steps - dragon.identical_steps);
  for (const EpsilonRow& r : epsilons) disagreements += !r.identical;
  for (const DegenerateSetTiming& t : degenerate) disagreements += t.disagreements;
  out << "\nbench: " << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
      << " s; tables in " << o.output_dir << "/bench.md; disagreements " << disagreements << '\n';
  return disagreements;
}

}  // namespace sscc::validation
