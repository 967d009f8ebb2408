#include "stress_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "feature_brute_force.hpp"
#include "load_run.hpp"
#include "progress_bar.hpp"
#include "sscc/bvh/subspace_bvh.hpp"
#include "sscc/certificates/certificates.hpp"
#include "sscc/query/self_ccd.hpp"
#include "sscc/scene/scene.hpp"
#include "stress_cases.hpp"
#include "stress_steps.hpp"

namespace sscc::validation {

namespace {

enum class Outcome { kIdentical, kRefused, kMismatch };

struct CaseResult {
  Outcome outcome = Outcome::kIdentical;
  int triangles = 0;
  int modes = 0;
  int steps = 0;
  int colliding_steps = 0;
  int root_certified_steps = 0;
  double root_radius = 0.0;
  double seconds = 0.0;
  std::string message;  ///< the refusal, or the first mismatch
};

const char* reference_name(StressReference reference) {
  switch (reference) {
    case StressReference::kBruteForce:
      return "brute force";
    case StressReference::kExhaustive:
      return "exhaustive";
    case StressReference::kTraditional:
      return "traditional";
  }
  return "";
}

std::vector<Eigen::Vector3d> positions(const SubspaceModel& model, const Eigen::VectorXd& q) {
  const Eigen::VectorXd q_hat = model.scaled_coordinates(q);
  std::vector<Eigen::Vector3d> x(model.mesh().vertex_count());
  for (int v = 0; v < model.mesh().vertex_count(); ++v) x[v] = model.position(v, q_hat);
  return x;
}

/// A scratch path for the certificate file of one case (removed when the case is done).
std::string certificate_path() {
  return (std::filesystem::temp_directory_path() / ("sscc_stress_" + std::to_string(getpid()) + ".sscc")).string();
}

/// Every query of one step against the reference; "" when all are identical.
std::string check_step(const StressCase& stress_case, const SelfCcd& detector, const SelfCcd& from_file,
                       const Scene& scene, const StressStep& step, CaseResult& result) {
  const SubspaceModel& model = detector.bvh().model();
  SelfCcdOptions traditional, displacement;
  set_traditional(traditional);
  displacement.use_certificates = false;  // the displacement bounds instead
  const SelfCcdReport certified = detector.query(step.q0, step.q1);
  const SelfCcdReport uncertified = detector.query(step.q0, step.q1, traditional);
  const std::vector<Eigen::Vector3d> x0 = positions(model, step.q0), x1 = positions(model, step.q1);
  SelfCcdReport reference;
  switch (stress_case.reference) {
    case StressReference::kBruteForce:
      reference = feature_brute_force(model.mesh(), x0, x1);
      break;
    case StressReference::kExhaustive:
      reference = detector.query_exhaustive(step.q0, step.q1);
      break;
    case StressReference::kTraditional:
      reference = uncertified;
      break;
  }
  if (reference.collided()) ++result.colliding_steps;
  if (certified.stats.root_certified) ++result.root_certified_steps;
  std::vector<std::pair<const char*, SelfCcdReport>> reports;
  reports.emplace_back("certified query", certified);
  reports.emplace_back("certificates read from file", from_file.query(step.q0, step.q1));
  if (stress_case.reference != StressReference::kTraditional) reports.emplace_back("traditional query", uncertified);
  reports.emplace_back("displacement-bounded query", detector.query(step.q0, step.q1, displacement));
  reports.emplace_back("query_positions", detector.query_positions(x0, x1));
  ObjectStep object;
  object.q0 = step.q0;
  object.q1 = step.q1;
  const SceneReport scene_report = scene.step({object});
  // A scene skips an object that does not move (stated in scene.hpp): nothing to compare.
  if (scene_report.objects[0].outcome != SelfTestOutcome::kStatic) {
    reports.emplace_back("scene step", scene_report.objects[0].report);
  }
  for (const auto& [name, report] : reports) {
    const std::string difference = report_difference(reference, report);
    if (!difference.empty()) return "step '" + step.kind + "', " + name + ": " + difference;
  }
  return "";
}

CaseResult run_case(const StressCase& stress_case, bool quick, std::uint64_t seed) {
  CaseResult result;
  const auto start = std::chrono::steady_clock::now();
  std::mt19937_64 rng(seed);
  const std::string path = certificate_path();
  try {
    const SubspaceModel model = stress_case.build(rng);
    result.triangles = model.mesh().triangle_count();
    result.modes = model.mode_count();
    const SubspaceBvh bvh(model);
    const Certificates certificates = Certificates::precompute(bvh, stress_case.certificates);
    result.root_radius = certificates.node_radius(0);
    certificates.write(path);
    const SelfCcd detector(bvh, certificates);
    const SelfCcd from_file(bvh, Certificates::read(path, bvh));
    Scene scene;
    scene.add_object(detector);
    StepBudget budget = quick ? StepBudget::kQuick : StepBudget::kFull;
    if (stress_case.reference == StressReference::kExhaustive) budget = StepBudget::kLarge;
    if (stress_case.reference == StressReference::kTraditional) budget = StepBudget::kLargest;
    for (const StressStep& step : stress_steps(model, certificates, budget, rng)) {
      ++result.steps;
      const std::string difference = check_step(stress_case, detector, from_file, scene, step, result);
      if (!difference.empty() && result.outcome == Outcome::kIdentical) {
        result.outcome = Outcome::kMismatch;
        result.message = difference;
      }
    }
  } catch (const std::exception& e) {
    if (result.outcome == Outcome::kIdentical) {  // a mismatch before the refusal stays one
      result.outcome = Outcome::kRefused;
      result.message = e.what();
    }
  }
  std::remove(path.c_str());
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::string outcome_text(const CaseResult& result) {
  switch (result.outcome) {
    case Outcome::kIdentical:
      return "identical";
    case Outcome::kRefused:
      return "refused: " + result.message;
    case Outcome::kMismatch:
      return "MISMATCH: " + result.message;
  }
  return "";
}

}  // namespace

long run_stress(const StressOptions& options, std::ostream& out, std::ostream& progress) {
  const auto start = std::chrono::steady_clock::now();
  long cases = 0, identical = 0, refused = 0, mismatches = 0;
  // The long run first, while the process holds only its own memory (its resident size is
  // then its own, not what the largest cases left with the allocator).
  LoadRunResult run;
  if (options.only_case == 0) {
    LoadRunOptions load;
    load.steps = options.quick ? std::min(options.load_steps, kQuickLoadSteps) : options.load_steps;
    load.seed = options.seed;
    progress << "stress: load, " << load.steps << " scene steps ..." << std::endl;
    run = run_load(load, progress);
  }
  out << "| # | group | case | triangles | r | reference | root radius | steps | colliding | root-certified | seconds "
         "| result |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  const std::vector<StressCase> all = stress_cases();
  const auto chosen = [&](std::size_t i) {
    return (!options.quick || all[i].in_quick) && (options.only_case == 0 || options.only_case == long(i) + 1);
  };
  long to_run = 0;
  for (std::size_t i = 0; i < all.size(); ++i) to_run += chosen(i);
  // By cases: the largest meshes come last and take the longest, so the estimate is low early.
  ProgressBar bar(progress, "stress");
  for (std::size_t i = 0; i < all.size(); ++i) {
    const StressCase& stress_case = all[i];
    if (!chosen(i)) continue;
    bar.update(static_cast<double>(cases), static_cast<double>(to_run),
               "case " + std::to_string(i + 1) + ": " + stress_case.group + ", " + stress_case.name);
    const CaseResult result = run_case(stress_case, options.quick, options.seed * 1000003 + i);
    bar.clear();
    ++cases;
    identical += result.outcome == Outcome::kIdentical;
    refused += result.outcome == Outcome::kRefused;
    mismatches += result.outcome == Outcome::kMismatch;
    std::ostringstream radius;
    radius << std::setprecision(3) << result.root_radius;
    out << "| " << i + 1 << " | " << stress_case.group << " | " << stress_case.name << " | " << result.triangles
        << " | " << result.modes << " | " << reference_name(stress_case.reference) << " | " << radius.str() << " | "
        << result.steps << " | " << result.colliding_steps << " | " << result.root_certified_steps << " | "
        << std::fixed << std::setprecision(1) << result.seconds << std::defaultfloat << " | " << outcome_text(result)
        << " |" << std::endl;
  }
  if (options.only_case == 0) {
    ++cases;
    const bool load_identical = run.mismatched_steps == 0 && run.rss_growth_kb <= kRssGrowthLimitKb;
    identical += load_identical;
    mismatches += !load_identical;
    out << "\nload: " << run.steps << " steps of a scene of " << run.objects << " objects (" << run.triangles
        << " triangles each, r = " << run.modes << "), " << run.threads << " threads against 1: " << run.colliding_steps
        << " colliding steps, " << run.mismatched_steps << " steps whose reports differ"
        << (run.first_difference.empty() ? "" : " (first: " + run.first_difference + ")") << "; resident memory "
        << run.rss_warm_kb << " kB after " << run.warm_up_steps << " warm-up steps, " << run.rss_end_kb
        << " kB at the end (growth " << run.rss_growth_kb << " kB, limit " << kRssGrowthLimitKb << "); " << std::fixed
        << std::setprecision(1) << run.seconds << " s" << std::defaultfloat << "\n";
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out << "stress time: " << std::fixed << std::setprecision(1) << seconds << " s" << std::defaultfloat << "\n";
  out << "stress: cases=" << cases << " identical=" << identical << " refused=" << refused
      << " mismatches=" << mismatches << std::endl;
  return mismatches;
}

}  // namespace sscc::validation
