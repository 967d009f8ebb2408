#include "stress_steps.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "stress_inputs.hpp"

namespace sscc::validation {

namespace {

/// A step that leaves a certificate ends this many radii out: far enough that the traversal
/// meets the node's contacts, near enough that it stays cheap.
constexpr double kOutsideFactor = 4.0;

struct Radius {
  std::string name;
  double value;
};

/// The radii whose boundaries are probed: the root's always; in the full run also the
/// smallest positive node radius and a random node's.
std::vector<Radius> probed_radii(const Certificates& certificates, bool all, std::mt19937_64& rng) {
  std::vector<Radius> radii{{"R_root", certificates.node_radius(0)}};
  if (!all || certificates.node_count() < 2) return radii;
  double smallest = std::numeric_limits<double>::infinity();
  for (int n = 0; n < certificates.node_count(); ++n) {
    if (certificates.node_radius(n) > 0) smallest = std::min(smallest, certificates.node_radius(n));
  }
  if (std::isfinite(smallest) && smallest != radii[0].value) radii.push_back({"R_min", smallest});
  std::uniform_int_distribution<int> node(1, certificates.node_count() - 1);
  const int n = node(rng);
  radii.push_back({"R_node" + std::to_string(n), certificates.node_radius(n)});
  return radii;
}

}  // namespace

std::vector<StressStep> stress_steps(const SubspaceModel& model, const Certificates& certificates, StepBudget budget,
                                     std::mt19937_64& rng) {
  const int r = model.mode_count();
  const Eigen::VectorXd inverse_root_weights = model.weights().cwiseSqrt().cwiseInverse();
  // Scaled coordinates (||q_hat|| = ||q||_M) to the coordinates the queries take.
  const auto to_q = [&](const Eigen::VectorXd& q_hat) -> Eigen::VectorXd {
    return q_hat.cwiseProduct(inverse_root_weights);
  };
  const auto direction = [&] { return random_direction(r, rng); };
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(r);
  std::vector<StressStep> steps;
  const double inside = 1 - 1e-12;
  const bool thorough = budget == StepBudget::kFull || budget == StepBudget::kLarge;
  for (const Radius& radius : probed_radii(certificates, thorough, rng)) {
    const double R = radius.value;
    if (!(R > 0) || !std::isfinite(R)) continue;
    std::vector<std::pair<std::string, double>> factors{{"(1-1e-12)", inside}, {"", 1.0}};
    if (thorough) {
      factors.insert(factors.begin(), {"(1-1e-9)", 1 - 1e-9});
      factors.push_back({"(1-2^-50)", 1 - std::ldexp(1.0, -50)});
      factors.push_back({"(1+2^-50)", 1 + std::ldexp(1.0, -50)});
    }
    for (const auto& [name, factor] : factors) {
      steps.push_back({"0 -> " + name + radius.name, zero, to_q(factor * R * direction())});
    }
    steps.push_back({"(1-1e-12)" + radius.name + " -> 4" + radius.name + " (leaves)", to_q(inside * R * direction()),
                     to_q(kOutsideFactor * R * direction())});
    if (budget == StepBudget::kLargest) continue;
    steps.push_back({"(1-1e-12)" + radius.name + " both ends (stays inside)", to_q(inside * R * direction()),
                     to_q(inside * R * direction())});
    if (thorough) {
      steps.push_back({"4" + radius.name + " -> (1-1e-12)" + radius.name + " (enters)",
                       to_q(kOutsideFactor * R * direction()), to_q(inside * R * direction())});
    }
  }
  // Amplitudes relative to the root radius, or to the global radius when the root has none.
  const double root = certificates.node_radius(0);
  const double unit = root > 0 && std::isfinite(root) ? root : certificates.global_radius();
  const Eigen::VectorXd still = to_q(2 * unit * direction());
  steps.push_back({"no motion at 2 R_root", still, still});
  steps.push_back({"0 -> 2 R_root (from rest)", zero, to_q(2 * unit * direction())});
  std::vector<double> amplitudes{0.5, 8};
  if (budget == StepBudget::kFull) amplitudes = {0.5, 2, 8, 32};
  if (budget == StepBudget::kLarge) amplitudes = {0.5, 2, 8, 32, 128};
  if (budget == StepBudget::kLargest) amplitudes = {2};
  if (budget == StepBudget::kFull || budget == StepBudget::kQuick) {
    // The global radius: the floppiest direction moves some vertex by half the mesh's size.
    steps.push_back({"0 -> R_global", zero, to_q(certificates.global_radius() * direction())});
  }
  std::uniform_real_distribution<double> fraction(0.0, 1.0);
  for (double amplitude : amplitudes) {
    const double norm = amplitude * unit;
    std::ostringstream kind;
    kind << "random, " << amplitude << " R_root";
    steps.push_back({kind.str(), to_q(fraction(rng) * norm * direction()), to_q(norm * direction())});
  }
  return steps;
}

}  // namespace sscc::validation
