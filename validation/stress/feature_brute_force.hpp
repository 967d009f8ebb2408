// The plainest self-collision report there is: every non-adjacent triangle pair (no shared
// vertex index, decided here, not by the mesh), all 15 of its vertex-face and edge-edge
// features through the kernels, nothing culled and no feature ownership, the features
// collected per feature and the pairs per pair. O(N^2) kernel calls: the reference the
// stress suite holds the library's queries to on small meshes.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "sscc/ccd/ccd_types.hpp"
#include "sscc/mesh/triangle_mesh.hpp"
#include "sscc/query/self_ccd.hpp"

namespace sscc::validation {

/// The report of a step in which every vertex moves linearly from x0 to x1: pairs sorted by
/// (first, second) at the earliest time of their features, features sorted by (kind,
/// first, second), earliest_toi the earliest of all. Statistics hold the kernel calls only.
SelfCcdReport feature_brute_force(const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& x0,
                                  const std::vector<Eigen::Vector3d>& x1, const ccd::CcdOptions& kernel = {});

/// "" when the two reports have the same pairs and features (times included, bit for bit)
/// and the same earliest time, else what differs first.
std::string report_difference(const SelfCcdReport& expected, const SelfCcdReport& actual);

}  // namespace sscc::validation
