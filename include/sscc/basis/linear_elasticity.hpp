// Linear elasticity on linear tetrahedra: the stiffness matrix K and the lumped mass matrix
// of a volume mesh, in SI units when the mesh is in metres (K in N/m, mass in kg).
// Degree of freedom 3n + k is node n's coordinate k.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "sscc/basis/volume_mesh.hpp"

namespace sscc {

struct ElasticMaterial {
  double youngs_modulus = 1.0e6;  ///< Pa (soft rubber)
  /// Linear tetrahedra lock (grow too stiff) as this nears 0.5; 0.4 stays clear of that.
  double poisson_ratio = 0.4;
  double density = 1100.0;  ///< kg/m^3

  /// Throws std::invalid_argument naming the bad parameter.
  void validate() const;
};

/// Symmetric positive semi-definite, 3N x 3N (both triangles stored). Throws
/// std::invalid_argument for a tetrahedron of non-positive volume.
Eigen::SparseMatrix<double> stiffness_matrix(const VolumeMesh& volume, const ElasticMaterial& material);
/// The diagonal of the lumped mass matrix (a quarter of each tetrahedron's mass to each of
/// its nodes), 3N entries.
Eigen::VectorXd lumped_mass(const VolumeMesh& volume, const ElasticMaterial& material);

}  // namespace sscc
