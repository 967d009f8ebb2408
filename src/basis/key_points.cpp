#include "sscc/basis/key_points.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

namespace sscc {

namespace {

/// The key rows A_K of U (3k x r), or of any 3V-row matrix or stacked pose.
Eigen::MatrixXd key_rows(const Eigen::Ref<const Eigen::MatrixXd>& rows, const std::vector<int>& vertices) {
  Eigen::MatrixXd keys(3 * static_cast<Eigen::Index>(vertices.size()), rows.cols());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    keys.middleRows<3>(3 * static_cast<Eigen::Index>(i)) = rows.middleRows<3>(3L * vertices[i]);
  }
  return keys;
}

/// The greedy selection's bookkeeping. For key set K, the least-squares (least-norm when
/// rank deficient) fit of every training pose at once is Q = G^+ B with the normal
/// equations G = A_K^T A_K (r x r) and B = A_K^T Y_K (r x P), both sums over the key
/// vertices, so a candidate costs one r x r eigendecomposition, not a fit from scratch.
/// (Squaring the condition number is harmless for ranking candidates; the final map is
/// computed from A_K itself.)
class GreedyResidual {
 public:
  GreedyResidual(const PoseSubspace& subspace, const Eigen::MatrixXd& training_poses)
      : basis_(subspace.basis()), centred_(training_poses.colwise() - subspace.mean()) {
    projection_ = basis_.transpose() * centred_;
    subspace_error_ = (centred_ - basis_ * projection_).squaredNorm();
    gram_ = Eigen::MatrixXd::Zero(basis_.cols(), basis_.cols());
    moments_ = Eigen::MatrixXd::Zero(basis_.cols(), centred_.cols());
  }

  void add(int v) {
    gram_ += vertex_gram(v);
    moments_ += vertex_moments(v);
  }
  /// sum_p ||x_p - m - U q_p||^2 with v added to the key set (v < 0: as it is).
  double squared_residual_with(int v) const {
    if (v < 0) return squared_residual(gram_, moments_);
    return squared_residual(gram_ + vertex_gram(v), moments_ + vertex_moments(v));
  }
  /// The root mean square vertex distance, over poses and vertices, of a squared residual sum.
  double rms(double squared) const { return std::sqrt(squared / static_cast<double>(centred_.size() / 3)); }

 private:
  Eigen::MatrixXd vertex_gram(int v) const {
    const auto rows = basis_.middleRows<3>(3L * v);
    return rows.transpose() * rows;
  }
  Eigen::MatrixXd vertex_moments(int v) const {
    return basis_.middleRows<3>(3L * v).transpose() * centred_.middleRows<3>(3L * v);
  }
  double squared_residual(const Eigen::MatrixXd& gram, const Eigen::MatrixXd& moments) const {
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram);
    const Eigen::VectorXd& lambda = eigen.eigenvalues();  // increasing, >= 0 up to round-off
    // The singular values of A_K are their square roots: the same rank rule as the final map.
    Eigen::VectorXd inverse = Eigen::VectorXd::Zero(lambda.size());
    for (Eigen::Index i = 0; i < lambda.size(); ++i) {
      if (lambda[i] > kKeyPointSingularFloor * kKeyPointSingularFloor) inverse[i] = 1.0 / lambda[i];
    }
    const Eigen::MatrixXd& vectors = eigen.eigenvectors();
    const Eigen::MatrixXd fit = vectors * (inverse.asDiagonal() * (vectors.transpose() * moments));
    return subspace_error_ + (fit - projection_).squaredNorm();
  }

  const Eigen::MatrixXd& basis_;
  Eigen::MatrixXd centred_;
  Eigen::MatrixXd projection_;  // U^T (x_p - m), r x P
  double subspace_error_ = 0.0;
  Eigen::MatrixXd gram_;
  Eigen::MatrixXd moments_;
};

}  // namespace

KeyPointMap::KeyPointMap(const PoseSubspace& subspace, std::vector<int> vertices)
    : vertices_(std::move(vertices)), pose_size_(subspace.mean().size()) {
  const int vertex_count = subspace.mean_shape().vertex_count();
  std::vector<char> seen(static_cast<std::size_t>(vertex_count), 0);
  for (int v : vertices_) {
    if (v < 0 || v >= vertex_count) {
      throw std::invalid_argument("key points: vertex " + std::to_string(v) + " is out of range (the mesh has " +
                                  std::to_string(vertex_count) + ")");
    }
    if (seen[v]++) throw std::invalid_argument("key points: vertex " + std::to_string(v) + " is given twice");
  }
  const int r = subspace.mode_count();
  const int k = static_cast<int>(vertices_.size());
  if (3 * k < r) {
    throw std::invalid_argument("key points: " + std::to_string(k) + " points give " + std::to_string(3 * k) +
                                " equations for " + std::to_string(r) +
                                " modes; the least-squares map needs full column rank, so at least " +
                                std::to_string((r + 2) / 3) + " points");
  }
  const Eigen::MatrixXd rows = key_rows(subspace.basis(), vertices_);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(rows, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& sigma = svd.singularValues();  // decreasing
  const Eigen::Index rank = (sigma.array() > kKeyPointSingularFloor).count();
  if (rank < r) {
    char floor[32];
    std::snprintf(floor, sizeof floor, "%g", kKeyPointSingularFloor);
    throw std::invalid_argument("key points: the basis rows at the " + std::to_string(k) + " points have rank " +
                                std::to_string(rank) + " for " + std::to_string(r) + " modes (singular values below " +
                                floor +
                                " count as zero): the least-squares map needs full column rank; the points do not "
                                "determine every mode, add key points (a smaller radius or more greedy additions) "
                                "where every mode moves");
  }
  condition_number_ = sigma[0] / sigma[r - 1];
  matrix_ = svd.matrixV() * sigma.cwiseInverse().asDiagonal() * svd.matrixU().transpose();
  key_mean_ = key_rows(subspace.mean(), vertices_);
}

Eigen::VectorXd KeyPointMap::coordinates_of_stacked_keys(const Eigen::VectorXd& keys) const {
  return matrix_ * (keys - key_mean_);
}

Eigen::VectorXd KeyPointMap::coordinates(const std::vector<Eigen::Vector3d>& key_positions) const {
  if (key_positions.size() != vertices_.size()) {
    throw std::invalid_argument("key points: " + std::to_string(key_positions.size()) + " positions for " +
                                std::to_string(vertices_.size()) + " key points");
  }
  return coordinates_of_stacked_keys(stack_positions(key_positions));
}

Eigen::VectorXd KeyPointMap::coordinates_of_pose(const Eigen::VectorXd& pose) const {
  if (pose.size() != pose_size_) {
    throw std::invalid_argument("key points: a pose of " + std::to_string(pose.size()) + " coordinates, the mesh has " +
                                std::to_string(pose_size_));
  }
  return coordinates_of_stacked_keys(key_rows(pose, vertices_));
}

std::vector<int> uniform_key_points(const std::vector<Eigen::Vector3d>& positions, double radius) {
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw std::invalid_argument("key points: the sampling radius must be positive and finite");
  }
  std::vector<int> kept;
  const double squared = radius * radius;
  for (int v = 0; v < static_cast<int>(positions.size()); ++v) {
    const bool covered = std::any_of(kept.begin(), kept.end(),
                                     [&](int k) { return (positions[k] - positions[v]).squaredNorm() <= squared; });
    if (!covered) kept.push_back(v);
  }
  return kept;
}

KeyPointSelection select_key_points(const PoseSubspace& subspace, const Eigen::MatrixXd& training_poses,
                                    const KeyPointOptions& options) {
  if (options.greedy_additions < 0) throw std::invalid_argument("key points: negative greedy additions");
  if (training_poses.rows() != subspace.mean().size() || training_poses.cols() < 1) {
    throw std::invalid_argument("key points: the training poses must be " + std::to_string(subspace.mean().size()) +
                                " x P with P >= 1, got " + std::to_string(training_poses.rows()) + " x " +
                                std::to_string(training_poses.cols()));
  }
  const TriangleMesh& mean = subspace.mean_shape();
  KeyPointSelection selection;
  selection.vertices = uniform_key_points(mean.vertices(), options.radius_fraction * mean.bounding_box_diagonal());
  selection.sampled = static_cast<int>(selection.vertices.size());
  GreedyResidual greedy(subspace, training_poses);
  std::vector<char> chosen(static_cast<std::size_t>(mean.vertex_count()), 0);
  for (int v : selection.vertices) {
    greedy.add(v);
    chosen[v] = 1;
  }
  double current = greedy.squared_residual_with(-1);
  selection.training_residual.push_back(greedy.rms(current));
  std::vector<double> score(chosen.size());
  for (int addition = 0; addition < options.greedy_additions; ++addition) {
    const int n = static_cast<int>(chosen.size());
#pragma omp parallel for schedule(dynamic, 64)
    for (int v = 0; v < n; ++v) {
      score[v] = chosen[v] ? std::numeric_limits<double>::max() : greedy.squared_residual_with(v);
    }
    const int best = static_cast<int>(std::min_element(score.begin(), score.end()) - score.begin());
    if (chosen[best] || !(score[best] < current - kGreedyStopFraction * current)) break;
    greedy.add(best);
    chosen[best] = 1;
    selection.vertices.push_back(best);
    current = score[best];
    selection.training_residual.push_back(greedy.rms(current));
  }
  return selection;
}

}  // namespace sscc
