#include "sscc/query/pose_step_ccd.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/finite.hpp"

namespace sscc {

namespace {

SelfCcd detector(const SubspaceBvh& bvh, const Certificates* certificates) {
  return certificates ? SelfCcd(bvh, *certificates) : SelfCcd(bvh);
}

void check_model(const PoseSubspace& subspace, const SubspaceModel& model) {
  if (model.mesh().vertices() != subspace.mean_shape().vertices() ||
      model.mesh().triangles() != subspace.mean_shape().triangles()) {
    throw std::invalid_argument("PoseStepCcd: the model's rest mesh is not the subspace's mean shape");
  }
  if (model.mode_count() != subspace.mode_count()) {
    throw std::invalid_argument("PoseStepCcd: the model has " + std::to_string(model.mode_count()) +
                                " modes, the subspace " + std::to_string(subspace.mode_count()));
  }
  const Eigen::MatrixXd unscaled = model.scaled_basis() * model.weights().cwiseSqrt().asDiagonal();
  if ((unscaled - subspace.basis()).cwiseAbs().maxCoeff() > kModelBasisMatchTolerance) {
    throw std::invalid_argument("PoseStepCcd: the model's basis is not the subspace's U");
  }
}

}  // namespace

PoseStepCcd::PoseStepCcd(const PoseSubspace& subspace, const SubspaceBvh& bvh, const Certificates* certificates)
    : subspace_(subspace), ccd_(detector(bvh, certificates)) {
  check_model(subspace, bvh.model());
}

PoseStepReport PoseStepCcd::query(const std::vector<Eigen::Vector3d>& x0, const std::vector<Eigen::Vector3d>& x1,
                                  const PoseStepOptions& options) const {
  if (!(options.residual_fraction >= 0.0) || !std::isfinite(options.residual_fraction)) {
    throw std::invalid_argument("PoseStepCcd: the residual fraction must be a non-negative finite number");
  }
  const Eigen::VectorXd stacked0 = stack_positions(x0);
  const Eigen::VectorXd stacked1 = stack_positions(x1);
  if (!all_finite(stacked0) || !all_finite(stacked1)) {
    throw std::invalid_argument("PoseStepCcd: a pose has a NaN or infinite coordinate");
  }
  PoseStepReport report;
  report.q0 = subspace_.project(stacked0);
  report.q1 = subspace_.project(stacked1);
  report.residual0 = subspace_.residual(stacked0, report.q0);
  report.residual1 = subspace_.residual(stacked1, report.q1);
  report.tolerance = options.residual_fraction * subspace_.mean_shape().bounding_box_diagonal();
  report.fell_back = report.residual0.max_vertex > report.tolerance || report.residual1.max_vertex > report.tolerance;
  report.ccd =
      report.fell_back ? ccd_.query_positions(x0, x1, options.ccd) : ccd_.query(report.q0, report.q1, options.ccd);
  return report;
}

}  // namespace sscc
