#include "agreement.hpp"

#include <algorithm>
#include <cstdio>

namespace sscc::validation {

namespace {

/// Distance between the primitives' points given by the contact parameters at time t.
double distance_at(const Query& q, double t, const double params[2]) {
  Eigen::Vector3d x[4];
  for (int i = 0; i < 4; ++i) x[i] = (1.0 - t) * q.points[i] + t * q.points[i + 4];
  if (q.kind == Kind::kVertexFace) {
    const Eigen::Vector3d on_face = (1.0 - params[0] - params[1]) * x[1] + params[0] * x[2] + params[1] * x[3];
    return (x[0] - on_face).norm();
  }
  const Eigen::Vector3d on_a = x[0] + params[0] * (x[1] - x[0]);
  const Eigen::Vector3d on_b = x[2] + params[1] * (x[3] - x[2]);
  return (on_a - on_b).norm();
}

/// Bound on how fast the distance between the primitives can change per unit of t.
double relative_speed_bound(const Query& q) {
  double first = 0.0;
  double second = 0.0;
  const int split = q.kind == Kind::kVertexFace ? 1 : 2;
  for (int i = 0; i < 4; ++i) {
    const double speed = (q.points[i + 4] - q.points[i]).norm();
    (i < split ? first : second) = std::max(i < split ? first : second, speed);
  }
  return first + second;
}

double scale_of(const Query& q) {
  double s = 0.0;
  for (const auto& p : q.points) s = std::max(s, p.cwiseAbs().maxCoeff());
  return s;
}

}  // namespace

std::string describe(const Query& q) {
  std::string out = to_string(q.kind);
  char buffer[96];
  for (const auto& p : q.points) {
    std::snprintf(buffer, sizeof buffer, " (%a, %a, %a)", p[0], p[1], p[2]);
    out += buffer;
  }
  return out;
}

std::string disagreement_with_reference(const Query& q, const ccd::CcdOptions& options, bool* reference_contact) {
  const ccd::CcdResult kernel = run_kernel(q, options);
  exact::ContactTime truth = run_reference(q);
  if (reference_contact) *reference_contact = truth.has_value();
  if (kernel.hit != truth.has_value()) {
    return std::string(kernel.hit ? "false positive" : "false negative") + " (decided by " +
           ccd::to_string(kernel.decided_by) + "): " + describe(q);
  }
  if (!truth) return {};
  const double tolerance = std::max(options.toi_tolerance, ccd::kMinToiTolerance);
  if (exact::compare(mpq_class(kernel.toi), *truth) > 0) {
    return "time of impact later than the first contact: " + describe(q);
  }
  if (exact::compare(mpq_class(kernel.toi) + mpq_class(tolerance), *truth) < 0) {
    return "time of impact earlier than the tolerance allows: " + describe(q);
  }
  const double allowed = tolerance * relative_speed_bound(q) + 1e-12 * scale_of(q);
  if (distance_at(q, kernel.toi, kernel.params) > allowed) {
    return "contact parameters do not place the primitives together: " + describe(q);
  }
  return {};
}

}  // namespace sscc::validation
