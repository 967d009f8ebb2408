#include "selfccd_validation.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <map>
#include <memory>
#include <stdexcept>

#include "fcl_self_ccd.hpp"
#include "fcl_settle.hpp"
#include "sscc/query/self_ccd.hpp"
#include "sscc/threads.hpp"
#include "statistics.hpp"
#include "trajectory.hpp"

namespace sscc::validation {

namespace {

struct MethodRun {
  std::vector<PairList> pairs;                   // per step
  std::vector<SelfCcdReport> reports;            // per step, sscc methods only
  std::vector<double> milliseconds;              // per step
  std::vector<double> one_thread_ms;             // per step, sscc and traditional on one thread
  double cpu_ms = 0.0, one_thread_cpu_ms = 0.0;  // process CPU time over all steps, each thread count
  int identical_one_thread = 0;                  // steps whose one-thread report is the same
};

PairList pair_list(const SelfCcdReport& report) {
  PairList pairs;
  for (const auto& p : report.pairs) pairs.emplace_back(p.first, p.second);
  return pairs;
}

/// CPU time of the whole process (every thread), in ms: with wall-clock time, how much of the
/// machine a run had.
double process_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

}  // namespace

long run_selfccd_validation(const SelfCcdValidationOptions& o, std::ostream& out, std::ostream& progress) {
  const SubspaceModel model = load_model(o.model, progress);
  const SubspaceBvh bvh(model);
  const BvhBuildStats& build = bvh.build_stats();
  progress << "bvh: " << build.nodes << " nodes, " << build.leaves << " leaves, depth " << build.depth << ", built in "
           << build.seconds << " s\n";
  std::unique_ptr<Certificates> certificates;
  if (!o.certificates.empty()) {
    certificates = std::make_unique<Certificates>(Certificates::read(o.certificates, bvh));
    progress << "certificates " << o.certificates << ": root radius " << certificates->node_radius(0)
             << ", global radius " << certificates->global_radius() << '\n';
  }
  if (!certificates && std::find(o.methods.begin(), o.methods.end(), "sscc") != o.methods.end()) {
    throw std::invalid_argument("method sscc needs --certificates FILE.sscc (from sscc precompute)");
  }
  // One detector: "traditional" is the same query with every cull of SelfCcdOptions switched
  // off, "cones" and "bounds" with only the normal cones or the displacement bounds on.
  const SelfCcd ccd = certificates ? SelfCcd(bvh, *certificates) : SelfCcd(bvh);
  SelfCcdOptions traditional;
  set_traditional(traditional);
  SelfCcdOptions cones = traditional;
  cones.use_normal_cones = true;
  SelfCcdOptions bounds = traditional;
  bounds.use_displacement_bounds = true;
  for (const SelfCcdOptions& each : {SelfCcdOptions(), traditional, cones, bounds}) {
    ccd.prepare(each);  // precomputation, as the certificates: not timed
  }
  const int threads = default_threads();
  SelfCcdOptions sscc_one_thread, traditional_one_thread = traditional;
  sscc_one_thread.threads = traditional_one_thread.threads = 1;
  const std::vector<Eigen::VectorXd> q = random_trajectory(model, o.steps, o.amplitude, o.seed, o.burst);
  std::map<std::string, MethodRun> runs;
  long problems = 0;
  for (const std::string& method : o.methods) {
    progress << "method " << method << ": " << o.steps << " steps\n";
    MethodRun& run = runs[method];
    std::unique_ptr<FclSelfCcd> fcl;
    if (method == "fcl") fcl = std::make_unique<FclSelfCcd>(model.mesh(), model.excluded_pairs());
    for (int k = 0; k < o.steps; ++k) {
      const auto start = std::chrono::steady_clock::now();
      const double cpu_start = process_cpu_ms();
      if (method == "sscc" || method == "cones" || method == "bounds" || method == "traditional" ||
          method == "exhaustive") {
        run.reports.push_back(method == "sscc"          ? ccd.query(q[k], q[k + 1])
                              : method == "cones"       ? ccd.query(q[k], q[k + 1], cones)
                              : method == "bounds"      ? ccd.query(q[k], q[k + 1], bounds)
                              : method == "traditional" ? ccd.query(q[k], q[k + 1], traditional)
                                                        : ccd.query_exhaustive(q[k], q[k + 1]));
        run.pairs.push_back(pair_list(run.reports.back()));
      } else if (method == "fcl") {
        run.pairs.push_back(fcl->step(model.deformed_positions(q[k]), model.deformed_positions(q[k + 1])));
      } else {
        throw std::invalid_argument("unknown method '" + method +
                                    "' (sscc, cones, bounds, traditional, exhaustive, fcl)");
      }
      run.milliseconds.push_back(1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      run.cpu_ms += process_cpu_ms() - cpu_start;
      if (threads > 1 && (method == "sscc" || method == "traditional")) {  // the same step on one thread
        const auto serial_start = std::chrono::steady_clock::now();
        const double serial_cpu_start = process_cpu_ms();
        const SelfCcdReport serial =
            ccd.query(q[k], q[k + 1], method == "sscc" ? sscc_one_thread : traditional_one_thread);
        run.one_thread_ms.push_back(
            1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - serial_start).count());
        run.one_thread_cpu_ms += process_cpu_ms() - serial_cpu_start;
        const bool same = serial.pairs == run.reports.back().pairs && serial.features == run.reports.back().features &&
                          serial.earliest_toi == run.reports.back().earliest_toi;
        run.identical_one_thread += same;
        problems += !same;
      }
    }
    long colliding = 0, pairs = 0;
    for (const PairList& p : run.pairs) colliding += !p.empty(), pairs += static_cast<long>(p.size());
    double mean = 0.0;
    for (double ms : run.milliseconds) mean += ms / o.steps;
    char line[256];
    std::snprintf(line, sizeof line, "%s selfccd: steps=%d colliding_steps=%ld pairs=%ld mean_ms=%.3f median_ms=%.3f",
                  method.c_str(), o.steps, colliding, pairs, mean, median(run.milliseconds));
    out << line;
    if (method == "sscc") {
      long certified = 0;
      for (const SelfCcdReport& report : run.reports) certified += report.stats.root_certified;
      out << " certified_steps=" << certified;
    }
    if (!run.reports.empty()) {
      double node_tests = 0.0, triangle_pairs = 0.0, cone_culled = 0.0, plane_culled = 0.0;
      for (const SelfCcdReport& report : run.reports) {
        node_tests += static_cast<double>(report.stats.box_tests) / o.steps;
        triangle_pairs += static_cast<double>(report.stats.triangle_pairs) / o.steps;
        cone_culled += static_cast<double>(report.stats.cone_culled) / o.steps;
        plane_culled += static_cast<double>(report.stats.plane_culled) / o.steps;
      }
      std::snprintf(line, sizeof line,
                    " node_tests_per_step=%.0f triangle_pairs_per_step=%.0f cone_culls_per_step=%.0f"
                    " plane_culls_per_step=%.0f",
                    node_tests, triangle_pairs, cone_culled, plane_culled);
      out << line;
    }
    out << '\n';
    if (!run.one_thread_ms.empty()) {
      double one = 0.0;
      for (double ms : run.one_thread_ms) one += ms / o.steps;
      std::snprintf(
          line, sizeof line,
          "%s threads: one_thread_mean_ms=%.3f threads=%d mean_ms=%.3f speedup=%.2f one_thread_median_ms=%.3f "
          "median_ms=%.3f identical_steps=%d/%d one_thread_cpu_ms=%.3f cpu_ms=%.3f",
          method.c_str(), one, threads, mean, one / std::max(mean, 1e-9), median(run.one_thread_ms),
          median(run.milliseconds), run.identical_one_thread, o.steps, run.one_thread_cpu_ms / o.steps,
          run.cpu_ms / o.steps);
      out << line << '\n';
    }
  }
  // Time ratios of each method against the slower ones on the same steps (sscc against
  // traditional has its own lines below).
  const std::vector<std::string> ladder = {"sscc", "cones", "traditional", "fcl"};
  for (std::size_t i = 0; i < ladder.size(); ++i) {
    for (std::size_t j = i + 1; j < ladder.size(); ++j) {
      const std::string& fast = ladder[i];
      const std::string& slow = ladder[j];
      if (!runs.count(fast) || !runs.count(slow) || (fast == "sscc" && slow == "traditional")) continue;
      double fast_total = 0.0, slow_total = 0.0;
      for (int k = 0; k < o.steps; ++k) {
        fast_total += runs[fast].milliseconds[k];
        slow_total += runs[slow].milliseconds[k];
      }
      char line[160];
      std::snprintf(line, sizeof line, "speedup %s vs %s: mean_time_ratio=%.2f", fast.c_str(), slow.c_str(),
                    slow_total / fast_total);
      out << line << '\n';
    }
  }
  if (runs.count("sscc")) {
    // The cost of a step the root certificate decides, timed over many repeats of one.
    const std::vector<SelfCcdReport>& reports = runs["sscc"].reports;
    const auto certified =
        std::find_if(reports.begin(), reports.end(), [](const SelfCcdReport& r) { return r.stats.root_certified; });
    if (certified != reports.end()) {
      const std::size_t k = static_cast<std::size_t>(certified - reports.begin());
      constexpr int kRepeats = 100000;
      long collided = 0;
      const auto start = std::chrono::steady_clock::now();
      for (int i = 0; i < kRepeats; ++i) collided += ccd.query(q[k], q[k + 1]).collided();
      const double us =
          1e6 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / kRepeats;
      char line[160];
      std::snprintf(line, sizeof line, "sscc certified step: mean_us=%.3f (one root-certified step, %d repeats)", us,
                    kRepeats);
      out << line << '\n';
      if (collided != 0) ++problems;
    }
  }
  if (runs.count("sscc") && runs.count("traditional")) {
    const MethodRun& fast = runs["sscc"];
    const MethodRun& slow = runs["traditional"];
    std::vector<double> ratios;
    double fast_total = 0.0, slow_total = 0.0;
    for (int k = 0; k < o.steps; ++k) {
      ratios.push_back(slow.milliseconds[k] / std::max(fast.milliseconds[k], 1e-6));
      fast_total += fast.milliseconds[k];
      slow_total += slow.milliseconds[k];
    }
    char line[256];
    std::snprintf(line, sizeof line, "speedup sscc vs traditional: mean_time_ratio=%.2f median_step_ratio=%.2f",
                  slow_total / fast_total, median(ratios));
    out << line << '\n';
    // Where the time goes: the steps the root certificate does not decide.
    int open = 0;
    double fast_open = 0.0, slow_open = 0.0;
    for (int k = 0; k < o.steps; ++k) {
      if (fast.reports[k].stats.root_certified) continue;
      ++open;
      fast_open += fast.milliseconds[k];
      slow_open += slow.milliseconds[k];
    }
    if (open > 0) {
      std::snprintf(line, sizeof line,
                    "steps not decided by the root certificate: %d, sscc mean_ms=%.3f traditional mean_ms=%.3f", open,
                    fast_open / open, slow_open / open);
      out << line << '\n';
    }
  }
  for (std::size_t i = 0; i < o.methods.size(); ++i) {
    for (std::size_t j = i + 1; j < o.methods.size(); ++j) {
      const MethodRun& a = runs[o.methods[i]];
      const MethodRun& b = runs[o.methods[j]];
      const bool full = !a.reports.empty() && !b.reports.empty();
      int identical = 0;
      SettledDisagreements settled;
      for (int k = 0; k < o.steps; ++k) {
        const bool same =
            full ? a.reports[k].pairs == b.reports[k].pairs && a.reports[k].features == b.reports[k].features
                 : a.pairs[k] == b.pairs[k];
        identical += same;
        if (same) continue;
        if (full) {
          ++problems;
          continue;
        }
        // One side is FCL: the exact kernels decide each pair the two disagree on.
        const bool a_is_fcl = o.methods[i] == "fcl";
        settled +=
            settle_with_exact_kernels(model.mesh(), model.deformed_positions(q[k]), model.deformed_positions(q[k + 1]),
                                      a_is_fcl ? a.pairs[k] : b.pairs[k], a_is_fcl ? b.pairs[k] : a.pairs[k]);
      }
      out << "agreement " << o.methods[i] << " vs " << o.methods[j] << ": identical_steps=" << identical << "/"
          << o.steps << '\n';
      if (!full && identical != o.steps) {
        out << "disagreements settled by the exact kernels (" << o.methods[i] << " vs " << o.methods[j]
            << "): fcl_false_positive_pairs=" << settled.fcl_false_positives
            << " fcl_false_negative_pairs=" << settled.fcl_false_negatives << " unexplained=" << settled.unexplained
            << '\n';
        problems += settled.unexplained;
      }
    }
  }
  return problems;
}

}  // namespace sscc::validation
