#include "sscc/experimental/culling_predictor.hpp"

#include <Eigen/QR>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "common/finite.hpp"

namespace sscc::experimental {

CullingPredictor CullingPredictor::fit(const SubspaceBvh& bvh, const std::vector<Eigen::VectorXd>& training_q,
                                       const std::vector<std::vector<char>>& training_collisions) {
  const int poses = static_cast<int>(training_q.size());
  const int nodes = static_cast<int>(bvh.nodes().size());
  const int r = bvh.model().mode_count();
  if (poses == 0) throw std::invalid_argument("culling predictor: no training poses");
  if (training_collisions.size() != training_q.size()) {
    throw std::invalid_argument("culling predictor: " + std::to_string(training_q.size()) + " poses but " +
                                std::to_string(training_collisions.size()) + " ground truths");
  }
  CullingPredictor predictor;
  predictor.sqrt_weights_ = bvh.model().weights().cwiseSqrt();
  Eigen::MatrixXd design(poses, 2 * r + 1);
  Eigen::MatrixXd labels(poses, nodes);
  for (int p = 0; p < poses; ++p) {
    if (training_q[p].size() != r || !all_finite(training_q[p])) {
      throw std::invalid_argument("culling predictor: training pose " + std::to_string(p) + " is not " +
                                  std::to_string(r) + " finite coordinates");
    }
    if (static_cast<int>(training_collisions[p].size()) != nodes) {
      throw std::invalid_argument("culling predictor: the ground truth of training pose " + std::to_string(p) +
                                  " is not one flag per node");
    }
    design.row(p) = predictor.features(training_q[p]).transpose();
    for (int n = 0; n < nodes; ++n) labels(p, n) = training_collisions[p][n] ? -1.0 : 1.0;
  }
  // One factorisation for every node's right-hand side; least-norm when underdetermined.
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> least_squares(design);
  predictor.coefficients_ = least_squares.solve(labels).transpose();
  predictor.thresholds_ = Eigen::VectorXd::Zero(nodes);
  for (int p = 0; p < poses; ++p) {
    // Scored exactly as at run time (not by the product design * F, whose rounding may
    // differ), so that no training pose is culled where it collides.
    const Eigen::VectorXd s = predictor.scores(training_q[p]);
    for (int n = 0; n < nodes; ++n) {
      if (training_collisions[p][n]) predictor.thresholds_[n] = std::max(predictor.thresholds_[n], s[n]);
    }
  }
  return predictor;
}

Eigen::VectorXd CullingPredictor::features(const Eigen::VectorXd& q) const {
  const Eigen::Index r = sqrt_weights_.size();
  if (q.size() != r || !all_finite(q)) {
    throw std::invalid_argument("culling predictor: q must be " + std::to_string(r) + " finite coordinates, got " +
                                std::to_string(q.size()));
  }
  const Eigen::VectorXd q_hat = sqrt_weights_.cwiseProduct(q);
  Eigen::VectorXd phi(2 * r + 1);
  phi << 1.0, q_hat, q_hat.cwiseAbs2();
  return phi;
}

Eigen::VectorXd CullingPredictor::scores(const Eigen::VectorXd& q) const { return coefficients_ * features(q); }

std::vector<char> CullingPredictor::predicted_free(const Eigen::VectorXd& q) const {
  const Eigen::VectorXd s = scores(q);
  std::vector<char> free(static_cast<std::size_t>(s.size()));
  for (Eigen::Index n = 0; n < s.size(); ++n) free[n] = s[n] > thresholds_[n];
  return free;
}

}  // namespace sscc::experimental
