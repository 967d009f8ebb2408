// `sscc poses`: the subspace-from-example-poses pipeline end to end on one mesh, with the
// experimental statistical culling held to the exact ground truth beside the sound
// certificates.
//
//   1. seeded synthetic poses (example_pose_generator.hpp): `training` for fitting,
//      `held_out` more from the same distribution for testing;
//   2. PCA of the training poses; with every component the training poses come back to
//      round-off (reported), the model keeps the components the options ask for;
//   3. key points (uniform sampling, greedy additions) and their least-squares map; held-out
//      residuals from the projection (the subspace's own error) and from the key points;
//   4. the sound certificates of the PCA model (Certificates::precompute);
//   5. the EXPERIMENTAL, NOT CONSERVATIVE regression predictor, fitted on the training
//      poses' key-point coordinates against the exact discrete test;
//   6. on the held-out poses (at their key-point coordinates, ground truth again the exact
//      discrete test): culls and false culls of both, side by side;
//   7. pose steps (pose_step_ccd.hpp) from the mean shape to each held-out pose as given
//      (off the subspace: the traditional query) and to its key-point reconstruction (in
//      it: certified).
// The last line is
//   poses: sound_false_culls=N experimental_false_culls=M (EXPERIMENTAL, NOT CONSERVATIVE) time_s=X
#pragma once

#include <ostream>
#include <string>

#include "sscc/basis/example_pose_generator.hpp"
#include "sscc/basis/example_poses.hpp"
#include "sscc/basis/key_points.hpp"
#include "sscc/certificates/certificates.hpp"

namespace sscc::validation {

/// Default end angles (radians) of the generated poses: a bend near pi / 2 folds a long
/// mesh until its ends meet in some poses, so that culling has something to get wrong,
/// while the mean shape (where the bends of either sign average out) stays free of
/// self-contact. (At 2 radians the averaged ends pull into the body and the mean shape
/// intersects itself: no root certificate.)
inline constexpr double kPosesDefaultBend = 1.5;
inline constexpr double kPosesDefaultTwist = 1.0;
/// Default explained variance: the bend alone explains 99% of these poses (3 to 5
/// components); 0.999 keeps about a dozen, and with them the twist and the modes.
inline constexpr double kPosesDefaultVariance = 0.999;
/// Default scale of the certificates' global radius. The PCA weights count in standard
/// deviations, and one standard deviation of these poses moves vertices by a sizeable
/// fraction of the mesh, so R_global (scale 1) is about 1.5 while typical poses have
/// ||q||_M near sqrt(r): no node is certified below the cap. Scale 4 resolves the radii the
/// poses actually reach, at a few times the precomputation.
inline constexpr double kPosesDefaultGlobalScale = 4.0;

struct PosesCommandOptions {
  std::string mesh;
  int training = 40;
  int held_out = 20;
  ExamplePoseOptions generator = [] {
    ExamplePoseOptions o;
    o.bend = kPosesDefaultBend;
    o.twist = kPosesDefaultTwist;
    return o;
  }();  ///< its pose count is ignored (training + held_out are generated)
  PcaOptions pca = [] {
    PcaOptions o;
    o.variance_fraction = kPosesDefaultVariance;
    return o;
  }();
  KeyPointOptions key_points;
  CertificateParameters certificates = [] {
    CertificateParameters o;
    o.global_radius_scale = kPosesDefaultGlobalScale;
    return o;
  }();
};

/// Prints the summary; returns the number of false culls of the sound certificates (0 when
/// all is well; the experimental predictor's do not count as problems, they are its result).
long run_poses(const PosesCommandOptions& options, std::ostream& out, std::ostream& progress);

}  // namespace sscc::validation
