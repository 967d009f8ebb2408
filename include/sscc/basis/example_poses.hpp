// A subspace from example poses: principal component analysis of a set of poses of one mesh
// (the statistical paper, section 4, after Meyer and Anderson 2007).
//
// The P poses x_1..x_P (3V coordinates each, row 3v + k is vertex v's coordinate k; the
// vertex order and triangles of one reference mesh) are centred on their mean m, and the
// thin SVD of the centred 3V x P matrix D = [x_1 - m, ..., x_P - m] = W S V^T gives the
// principal directions (columns of W, orthonormal) and the variances s_i^2 / (P - 1) of the
// poses' coordinates along them. The subspace model is
//   x = m + U q,   U = the first r columns of W,   weights w_i = 1 / variance_i,
// so its rest mesh is the mean shape (not the reference's positions), U^T U = I, and
// ||q||_M^2 = sum_i q_i^2 / variance_i is the squared Mahalanobis distance of the pose's
// coordinates from the mean: certificate radii are then counted in standard deviations of
// the training set.
//
// Guarantee: with every component kept, each training pose is reproduced to round-off:
// m + U U^T (x_p - m) = x_p up to the singular values dropped as round-off, below
// kRoundOffSingularFraction (1e-13) of the poses' size. Such directions are not components
// (rounding can make them, and their weight would be enormous); P poses give at most
// P - 1 components.
//
// Units: positions and q in mesh units (U is orthonormal), variances in mesh units squared,
// weights in 1 / mesh units squared.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

#include "sscc/mesh/triangle_mesh.hpp"
#include "sscc/model/subspace_model.hpp"

namespace sscc {

/// A singular value of the centred poses below this fraction of the poses' size (the
/// Frobenius norm of the 3V x P matrix of poses as given) is round-off, not a component.
/// Centring in doubles perturbs every entry by about 1e-16 of its coordinate, and a matrix
/// of such errors has singular values up to about 1e-16 of the poses' size; 1e-13 leaves a
/// factor of 1000 above that. (Relative to the largest singular value instead, the floor
/// would depend on how much the poses deform: generated poses of a smooth family have real
/// components down to 1e-14 of the largest.) Raising it drops real small components, and
/// training poses are no longer reproduced; lowering it towards 1e-16 keeps noise
/// directions with weights near 1e32. Poses whose largest singular value is below it are
/// one pose up to round-off.
inline constexpr double kRoundOffSingularFraction = 1e-13;
/// Default explained-variance fraction when neither a fraction nor a count is given.
inline constexpr double kDefaultVarianceFraction = 0.99;

struct PcaOptions {
  /// Components kept; 0: the smallest count whose variance reaches variance_fraction.
  int modes = 0;
  /// In (0, 1]: the fraction of the total variance (the sum over all components) the kept
  /// components must explain. 1 keeps every component.
  double variance_fraction = kDefaultVarianceFraction;
};

/// How far a pose lies from the subspace: the residual x - m - U q of coordinates q. The
/// pose-step query decides its fallback by max_vertex (pose_step_ccd.hpp: a distance per
/// vertex is what a contact tolerance is about); the key point selection minimises the
/// sum of squared norms over the training poses (key_points.hpp: least squares).
struct SubspaceResidual {
  double norm = 0.0;        ///< 2-norm over all 3V coordinates (mesh units)
  double max_vertex = 0.0;  ///< largest per-vertex distance (mesh units)
};

/// A pose as one 3V vector (vertex v's coordinates at rows 3v..3v+2), and back.
Eigen::VectorXd stack_positions(const std::vector<Eigen::Vector3d>& positions);
std::vector<Eigen::Vector3d> unstack_positions(const Eigen::VectorXd& stacked);

/// A pose mesh's positions, stacked, after checking it has the reference's vertex count
/// and triangles (same order). Throws std::invalid_argument naming `name` and the first
/// difference.
Eigen::VectorXd pose_of(const TriangleMesh& reference, const TriangleMesh& pose, const std::string& name);
/// Reads the pose files (any format read_mesh reads), 3V x P, one pose per column.
/// Throws MeshFileError for an unreadable file and std::invalid_argument naming the file
/// whose vertex count or triangles differ from the reference's.
Eigen::MatrixXd read_example_poses(const TriangleMesh& reference, const std::vector<std::string>& paths);

class PoseSubspace {
 public:
  /// PCA of `poses` (3V x P, P >= 2) for the reference's connectivity. Throws
  /// std::invalid_argument for a wrong row count, NaN/infinity, fewer than two poses, poses
  /// that are all the same, a fraction outside (0, 1], or more modes than components.
  PoseSubspace(const TriangleMesh& reference, const Eigen::MatrixXd& poses, const PcaOptions& options = {});

  /// The reference's triangles at the mean positions.
  const TriangleMesh& mean_shape() const { return mean_shape_; }
  const Eigen::VectorXd& mean() const { return mean_; }
  /// U, 3V x r, orthonormal columns in order of decreasing variance.
  const Eigen::MatrixXd& basis() const { return basis_; }
  int mode_count() const { return static_cast<int>(basis_.cols()); }
  /// The kept components' variances (mesh units squared), decreasing.
  Eigen::VectorXd variances() const { return component_variances_.head(mode_count()); }
  /// 1 / variances(): ||q||_M is the Mahalanobis distance.
  Eigen::VectorXd weights() const { return variances().cwiseInverse(); }
  /// Every component's variance (kept or not), decreasing.
  const Eigen::VectorXd& component_variances() const { return component_variances_; }
  /// The fraction of the total variance the kept components explain.
  double explained_fraction() const;
  /// The subspace model x = m + U q with the Mahalanobis weights.
  SubspaceModel model() const { return SubspaceModel(mean_shape_, basis_, weights()); }

  /// q = argmin ||x - m - U q|| = U^T (x - m) for a stacked pose (3V). Throws
  /// std::invalid_argument for a wrong size.
  Eigen::VectorXd project(const Eigen::VectorXd& pose) const;
  /// m + U q, stacked.
  Eigen::VectorXd reconstruct(const Eigen::VectorXd& q) const;
  /// ||pose - m - U q|| both as a 2-norm and as the largest vertex distance.
  SubspaceResidual residual(const Eigen::VectorXd& pose, const Eigen::VectorXd& q) const;

 private:
  void check_pose_size(const Eigen::VectorXd& pose) const;

  TriangleMesh mean_shape_;
  Eigen::VectorXd mean_;
  Eigen::MatrixXd basis_;
  Eigen::VectorXd component_variances_;
};

}  // namespace sscc
