// Holding culling decisions to the exact ground truth on held-out poses: how often would a
// node have been declared collision free where the exact discrete test finds two of its
// non-adjacent triangles intersecting (a false cull)? Counted side by side for the sound
// node certificates (node n culled when ||q||_M < R_n, certificates.hpp; they must have no
// false culls at all) and for the EXPERIMENTAL, NOT CONSERVATIVE regression predictor
// (culling_predictor.hpp). Nodes are counted independently (as if each were reached); the
// sibling radii R_ab are not part of the comparison (the predictor has no counterpart).
#pragma once

#include <Eigen/Core>

#include <vector>

#include "sscc/certificates/certificates.hpp"
#include "sscc/experimental/culling_predictor.hpp"

namespace sscc::experimental {

struct CullCounts {
  long culled = 0;              ///< (pose, node) pairs declared free
  long false_culls = 0;         ///< of those, pairs where the exact test finds a collision
  int poses_declared_free = 0;  ///< poses whose root was declared free
  int poses_falsely_free = 0;   ///< of those, poses with a collision
};

struct CullValidation {
  int poses = 0;
  int nodes = 0;            ///< per pose
  long colliding = 0;       ///< (pose, node) pairs with a collision under the node
  int colliding_poses = 0;  ///< poses with a collision anywhere
  CullCounts sound;         ///< the certificates
  CullCounts predicted;     ///< EXPERIMENTAL, NOT CONSERVATIVE: the regression
};

/// For each pose (reduced coordinates q, not scaled) with its ground truth (colliding_nodes,
/// one flag per node), the culls of both. Throws std::invalid_argument when the sizes do not
/// match or the certificates are not the hierarchy's.
CullValidation validate_culling(const SubspaceBvh& bvh, const Certificates& certificates,
                                const CullingPredictor& predictor, const std::vector<Eigen::VectorXd>& q,
                                const std::vector<std::vector<char>>& collisions);

}  // namespace sscc::experimental
