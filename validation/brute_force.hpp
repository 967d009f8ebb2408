// The plainest self-collision reference: all 15 vertex-face and edge-edge features of a
// triangle pair through the kernels, nothing culled, nothing shared with the library's
// traversal (feature ownership, boxes, frames).
#pragma once

#include <Eigen/Core>

#include <vector>

#include "sscc/ccd/ccd_types.hpp"
#include "sscc/mesh/triangle_mesh.hpp"

namespace sscc::validation {

/// Earliest time of impact of any feature of triangles a and b between positions x0 and
/// x1, or 2 when none touches (comes within options.minimum_separation).
double triangle_pair_first_contact(const std::vector<Eigen::Vector3d>& x0, const std::vector<Eigen::Vector3d>& x1,
                                   const Triangle& a, const Triangle& b, const ccd::CcdOptions& options = {});

}  // namespace sscc::validation
