// Settles disagreements between FCL's pair sets and ours with the exact kernels: each pair
// only one side reports is decided on all 15 of its features (brute_force.hpp).
#pragma once

#include <Eigen/Core>

#include <utility>
#include <vector>

#include "sscc/mesh/triangle_mesh.hpp"

namespace sscc::validation {

using PairList = std::vector<std::pair<int, int>>;  ///< sorted (first < second)

struct SettledDisagreements {
  long fcl_false_positives = 0;  ///< FCL reports them, they do not touch
  long fcl_false_negatives = 0;  ///< FCL misses them, they touch
  long unexplained = 0;          ///< decided against us: a bug of ours
  SettledDisagreements& operator+=(const SettledDisagreements& o) {
    fcl_false_positives += o.fcl_false_positives;
    fcl_false_negatives += o.fcl_false_negatives;
    unexplained += o.unexplained;
    return *this;
  }
};

SettledDisagreements settle_with_exact_kernels(const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& x0,
                                               const std::vector<Eigen::Vector3d>& x1, const PairList& fcl,
                                               const PairList& ours);

}  // namespace sscc::validation
