// The precomputation's level loop (precompute.cpp), run by Certificates::precompute on every
// node and, split by subtrees, by the shards and their merge (precompute_shards.cpp).
//
// Each level's work items (a leaf's own triangle pairs; a sibling pair of an inner node,
// resolved up to a reach set by the children's radii) depend only on the results of the level
// below, and only through the node's own children: the items under one subtree need nothing
// from another. Each item runs on one thread from the same starting values, and a node's
// results are minima of its items' (exact, in any order), so the results do not depend on the
// threads, the order of the items, or which nodes one run computes.
#pragma once

#include <array>
#include <vector>

#include "sscc/certificates/certificates.hpp"

namespace sscc::detail {

/// What the levels compute and pass up: the certificates and, per node, the smallest contact
/// configuration found under it (its parent's running minimum starts from its children's;
/// not in the certificate file).
struct PrecomputeState {
  Certificates certificates;
  std::vector<double> contact;
  /// Per node a and position of sibling b > a: the pair certificates below (a, b), until
  /// finish() lays them out in the certificates.
  std::vector<std::array<std::vector<PairCertificate>, kBranchingFactor>> trees;
};

struct PrecomputeDriver {
  /// Every radius 0, every contact R_global, for the hierarchy and parameters. Throws
  /// std::invalid_argument for parameters out of range or a basis outside the range
  /// certificates hold for.
  static PrecomputeState start(const SubspaceBvh& bvh, const CertificateParameters& parameters);
  /// Computes node n's results for every n with selected[n], level by level, deepest first;
  /// every child of a selected node must be selected or computed already. Adds to the
  /// certificates' statistics.
  static void run(const SubspaceBvh& bvh, const std::vector<char>& selected, PrecomputeState& state,
                  const PrecomputeProgress& progress);
  /// Copies node n's results (its radius, and the sibling radii and pair certificates of its
  /// children: what its work items compute) from `from` to `to`, both of bvh. Its contact
  /// configuration is the state's, not the certificates'.
  static void copy_node(const SubspaceBvh& bvh, int n, const Certificates& from, PrecomputeState& to);
  /// Lays out the pair certificates, sets the statistics' thread count and time (seconds
  /// since `start`).
  static void finish(PrecomputeState& state, double seconds);
};

}  // namespace sscc::detail
