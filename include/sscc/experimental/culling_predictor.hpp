// EXPERIMENTAL -- NOT CONSERVATIVE. Regression-predicted culling (the statistical paper,
// section 4, eq. 3): it can declare a node collision free in a pose where two of its
// triangles intersect. It is here to measure what statistical culling would buy and what it
// would miss beside the sound certificates (certificates.hpp), which never miss; nothing in
// the library culls with it. Its output must always be labelled experimental.
//
// What the paper fits: a linear map F from the key point positions K of each training pose
// to that pose's certificate values C, min_F ||F K - C||, evaluated by one matrix product at
// run time. What is fitted here, per node n of a SubspaceBvh:
//   - the value C_np of training pose p is the exact ground truth of the discrete test
//     (node_collisions.hpp): +1 when no two non-adjacent triangles under n intersect in
//     pose p, -1 when some do. A per-pose certificate in the paper's sense has no other
//     exact meaning for one pose, and these labels are what a cull must get right;
//   - the features of a pose are phi(q) = [1, q_hat, q_hat .* q_hat] (2r + 1 numbers),
//     q_hat = M^(1/2) q, with q from the key points (key_points.hpp), itself linear in K;
//   - F = argmin ||Phi F - C||_F over the training poses, all nodes at once (the least-norm
//     solution when there are fewer poses than features). Regression on +-1 labels is
//     Fisher's linear discriminant for the two classes.
// Why the squares, not K alone as in the paper: a score linear in K is linear in q, so it
// can cull only on one side of a hyperplane in pose space, while collision freedom holds
// around the mean shape and fails on every side of it (a bar folded either way brings its
// ends together). With the squares the score can represent axis-aligned ellipsoids in
// q_hat, the shape of the sound certificates ||q||_M < R_n, and the fit is still the linear
// least-squares problem of eq. 3 (on features of K).
//
// Decision: node n is predicted free in pose q when score_n(q) = F_n^T phi(q) > theta_n,
// theta_n the largest score a training pose colliding under n got (0 when none did). So no
// training pose is culled where it collides, by construction; held-out poses may be, which
// is what validate_culling (cull_validation.hpp) counts. Cost at run time: O(kr) for q from
// the key points, O(r) for the features, O(r) per node scored, as for a certificate.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "sscc/bvh/subspace_bvh.hpp"

namespace sscc::experimental {

class CullingPredictor {
 public:
  /// Fits on training poses given by their reduced coordinates (q, not scaled; from the key
  /// points) and their ground truth (colliding_nodes of each, one flag per node). Throws
  /// std::invalid_argument for no poses, sizes that do not match the hierarchy, or a NaN or
  /// infinite q.
  static CullingPredictor fit(const SubspaceBvh& bvh, const std::vector<Eigen::VectorXd>& training_q,
                              const std::vector<std::vector<char>>& training_collisions);

  int node_count() const { return static_cast<int>(thresholds_.size()); }
  int feature_count() const { return static_cast<int>(coefficients_.cols()); }
  /// Every node's score in configuration q (not scaled).
  Eigen::VectorXd scores(const Eigen::VectorXd& q) const;
  /// EXPERIMENTAL: per node, 1 when the regression predicts no intersection under it.
  std::vector<char> predicted_free(const Eigen::VectorXd& q) const;
  const Eigen::VectorXd& thresholds() const { return thresholds_; }

 private:
  CullingPredictor() = default;
  Eigen::VectorXd features(const Eigen::VectorXd& q) const;

  Eigen::VectorXd sqrt_weights_;  // M^(1/2), r
  Eigen::MatrixXd coefficients_;  // nodes x (2r + 1): row n is F_n
  Eigen::VectorXd thresholds_;    // theta_n
};

}  // namespace sscc::experimental
