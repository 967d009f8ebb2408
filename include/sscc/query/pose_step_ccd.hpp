// Self-CCD of a step between two full poses (vertex positions) of a PCA model, for poses
// that need not lie in its subspace (recorded or simulated poses, key-point-driven ones).
//
// Both poses are projected onto the subspace, q = U^T (x - m) (example_poses.hpp). When both
// projections reproduce their pose to within the tolerance (the largest vertex distance
// ||x_v - m_v - U_v q||, mesh units), the step is the subspace step q0 -> q1 and the
// certified query runs (SelfCcd::query). Otherwise the certificates do not apply (they
// speak of the positions m + U q, and a pose off the subspace can touch where its
// projection does not), so the traditional query runs on the given positions
// (SelfCcd::query_positions), and the report says that it fell back. Either way the report
// carries both residuals.
//
// Guarantee: a fallback report is the traditional query's on the given positions (exact, see
// self_ccd.hpp). A certified report is exact for the projected positions m + U q, which lie
// within the tolerance of the given ones: a contact that exists only through a deviation
// that small is outside the guarantee, as the rounding of positions already is
// (certificates.hpp). Raising the tolerance widens that gap; it is a trade of soundness for
// speed that the caller makes knowingly.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "sscc/basis/example_poses.hpp"
#include "sscc/query/self_ccd.hpp"

namespace sscc {

/// Default tolerance of the largest vertex residual, in diagonals of the mean shape's
/// bounding box. A pose computed as m + U q comes back from the projection with a residual
/// of rounding only: at worst about 3V machine epsilons of the coordinates' size (2e-12 of
/// it for 3V = 10^4; typically far less, growing like sqrt(3V)), so for a mesh within a few
/// diagonals of the origin 1e-10 accepts such poses up to some 10^5 vertices even in the
/// worst case. Anything farther is treated as off the subspace. Larger values accept poses
/// whose contacts the certificates do not cover (see above); smaller ones send rounded
/// in-subspace poses to the slow query.
inline constexpr double kSubspaceResidualFraction = 1e-10;

struct PoseStepOptions {
  SelfCcdOptions ccd;
  /// Fall back when either pose's largest vertex residual exceeds this fraction of the
  /// mean shape's bounding-box diagonal (>= 0).
  double residual_fraction = kSubspaceResidualFraction;
};

struct PoseStepReport {
  SelfCcdReport ccd;
  Eigen::VectorXd q0, q1;      ///< the projections
  SubspaceResidual residual0;  ///< of x0 from m + U q0
  SubspaceResidual residual1;
  double tolerance = 0.0;  ///< the largest vertex residual accepted (mesh units)
  /// True: a residual exceeded the tolerance and ccd is query_positions(x0, x1); false: ccd
  /// is query(q0, q1), with the certificates when there are any.
  bool fell_back = false;
};

/// The model a PoseStepCcd is built on must be the subspace's: its rest positions the mean
/// and its basis U up to the rounding of the weight scaling, entry by entry within this
/// (U's entries are at most 1 in magnitude, and the scaling rounds each by a few units of
/// 1e-16). Larger would accept a slightly different basis, whose certificates are not U's.
inline constexpr double kModelBasisMatchTolerance = 1e-12;

class PoseStepCcd {
 public:
  /// `bvh` must be built on subspace.model() (or a model with the same rest positions and
  /// basis); throws std::invalid_argument otherwise, or when the certificates belong to
  /// another hierarchy. Holds a copy of the subspace and a detector owning the hierarchy and
  /// certificates, so none of the arguments needs to outlive it.
  PoseStepCcd(const PoseSubspace& subspace, const SubspaceBvh& bvh, const Certificates* certificates = nullptr);

  const SelfCcd& ccd() const { return ccd_; }

  /// Throws std::invalid_argument for wrong vertex counts, NaN/infinity or a bad tolerance.
  PoseStepReport query(const std::vector<Eigen::Vector3d>& x0, const std::vector<Eigen::Vector3d>& x1,
                       const PoseStepOptions& options = {}) const;

 private:
  PoseSubspace subspace_;
  SelfCcd ccd_;
};

}  // namespace sscc
