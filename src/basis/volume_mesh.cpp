#include "sscc/basis/volume_mesh.hpp"

#include <Eigen/Geometry>

#include <map>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace sscc {

double signed_volume(const std::vector<Eigen::Vector3d>& nodes, const Tetrahedron& t) {
  return (nodes[t[1]] - nodes[t[0]]).dot((nodes[t[2]] - nodes[t[0]]).cross(nodes[t[3]] - nodes[t[0]])) / 6.0;
}

Tetrahedron positively_oriented(const std::vector<Eigen::Vector3d>& nodes, Tetrahedron t) {
  if (signed_volume(nodes, t) < 0.0) std::swap(t[2], t[3]);
  return t;
}

VolumeMethod parse_volume_method(const std::string& name) {
  if (name == "auto") return VolumeMethod::automatic;
  if (name == "tetgen") return VolumeMethod::tetgen;
  if (name == "voxel") return VolumeMethod::voxel;
  throw std::invalid_argument("volume method '" + name + "': expected auto, tetgen or voxel");
}

bool is_closed_manifold(const TriangleMesh& mesh) {
  if (mesh.triangle_count() == 0) return false;
  // Each directed edge exactly once, and its reverse present.
  std::map<std::pair<int, int>, int> directed;
  for (const Triangle& t : mesh.triangles()) {
    for (int k = 0; k < 3; ++k) {
      if (++directed[{t[k], t[(k + 1) % 3]}] > 1) return false;
    }
  }
  for (const auto& entry : directed) {
    if (directed.count({entry.first.second, entry.first.first}) == 0) return false;
  }
  return true;
}

VolumeMesh volume_mesh(const TriangleMesh& mesh, const VolumeMeshOptions& options) {
  switch (options.method) {
    case VolumeMethod::tetgen:
      return tetrahedralize_surface(mesh, options.tetgen_quality, options.tetgen_max_volume);
    case VolumeMethod::voxel:
      return voxelize_surface(mesh, options.voxel_resolution);
    case VolumeMethod::automatic:
      break;
  }
  if (!is_closed_manifold(mesh)) {
    VolumeMesh voxels = voxelize_surface(mesh, options.voxel_resolution);
    voxels.note = "the surface is not a closed oriented manifold";
    return voxels;
  }
  try {
    return tetrahedralize_surface(mesh, options.tetgen_quality, options.tetgen_max_volume);
  } catch (const std::runtime_error& refusal) {
    VolumeMesh voxels = voxelize_surface(mesh, options.voxel_resolution);
    voxels.note = refusal.what();
    return voxels;
  }
}

Eigen::MatrixXd embed_in_surface(const VolumeMesh& volume, const Eigen::MatrixXd& node_fields) {
  using NodeRows = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
  const Eigen::Index nodes = static_cast<Eigen::Index>(volume.nodes.size());
  if (node_fields.rows() != 3 * nodes) throw std::invalid_argument("embed_in_surface: fields are not 3N rows");
  const Eigen::Index vertices = volume.embedding.rows();
  Eigen::MatrixXd surface(3 * vertices, node_fields.cols());
  for (Eigen::Index m = 0; m < node_fields.cols(); ++m) {
    const NodeRows field = Eigen::Map<const NodeRows>(node_fields.col(m).data(), nodes, 3);
    Eigen::Map<NodeRows>(surface.col(m).data(), vertices, 3) = volume.embedding * field;
  }
  return surface;
}

int connected_pieces(const VolumeMesh& volume) {
  std::vector<int> parent(volume.nodes.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int n) {
    while (parent[n] != n) n = parent[n] = parent[parent[n]];
    return n;
  };
  std::vector<char> used(volume.nodes.size(), 0);
  for (const Tetrahedron& t : volume.tetrahedra) {
    for (int k = 0; k < 4; ++k) {
      used[t[k]] = 1;
      parent[root(t[k])] = root(t[0]);
    }
  }
  int pieces = 0;
  for (int n = 0; n < static_cast<int>(parent.size()); ++n) pieces += used[n] && root(n) == n;
  return pieces;
}

}  // namespace sscc
