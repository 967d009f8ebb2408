// A volumetric (tetrahedral) discretisation of a surface mesh, for elasticity.
//
// Two ways, chosen per mesh:
//  - TetGen (constrained Delaunay with quality refinement) for closed manifold surfaces;
//    the surface vertices are the first nodes, so they move exactly with the volume.
//  - A voxel grid for everything TetGen cannot take (open, non-manifold or
//    self-intersecting scans): the cells the surface passes through plus the cells it
//    encloses, each split into six tetrahedra; every surface vertex is embedded in its cell
//    by trilinear interpolation of the cell's eight corners.
// Either way `embedding` maps node displacements to surface-vertex displacements
// (per coordinate: u_surface = embedding * u_nodes).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <array>
#include <string>
#include <vector>

#include "sscc/mesh/triangle_mesh.hpp"

namespace sscc {

using Tetrahedron = std::array<int, 4>;  ///< node indices, positively oriented

struct VolumeMesh {
  std::vector<Eigen::Vector3d> nodes;
  std::vector<Tetrahedron> tetrahedra;
  Eigen::SparseMatrix<double, Eigen::RowMajor> embedding;  ///< surface vertices x nodes
  std::string method;                                      ///< "tetgen" or "voxel"
  std::string note;                                        ///< why the method was chosen (e.g. TetGen's refusal)
};

/// The signed volume of tetrahedron t (positive when oriented).
double signed_volume(const std::vector<Eigen::Vector3d>& nodes, const Tetrahedron& t);
/// t with its last two nodes swapped when its volume is negative.
Tetrahedron positively_oriented(const std::vector<Eigen::Vector3d>& nodes, Tetrahedron t);

enum class VolumeMethod { automatic, tetgen, voxel };

/// Parses "auto", "tetgen" or "voxel"; throws std::invalid_argument otherwise.
VolumeMethod parse_volume_method(const std::string& name);

struct VolumeMeshOptions {
  VolumeMethod method = VolumeMethod::automatic;
  /// Voxel grid: cells along the bounding box's longest side. 40 keeps the lowest modes of
  /// the shipped meshes within a few percent of a finer grid at a few seconds of solve time;
  /// halving it makes thin parts (ears, tails) stiffer than they are.
  int voxel_resolution = 40;
  /// TetGen's radius-edge quality bound (its -q switch); below ~1.2 TetGen may not finish.
  double tetgen_quality = 1.414;
  /// TetGen: the largest tetrahedron volume (its -a switch), in the mesh's units cubed; 0
  /// leaves the size to the quality bound alone. Smaller values refine the interior:
  /// linear tetrahedra are too stiff in bending until several span a thin part.
  double tetgen_max_volume = 0.0;
};

/// Whether every edge of the mesh has exactly two triangles, consistently oriented
/// (a closed, oriented 2-manifold: what TetGen needs to see an inside).
bool is_closed_manifold(const TriangleMesh& mesh);

/// TetGen: throws std::runtime_error with TetGen's complaint when it refuses the surface.
VolumeMesh tetrahedralize_surface(const TriangleMesh& mesh, double quality, double max_volume = 0.0);
/// Voxel grid with `resolution` cells along the longest side (at least 2).
VolumeMesh voxelize_surface(const TriangleMesh& mesh, int resolution);
/// automatic: TetGen when the surface is a closed manifold and TetGen accepts it, else voxels.
VolumeMesh volume_mesh(const TriangleMesh& mesh, const VolumeMeshOptions& options = {});

/// Surface displacements (3V x m) of node displacement fields (3N x m) through the embedding.
Eigen::MatrixXd embed_in_surface(const VolumeMesh& volume, const Eigen::MatrixXd& node_fields);
/// Number of node-connected pieces of the tetrahedra (each has six rigid motions).
int connected_pieces(const VolumeMesh& volume);

}  // namespace sscc
