#include "certificate_sweep.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "plot.hpp"
#include "sscc/query/self_ccd.hpp"
#include "trajectory.hpp"

namespace sscc::validation {

namespace {

struct TimedRun {
  std::vector<SelfCcdReport> reports;
  double total_ms = 0.0;
  long nodes_visited = 0;
  int root_certified = 0;
};

TimedRun run_steps(const SelfCcd& ccd, const std::vector<Eigen::VectorXd>& q, const SelfCcdOptions& options) {
  TimedRun run;
  for (std::size_t k = 0; k + 1 < q.size(); ++k) {
    const auto start = std::chrono::steady_clock::now();
    run.reports.push_back(ccd.query(q[k], q[k + 1], options));
    run.total_ms += 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.nodes_visited += run.reports.back().stats.nodes_visited;
    run.root_certified += run.reports.back().stats.root_certified;
  }
  return run;
}

}  // namespace

long run_certificate_sweep(const CertificateSweepOptions& o, std::ostream& out, std::ostream& progress) {
  const SubspaceModel model = load_model(o.model, progress);
  const SubspaceBvh bvh(model);
  const std::vector<Eigen::VectorXd> q = random_trajectory(model, o.steps, o.amplitude, o.seed, o.burst);
  SelfCcdOptions traditional_options;
  set_traditional(traditional_options);
  progress << "traditional: " << o.steps << " steps\n";
  const TimedRun traditional = run_steps(SelfCcd(bvh), q, traditional_options);
  std::filesystem::create_directories(o.output_dir);
  const std::string csv_path = o.output_dir + "/certificates_epsilon.csv";
  std::ofstream csv(csv_path);
  csv << "epsilon,precompute_s,root_radius,certified_steps,culled_node_visits,sscc_mean_ms,traditional_mean_ms,"
         "speedup\n";
  long problems = 0;
  for (double epsilon : o.epsilons) {
    CertificateParameters parameters;
    parameters.epsilon = epsilon;
    progress << "epsilon " << epsilon << ": precomputing\n" << std::flush;
    const Certificates certificates = Certificates::precompute(bvh, parameters);
    const SelfCcd ccd(bvh, certificates);
    const TimedRun sscc = run_steps(ccd, q, {});
    int identical = 0;
    for (int k = 0; k < o.steps; ++k) {
      identical += sscc.reports[k].pairs == traditional.reports[k].pairs &&
                   sscc.reports[k].features == traditional.reports[k].features;
    }
    problems += o.steps - identical;
    const double culled = 1.0 - static_cast<double>(sscc.nodes_visited) / std::max(1L, traditional.nodes_visited);
    char line[400];
    std::snprintf(line, sizeof line,
                  "certificates epsilon=%g: precompute_s=%.3f root_radius=%.6g certified_steps=%d/%d "
                  "culled_node_visits=%.4f sscc_mean_ms=%.4f traditional_mean_ms=%.4f speedup=%.2f "
                  "identical_steps=%d/%d",
                  epsilon, certificates.stats().seconds, certificates.node_radius(0), sscc.root_certified, o.steps,
                  culled, sscc.total_ms / o.steps, traditional.total_ms / o.steps, traditional.total_ms / sscc.total_ms,
                  identical, o.steps);
    out << line << '\n';
    csv << epsilon << ',' << certificates.stats().seconds << ',' << certificates.node_radius(0) << ','
        << sscc.root_certified << ',' << culled << ',' << sscc.total_ms / o.steps << ','
        << traditional.total_ms / o.steps << ',' << traditional.total_ms / sscc.total_ms << '\n';
  }
  csv.close();
  progress << "csv: " << csv_path << '\n';
  Figure figure{o.output_dir + "/certificates_epsilon.png", 1100, 450, {}};
  figure.panels.emplace_back("Precomputation against accuracy", "epsilon", "seconds", LogScale::kX,
                             std::vector<PlotSeries>{{csv_path, 1, "2", "precompute time"},
                                                     {csv_path, 1, "3", "root radius", "linespoints lw 2", true}});
  figure.panels.back().y2_label = "root radius";
  figure.panels.emplace_back("Query: speedup over the traditional query", "epsilon", "speedup", LogScale::kX,
                             std::vector<PlotSeries>{{csv_path, 1, "8", "speedup (mean time)"},
                                                     {csv_path, 1, "($5*100)", "node visits culled (%)"}});
  render_figure(figure, progress);
  return problems;
}

}  // namespace sscc::validation
