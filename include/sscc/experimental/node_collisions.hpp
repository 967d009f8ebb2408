// Ground truth per hierarchy node: in which nodes of a SubspaceBvh do two non-adjacent
// triangles intersect in a given configuration? The exact discrete test (SelfCcd::
// query_discrete, certificates off, every pair reported) finds the intersecting pairs; a
// pair marks every node that holds both of its triangles (the pair's lowest common ancestor
// and the nodes above it). This is what a node certificate claims cannot happen, so it is
// the reference both the sound certificates and the experimental predictor are held to.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "sscc/bvh/subspace_bvh.hpp"
#include "sscc/query/self_ccd.hpp"

namespace sscc::experimental {

/// Per node (bvh.nodes() order): 1 when some reported pair has both triangles under it.
std::vector<char> nodes_holding_pairs(const SubspaceBvh& bvh, const std::vector<TrianglePairContact>& pairs);

/// nodes_holding_pairs of the exact discrete test at reduced coordinates q (not scaled).
/// Throws std::invalid_argument for a q of the wrong size or with NaN/infinity.
std::vector<char> colliding_nodes(const SubspaceBvh& bvh, const Eigen::VectorXd& q);

}  // namespace sscc::experimental
