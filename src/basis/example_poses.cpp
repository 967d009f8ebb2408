#include "sscc/basis/example_poses.hpp"

#include <Eigen/SVD>

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/finite.hpp"
#include "common/sign_convention.hpp"
#include "sscc/mesh/mesh_io.hpp"

namespace sscc {

namespace {

std::string triangle_text(const Triangle& t) {
  return "(" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")";
}

}  // namespace

Eigen::VectorXd stack_positions(const std::vector<Eigen::Vector3d>& positions) {
  Eigen::VectorXd stacked(3 * static_cast<Eigen::Index>(positions.size()));
  for (std::size_t v = 0; v < positions.size(); ++v)
    stacked.segment<3>(3 * static_cast<Eigen::Index>(v)) = positions[v];
  return stacked;
}

std::vector<Eigen::Vector3d> unstack_positions(const Eigen::VectorXd& stacked) {
  if (stacked.size() % 3 != 0) {
    throw std::invalid_argument("unstack_positions: " + std::to_string(stacked.size()) +
                                " coordinates are not a whole number of vertices");
  }
  std::vector<Eigen::Vector3d> positions(static_cast<std::size_t>(stacked.size() / 3));
  for (std::size_t v = 0; v < positions.size(); ++v)
    positions[v] = stacked.segment<3>(3 * static_cast<Eigen::Index>(v));
  return positions;
}

Eigen::VectorXd pose_of(const TriangleMesh& reference, const TriangleMesh& pose, const std::string& name) {
  if (pose.vertex_count() != reference.vertex_count()) {
    throw std::invalid_argument("example pose " + name + ": " + std::to_string(pose.vertex_count()) +
                                " vertices, the reference mesh has " + std::to_string(reference.vertex_count()));
  }
  if (pose.triangle_count() != reference.triangle_count()) {
    throw std::invalid_argument("example pose " + name + ": " + std::to_string(pose.triangle_count()) +
                                " triangles, the reference mesh has " + std::to_string(reference.triangle_count()));
  }
  for (int t = 0; t < pose.triangle_count(); ++t) {
    if (pose.triangles()[t] != reference.triangles()[t]) {
      throw std::invalid_argument("example pose " + name + ": triangle " + std::to_string(t) + " is " +
                                  triangle_text(pose.triangles()[t]) + ", the reference mesh's is " +
                                  triangle_text(reference.triangles()[t]) + " (a pose needs the same connectivity)");
    }
  }
  return stack_positions(pose.vertices());
}

Eigen::MatrixXd read_example_poses(const TriangleMesh& reference, const std::vector<std::string>& paths) {
  Eigen::MatrixXd poses(3L * reference.vertex_count(), static_cast<Eigen::Index>(paths.size()));
  for (std::size_t p = 0; p < paths.size(); ++p) {
    poses.col(static_cast<Eigen::Index>(p)) = pose_of(reference, read_mesh(paths[p]), paths[p]);
  }
  return poses;
}

PoseSubspace::PoseSubspace(const TriangleMesh& reference, const Eigen::MatrixXd& poses, const PcaOptions& options)
    : mean_shape_(reference) {
  const Eigen::Index count = poses.cols();
  if (poses.rows() != 3L * reference.vertex_count()) {
    throw std::invalid_argument("PCA: poses have " + std::to_string(poses.rows()) + " coordinates, the mesh's " +
                                std::to_string(reference.vertex_count()) + " vertices need " +
                                std::to_string(3L * reference.vertex_count()));
  }
  if (count < 2)
    throw std::invalid_argument("PCA: at least two example poses are needed, got " + std::to_string(count));
  if (!all_finite(poses)) throw std::invalid_argument("PCA: an example pose has a NaN or infinite coordinate");
  if (!(options.variance_fraction > 0.0 && options.variance_fraction <= 1.0)) {
    throw std::invalid_argument("PCA: the variance fraction must lie in (0, 1], got " +
                                std::to_string(options.variance_fraction));
  }
  if (options.modes < 0) throw std::invalid_argument("PCA: a negative number of modes was requested");
  mean_ = poses.rowwise().mean();
  mean_shape_ = TriangleMesh(unstack_positions(mean_), reference.triangles());
  const Eigen::MatrixXd centred = poses.colwise() - mean_;
  // Thin SVD of the tall 3V x P matrix: U is 3V x P, cheap for P << 3V. (The P x P Gram
  // matrix would square the singular values and lose the small components to round-off.)
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(centred, Eigen::ComputeThinU);
  const Eigen::VectorXd& sigma = svd.singularValues();  // decreasing
  const double round_off = kRoundOffSingularFraction * poses.norm();
  if (!(sigma.size() > 0 && sigma[0] > round_off)) {
    throw std::invalid_argument("PCA: all example poses are the same (up to round-off)");
  }
  Eigen::Index components = 0;
  while (components < sigma.size() && sigma[components] > round_off) ++components;
  component_variances_ = sigma.head(components).cwiseAbs2() / static_cast<double>(count - 1);
  Eigen::Index kept = options.modes;
  if (kept > components) {
    throw std::invalid_argument("PCA: " + std::to_string(options.modes) + " modes requested, the " +
                                std::to_string(count) + " poses have " + std::to_string(components) +
                                " components (at most poses - 1)");
  }
  if (kept == 0 && options.variance_fraction >= 1.0) {
    // Not by the sum: the smallest variances no longer change it in floating point.
    kept = components;
  } else if (kept == 0) {
    const double total = component_variances_.sum();
    double explained = 0.0;
    while (kept < components && explained < options.variance_fraction * total)
      explained += component_variances_[kept++];
  }
  basis_ = svd.matrixU().leftCols(kept);
  make_largest_entries_positive(basis_);
}

double PoseSubspace::explained_fraction() const {
  return component_variances_.head(mode_count()).sum() / component_variances_.sum();
}

void PoseSubspace::check_pose_size(const Eigen::VectorXd& pose) const {
  if (pose.size() != mean_.size()) {
    throw std::invalid_argument("PoseSubspace: a pose of " + std::to_string(pose.size()) +
                                " coordinates for a mesh of " + std::to_string(mean_.size() / 3) + " vertices");
  }
}

Eigen::VectorXd PoseSubspace::project(const Eigen::VectorXd& pose) const {
  check_pose_size(pose);
  return basis_.transpose() * (pose - mean_);
}

Eigen::VectorXd PoseSubspace::reconstruct(const Eigen::VectorXd& q) const {
  if (q.size() != mode_count()) {
    throw std::invalid_argument("PoseSubspace: q has " + std::to_string(q.size()) + " coordinates, the subspace " +
                                std::to_string(mode_count()));
  }
  return mean_ + basis_ * q;
}

SubspaceResidual PoseSubspace::residual(const Eigen::VectorXd& pose, const Eigen::VectorXd& q) const {
  check_pose_size(pose);
  const Eigen::VectorXd difference = pose - reconstruct(q);
  SubspaceResidual residual;
  residual.norm = difference.stableNorm();
  for (Eigen::Index v = 0; v < difference.size() / 3; ++v) {
    residual.max_vertex = std::max(residual.max_vertex, difference.segment<3>(3 * v).norm());
  }
  return residual;
}

}  // namespace sscc
