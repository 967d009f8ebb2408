// The example pose files of `sscc basis --method pca --poses LIST`: each item of the list is
// a mesh file or a directory, which stands for the mesh files in it (extensions .off, .obj,
// .ply in any case), sorted by name so that the pose order (and with it the basis) does not
// depend on the directory's listing order.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "sscc/basis/example_poses.hpp"

namespace sscc::validation {

/// The files the items stand for. Throws std::invalid_argument for a directory without mesh
/// files.
std::vector<std::string> example_pose_files(const std::vector<std::string>& items);

/// Reads the poses the items stand for and builds their PCA, reporting on `progress`.
PoseSubspace pose_subspace_from_files(const TriangleMesh& reference, const std::vector<std::string>& items,
                                      const PcaOptions& options, std::ostream& progress);

}  // namespace sscc::validation
