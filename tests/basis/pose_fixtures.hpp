// Example poses for the PCA and key point tests: a bar bent, twisted and displaced by the
// seeded generator, some poses folded until its ends meet.
#pragma once

#include <Eigen/Core>

#include <random>

#include "sscc/basis/example_pose_generator.hpp"
#include "sscc/basis/example_poses.hpp"
#include "sscc/certificates/certificates.hpp"
#include "support/test_meshes.hpp"

namespace sscc::test {

/// A bar 1 x 0.3 x 0.2: bent about its thinnest axis, its ends (0.3 wide in the bending
/// plane) meet once an end turns by more than about acos(0.3) = 1.27 radians.
inline TriangleMesh pose_bar() { return box_surface({1.0, 0.3, 0.2}, {10, 3, 2}); }

/// Bends up to 1.5 radians (below pi / 2, so that the mean shape does not fold), twists up
/// to 0.5, small polynomial displacements.
inline ExamplePoseOptions bar_pose_options(int poses, std::uint64_t seed) {
  ExamplePoseOptions options;
  options.poses = poses;
  options.seed = seed;
  options.twist = 0.5;
  options.bend = 1.5;
  options.modal_amplitude = 0.02;
  return options;
}

inline PcaOptions pca_modes(int modes) {
  PcaOptions options;
  options.modes = modes;
  return options;
}

inline PcaOptions pca_fraction(double fraction) {
  PcaOptions options;
  options.variance_fraction = fraction;
  return options;
}

/// Coordinates of a pose inside the subspace: independent normal components with the
/// subspace's variances (a pose like the training poses, but exactly in the span).
inline Eigen::VectorXd random_subspace_coordinates(const PoseSubspace& subspace, std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::VectorXd q(subspace.mode_count());
  for (int i = 0; i < q.size(); ++i) q[i] = std::sqrt(subspace.variances()[i]) * normal(rng);
  return q;
}

/// A random displacement orthogonal to the subspace (U^T e = 0), scaled so that its largest
/// vertex displacement is `largest`.
inline Eigen::VectorXd orthogonal_displacement(const PoseSubspace& subspace, std::mt19937_64& rng, double largest) {
  std::normal_distribution<double> normal;
  Eigen::VectorXd e(subspace.mean().size());
  for (Eigen::Index i = 0; i < e.size(); ++i) e[i] = normal(rng);
  e -= subspace.basis() * (subspace.basis().transpose() * e);
  double max_vertex = 0.0;
  for (Eigen::Index v = 0; v < e.size() / 3; ++v) max_vertex = std::max(max_vertex, e.segment<3>(3 * v).norm());
  return e * (largest / max_vertex);
}

/// Bar poses, the PCA of the first `training` of them, its model and hierarchy.
struct PosePca {
  TriangleMesh bar = pose_bar();
  Eigen::MatrixXd poses;
  int training;
  PoseSubspace subspace;
  SubspaceModel model;
  SubspaceBvh bvh;

  PosePca(int count, int training_count, std::uint64_t seed, const PcaOptions& pca)
      : poses(generate_example_poses(bar, bar_pose_options(count, seed))),
        training(training_count),
        subspace(bar, poses.leftCols(training_count), pca),
        model(subspace.model()),
        bvh(model) {}
};

/// With the model's sound certificates, radii resolved up to `global_scale` R_global (4 by
/// default: PCA weights count in standard deviations, and the poses reach a few; the
/// precomputation takes longer the larger it is).
struct CertifiedPoses : PosePca {
  Certificates certificates;

  CertifiedPoses(int count, int training_count, std::uint64_t seed, const PcaOptions& pca, double global_scale = 4.0)
      : PosePca(count, training_count, seed, pca), certificates(Certificates::precompute(bvh, [&] {
          CertificateParameters parameters;
          parameters.global_radius_scale = global_scale;
          return parameters;
        }())) {}
};

}  // namespace sscc::test
