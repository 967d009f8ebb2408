#include "kernel_validation.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <sstream>
#include <vector>

#include "agreement.hpp"
#include "degenerate_benchmark.hpp"
#include "fcl_kernels.hpp"
#include "min_distance.hpp"
#include "plot.hpp"
#include "progress_bar.hpp"
#include "query_generators.hpp"
#include "query_set.hpp"
#include "slow_query_search.hpp"
#include "statistics.hpp"

namespace sscc::validation {

namespace {

using Clock = std::chrono::steady_clock;

/// Answers of one method on a list of queries, against the truth.
struct Tally {
  long queries = 0;
  long positives = 0;
  long false_negatives = 0;
  long false_positives = 0;
  double mean_us = 0.0;

  void add(bool answer, bool truth) {
    ++queries;
    positives += truth ? 1 : 0;
    false_negatives += (truth && !answer) ? 1 : 0;
    false_positives += (!truth && answer) ? 1 : 0;
  }
};

void print_tally(std::ostream& out, const std::string& method, Kind kind, const std::string& label, const Tally& t) {
  char line[256];
  std::snprintf(line, sizeof line, "%s %s %s: queries=%ld positives=%ld fn=%ld fp=%ld mean_us=%.3f", method.c_str(),
                to_string(kind), label.c_str(), t.queries, t.positives, t.false_negatives, t.false_positives,
                t.mean_us);
  out << line << '\n';
}

/// Median over repeats of the mean time per query of `answer` on `queries`, in us.
double median_mean_us(const std::vector<Query>& queries, const std::function<bool(const Query&)>& answer, int repeats) {
  std::vector<double> means;
  volatile long sink = 0;
  for (int r = 0; r < std::max(1, repeats); ++r) {
    const auto start = Clock::now();
    long hits = 0;
    for (const Query& q : queries) hits += answer(q) ? 1 : 0;
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    sink = sink + hits;
    means.push_back(1e6 * seconds / std::max<std::size_t>(1, queries.size()));
  }
  return median(means);
}

bool ours(const Query& q) { return run_kernel(q).hit; }

struct Methods {
  std::vector<std::pair<std::string, std::function<bool(const Query&)>>> list;
  Methods() {
    list.emplace_back("sscc", ours);
    if (fcl_available()) list.emplace_back("fcl", run_fcl);
  }
};

long report_query_set(const KernelValidationOptions& options, std::ostream& out, std::ostream& progress) {
  const std::vector<QueryFile> files = read_query_set(options.queries_dir);
  const Methods methods;
  std::map<std::pair<std::string, Kind>, Tally> totals;
  std::map<std::pair<std::string, Kind>, double> total_seconds;
  long problems = 0;
  for (const QueryFile& file : files) {
    progress << "query set: " << file.scene << " " << to_string(file.kind) << " (" << file.queries.size()
             << " queries)\n";
    std::vector<Query> queries;
    std::vector<bool> truth;
    for (const auto& labelled : file.queries) {
      queries.push_back(labelled.query);
      truth.push_back(labelled.truth);
    }
    for (const auto& [name, answer] : methods.list) {
      Tally t;
      for (std::size_t i = 0; i < queries.size(); ++i) t.add(answer(queries[i]), truth[i]);
      t.mean_us = median_mean_us(queries, answer, options.repeats);
      print_tally(out, name, file.kind, file.scene, t);
      Tally& total = totals[{name, file.kind}];
      total.queries += t.queries;
      total.positives += t.positives;
      total.false_negatives += t.false_negatives;
      total.false_positives += t.false_positives;
      total_seconds[{name, file.kind}] += t.mean_us * 1e-6 * t.queries;
      if (name == "sscc") problems += t.false_negatives + t.false_positives;
    }
  }
  std::array<long, ccd::kDecidedByCount> stages{};
  for (const QueryFile& file : files) {
    for (const auto& labelled : file.queries) {
      ++stages[static_cast<int>(run_kernel(labelled.query).decided_by)];
    }
  }
  for (auto& [key, t] : totals) {
    t.mean_us = 1e6 * total_seconds[key] / std::max(1L, t.queries);
    print_tally(out, key.first, key.second, "total", t);
  }
  out << "sscc stages query-set:";
  for (int s = 0; s < ccd::kDecidedByCount; ++s) {
    out << ' ' << ccd::to_string(static_cast<ccd::DecidedBy>(s)) << '=' << stages[s];
  }
  out << '\n';
  return problems;
}

/// Random or near-degenerate queries: each method against the exact reference.
long report_generated(const std::string& label, Kind kind, const std::vector<Query>& queries,
                      const KernelValidationOptions& options, std::ostream& out, std::ostream& progress) {
  progress << label << " " << to_string(kind) << ": " << queries.size() << " queries against the exact reference\n";
  std::vector<bool> truth;
  long disagreements = 0;
  std::array<long, ccd::kDecidedByCount> stages{};
  ProgressBar bar(progress, std::string("kernels: ") + label + " " + to_string(kind) + " against the reference");
  for (std::size_t i = 0; i < queries.size(); ++i) {
    bool contact = false;
    const std::string problem = disagreement_with_reference(queries[i], {}, &contact);
    truth.push_back(contact);
    if (!problem.empty() && ++disagreements <= 5) out << "disagreement: " << problem << '\n';
    ++stages[static_cast<int>(run_kernel(queries[i]).decided_by)];
    bar.update(static_cast<double>(i + 1), static_cast<double>(queries.size()));
  }
  bar.finish();
  for (const auto& [name, answer] : Methods().list) {
    Tally t;
    for (std::size_t i = 0; i < queries.size(); ++i) t.add(answer(queries[i]), truth[i]);
    t.mean_us = median_mean_us(queries, answer, options.repeats);
    print_tally(out, name, kind, label, t);
  }
  out << "sscc stages " << to_string(kind) << " " << label << ":";
  for (int s = 0; s < ccd::kDecidedByCount; ++s) {
    out << ' ' << ccd::to_string(static_cast<ccd::DecidedBy>(s)) << '=' << stages[s];
  }
  out << '\n';
  out << "disagreements " << to_string(kind) << " " << label << ": " << disagreements << '\n';
  return disagreements;
}

void write_plots(const std::string& dir, std::ostream& progress) {
  const std::string tolerance = dir + "/toi_tolerance.csv";
  const std::string separation = dir + "/separation.csv";
  Figure figure{dir + "/kernels_time_vs_error.png", 1100, 450, {}};
  figure.panels.emplace_back(
      "Time of impact: cost against tolerance", "toi tolerance", "mean time per query (us)", LogScale::kX,
      std::vector<PlotSeries>{{tolerance, 1, "2", "vertex-face"}, {tolerance, 1, "3", "edge-edge"}});
  figure.panels.emplace_back("Minimum separation d: positives beyond touching", "d", "queries", LogScale::kX,
                             std::vector<PlotSeries>{{separation, 1, "3", "positives"},
                                                     {separation, 1, "4", "touching (exact, d = 0)"},
                                                     {separation, 1, "6", "not confirmed by sampling (FP bound)"}});
  render_figure(figure, progress);
}

std::vector<ToleranceTiming> toi_tolerance_sweep(const std::vector<Query>& vf, const std::vector<Query>& ee,
                                                 int repeats) {
  std::vector<ToleranceTiming> timings;
  for (int e = 2; e <= 12; e += 2) {
    ccd::CcdOptions o;
    o.toi_tolerance = std::pow(10.0, -e);
    const auto answer = [&](const Query& q) { return run_kernel(q, o).hit; };
    timings.push_back({o.toi_tolerance, median_mean_us(vf, answer, repeats), median_mean_us(ee, answer, repeats)});
  }
  return timings;
}

/// Minimum separation at several d on the first 1000 queries of each kind: positives,
/// touching ones, those confirmed within d by sampling, and the reference's verdict
/// (min_distance.hpp): false negatives and positives beyond d (1 + kSeparationRelativeTolerance),
/// both 0 when the guarantee holds. Returns their count.
long separation_sweep(const std::vector<Query>& vf, const std::vector<Query>& ee,
                      const KernelValidationOptions& options, std::ostream& out, std::ostream& progress) {
  std::filesystem::create_directories(options.output_dir);
  progress << "sweep: minimum separation d (sampled distances for confirmation, the reference for the guarantee)\n";
  std::ofstream sep(options.output_dir + "/separation.csv");
  sep << "d,queries,positives,touching,confirmed_within_d,not_confirmed,mean_us,reference_fn,beyond_band\n";
  std::vector<Query> sample;
  for (std::size_t i = 0; i < std::min<std::size_t>(1000, vf.size()); ++i) {
    sample.push_back(vf[i]);
    sample.push_back(ee[i]);
  }
  std::vector<bool> touching;
  std::vector<double> sampled;
  for (const Query& q : sample) {
    touching.push_back(run_kernel(q).hit);
    sampled.push_back(sampled_min_distance(q, 40));
  }
  long problems = 0;
  for (double d : {1e-4, 1e-3, 1e-2, 3e-2, 1e-1}) {
    ccd::CcdOptions o;
    o.minimum_separation = d;
    const double reach = d * (1 + ccd::kSeparationRelativeTolerance);
    long positives = 0, touch = 0, confirmed = 0, reference_fn = 0, beyond_band = 0;
    for (std::size_t i = 0; i < sample.size(); ++i) {
      const bool hit = run_kernel(sample[i], o).hit;
      positives += hit;
      touch += touching[i];
      confirmed += hit && !touching[i] && sampled[i] <= d;
      if (touching[i] && !hit) out << "separation false negative: " << describe(sample[i]) << '\n';
      BracketOptions question;
      question.threshold = hit ? reach : d;
      const DistanceBracket minimum = min_distance_bracket(sample[i], question);
      if (!hit && minimum.upper <= d) {
        ++reference_fn;
        out << "separation false negative (reference): d=" << d << ' ' << describe(sample[i]) << '\n';
      }
      if (hit && minimum.lower > reach) {
        ++beyond_band;
        out << "separation positive beyond d(1 + tolerance) (reference): d=" << d << ' ' << describe(sample[i]) << '\n';
      }
    }
    problems += reference_fn + beyond_band;
    const auto answer = [&](const Query& q) { return run_kernel(q, o).hit; };
    const double us = median_mean_us(sample, answer, options.repeats);
    const long not_confirmed = positives - touch - confirmed;
    sep << d << ',' << sample.size() << ',' << positives << ',' << touch << ',' << confirmed << ',' << not_confirmed
        << ',' << us << ',' << reference_fn << ',' << beyond_band << '\n';
    char line[256];
    std::snprintf(line, sizeof line,
                  "separation d=%.0e: queries=%zu positives=%ld touching=%ld confirmed_within_d=%ld "
                  "not_confirmed=%ld mean_us=%.3f reference_fn=%ld beyond_band=%ld",
                  d, sample.size(), positives, touch, confirmed, not_confirmed, us, reference_fn, beyond_band);
    out << line << '\n';
  }
  return problems;
}

long sweep_time_against_error(const std::vector<Query>& vf, const std::vector<Query>& ee,
                              const KernelValidationOptions& options, std::ostream& out, std::ostream& progress) {
  std::filesystem::create_directories(options.output_dir);
  progress << "sweep: time of impact tolerance 1e-2 .. 1e-12\n";
  std::ofstream toi(options.output_dir + "/toi_tolerance.csv");
  toi << "tolerance,vertex_face_mean_us,edge_edge_mean_us\n";
  for (const ToleranceTiming& t : toi_tolerance_sweep(vf, ee, options.repeats)) {
    toi << t.tolerance << ',' << t.vertex_face_us << ',' << t.edge_edge_us << '\n';
    char line[160];
    std::snprintf(line, sizeof line, "toi-tolerance %.0e: vertex-face mean_us=%.3f edge-edge mean_us=%.3f", t.tolerance,
                  t.vertex_face_us, t.edge_edge_us);
    out << line << '\n';
  }
  toi.close();
  const long problems = separation_sweep(vf, ee, options, out, progress);
  write_plots(options.output_dir, progress);
  return problems;
}

long report_random(const KernelValidationOptions& options, std::ostream& out, std::ostream& progress) {
  std::mt19937_64 rng(options.seed);
  std::vector<Query> random[2];
  std::vector<Query> degenerate[2];
  const Kind kinds[2] = {Kind::kVertexFace, Kind::kEdgeEdge};
  for (int k = 0; k < 2; ++k) {
    for (long i = 0; i < options.random; ++i) random[k].push_back(random_query(kinds[k], rng));
    for (long i = 0; i < std::max(1L, options.random / 10); ++i) {
      degenerate[k].push_back(near_degenerate_query(kinds[k], rng));
    }
  }
  if (options.separation_only) return separation_sweep(random[0], random[1], options, out, progress);
  long problems = 0;
  for (int k = 0; k < 2; ++k) {
    problems += report_generated("random", kinds[k], random[k], options, out, progress);
    problems += report_generated("near-degenerate", kinds[k], degenerate[k], options, out, progress);
  }
  for (const DegenerateSetTiming& t :
       run_degenerate_benchmark(std::max(1L, options.random / 10), options.seed, out, progress)) {
    problems += t.disagreements;
  }
  const std::size_t n = std::min<std::size_t>(100000, random[0].size());
  problems += sweep_time_against_error({random[0].begin(), random[0].begin() + n},
                                       {random[1].begin(), random[1].begin() + n}, options, out, progress);
  return problems;
}

}  // namespace

std::vector<ToleranceTiming> time_against_toi_tolerance(long queries, std::uint64_t seed, int repeats) {
  std::mt19937_64 rng(seed);
  std::vector<Query> vf, ee;
  for (long i = 0; i < queries; ++i) vf.push_back(random_query(Kind::kVertexFace, rng));
  for (long i = 0; i < queries; ++i) ee.push_back(random_query(Kind::kEdgeEdge, rng));
  return toi_tolerance_sweep(vf, ee, repeats);
}

long run_kernel_validation(const KernelValidationOptions& options, std::ostream& out, std::ostream& progress) {
  if (!fcl_available()) progress << "note: built without FCL; only sscc lines are printed\n";
  long problems = 0;
  if (!options.queries_dir.empty()) problems += report_query_set(options, out, progress);
  if (options.random > 0) problems += report_random(options, out, progress);
  if (options.search_slow > 0) {
    problems += report_slow_query_search({options.search_slow, options.seed, options.exponent_range}, out, progress);
  }
  return problems;
}

}  // namespace sscc::validation
