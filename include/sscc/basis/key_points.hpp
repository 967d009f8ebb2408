// Key points: a few vertices whose positions determine a pose's reduced coordinates (the
// statistical paper, section 4, after Meyer and Anderson 2007), so that a simulator that
// moves only the key points gets q, and with it the certificates, in O(k r).
//
// For key vertices K, with A_K the 3k x r rows of U at them and m_K the mean's, the least-
// squares coordinates of key positions y are q = A_K^+ (y - m_K), the r x 3k map A_K^+
// precomputed (from the SVD of A_K). A pose inside the subspace, x = m + U q, gives back q
// to round-off from any key set whose A_K has full column rank; a pose off the subspace
// gives the q that fits its key points best, which may differ from its projection
// U^T (x - m) (that difference is what the selection below minimises).
//
// Selection: first the paper's uniform sampling by radius on the mean shape (take the first
// vertex not yet covered, drop every vertex within the radius of it, repeat), then greedy
// additions: each adds the vertex that most reduces the training poses' reconstruction
// residual sum_p ||x_p - m - U q_p||^2, with q_p fitted to the key points alone. Because U
// is orthonormal this is sum_p (||x_p - m - U c_p||^2 + ||c_p - q_p||^2) with c_p the
// projection: the first term is the subspace's own error, the same for every key set, the
// second what the key points add to it. An addition tries every vertex, each at the cost of
// an r x r eigendecomposition and an r x P fit: O(V (r^3 + r^2 P)) per addition, in
// parallel (OpenMP); the uniform sampling costs O(V k).
#pragma once

#include <Eigen/Core>

#include <vector>

#include "sscc/basis/example_poses.hpp"

namespace sscc {

/// A singular value of A_K below this counts as zero. U's columns are unit vectors, so a
/// singular value of A_K is the share (in norm) of a unit combination of modes that the key
/// points see, and 1 / sigma_min(A_K) is how much the map amplifies errors of the key
/// positions into q (mesh units to mesh units). The threshold is absolute, not relative to
/// the largest singular value: key points where every mode vanishes (a part of the mesh
/// that never moves) have only round-off in A_K, of any rank relative to itself. Raising it
/// refuses usable but ill-conditioned key sets; lowering it accepts maps that amplify
/// round-off of the key positions by more than 10^6.
inline constexpr double kKeyPointSingularFloor = 1e-6;
/// Greedy additions stop early when the best one would lower the training residual by less
/// than this fraction of it (the residual is then at round-off or the subspace's own error,
/// and more points only cost run time).
inline constexpr double kGreedyStopFraction = 1e-6;
/// Default radius of the uniform sampling, in diagonals of the mean shape's bounding box.
/// The paper's 1% to 4% of the vertices: on a mesh of a few thousand vertices spread over
/// an animal, 0.1 of the diagonal keeps some tens.
inline constexpr double kDefaultKeyPointRadiusFraction = 0.1;

struct KeyPointOptions {
  /// Radius of the uniform sampling, in diagonals of the mean shape's bounding box (> 0).
  double radius_fraction = kDefaultKeyPointRadiusFraction;
  /// Greedy additions after the sampling (at most; see kGreedyStopFraction).
  int greedy_additions = 8;
};

/// The least-squares map from key point positions to reduced coordinates.
class KeyPointMap {
 public:
  /// Throws std::invalid_argument for a vertex out of range or repeated, and when the key
  /// rows of U do not have full column rank r: fewer than ceil(r / 3) key points, or points
  /// that do not see every mode (the message says how many points, the rank reached and
  /// what to do).
  KeyPointMap(const PoseSubspace& subspace, std::vector<int> vertices);

  const std::vector<int>& vertices() const { return vertices_; }
  /// A_K^+, r x 3k: q = matrix() (y - m_K), y the key positions stacked in vertices() order.
  const Eigen::MatrixXd& matrix() const { return matrix_; }
  /// sigma_max / sigma_min of A_K: how much the map can amplify key position errors.
  double condition_number() const { return condition_number_; }
  /// q from the key points' positions (in vertices() order), O(k r). Throws
  /// std::invalid_argument for a wrong count.
  Eigen::VectorXd coordinates(const std::vector<Eigen::Vector3d>& key_positions) const;
  /// q from a whole stacked pose (3V), reading only its key points.
  Eigen::VectorXd coordinates_of_pose(const Eigen::VectorXd& pose) const;

 private:
  Eigen::VectorXd coordinates_of_stacked_keys(const Eigen::VectorXd& keys) const;

  std::vector<int> vertices_;
  Eigen::Index pose_size_ = 0;
  Eigen::VectorXd key_mean_;
  Eigen::MatrixXd matrix_;
  double condition_number_ = 0.0;
};

/// The uniform sampling: vertices in index order, each kept when no kept vertex lies within
/// `radius` (mesh units, > 0) of it. Every vertex then lies within the radius of a kept
/// one, and kept ones are more than the radius apart.
std::vector<int> uniform_key_points(const std::vector<Eigen::Vector3d>& positions, double radius);

struct KeyPointSelection {
  std::vector<int> vertices;  ///< the sampled ones first, then the greedy additions in order
  int sampled = 0;            ///< how many came from the uniform sampling
  /// Root mean square over the training poses p and vertices v of the vertex distance
  /// ||x_pv - m_v - U_v q_p|| (mesh units), q_p from the key points: after the sampling,
  /// then after each greedy addition. With a key set that does not determine q, q_p is the
  /// least-norm fit.
  std::vector<double> training_residual;
};

/// Samples and greedily extends key points for the subspace, measured on the training poses
/// (3V x P). Throws std::invalid_argument for bad options or sizes; does not check the
/// rank (KeyPointMap does).
KeyPointSelection select_key_points(const PoseSubspace& subspace, const Eigen::MatrixXd& training_poses,
                                    const KeyPointOptions& options = {});

}  // namespace sscc
