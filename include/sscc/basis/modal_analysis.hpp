// Bases from linear elasticity: vibration modes (linear modal analysis) and stiffness-scaled
// polynomial modes (SSCC paper section 6), each with the weights that make ||q||_M^2 the
// strain energy of the displacement U q (joules for a mesh in metres).
//
// Modal analysis solves K phi = lambda M phi (K stiffness, M lumped mass) for the lowest
// modes by shift-invert Lanczos (Spectra) around a small negative shift, factoring
// K - sigma M once (sparse Cholesky); the rigid motions (six per connected piece, plus any
// zero-energy hinge of a voxel grid) are detected by their zero eigenvalue and dropped.
// Modes are mass-normalised (phi^T M phi = 1), so q is the modal coordinate, and weighted
// by omega^2 / 2 = lambda / 2.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <ostream>
#include <string>

#include "sscc/basis/linear_elasticity.hpp"
#include "sscc/basis/volume_mesh.hpp"
#include "sscc/mesh/triangle_mesh.hpp"

namespace sscc {

/// An eigenvalue below this fraction of the mean diagonal of M^-1 K is a zero-energy
/// motion. Elastic eigenvalues of the meshes here sit above 1e-7 of it; rigid ones come out
/// of the solver below 1e-12. Raising it towards the elastic range would drop real modes.
inline constexpr double kZeroEnergyFraction = 1e-9;
/// The shift sigma = -kModalShiftFraction * (mean diagonal of M^-1 K): negative so that
/// K - sigma M is positive definite despite the rigid motions, small so that the lowest
/// modes converge first.
inline constexpr double kModalShiftFraction = 1e-6;

struct ElasticBasisOptions {
  ElasticMaterial material;
  VolumeMeshOptions volume;
  int modes = 30;  ///< elastic modes wanted (modal), or polynomial modes to scale (<= 27)
  /// Stiffness-scaled weights: lambda -> (1/lambda + 1/(l lambda_min))^-1, l = this.
  double weight_filter_ratio = 100.0;
};

struct ElasticBasis {
  Eigen::MatrixXd basis;           ///< 3V x r surface displacements
  Eigen::VectorXd weights;         ///< r, ||q||_M^2 = sum weights_i q_i^2
  Eigen::VectorXd frequencies_hz;  ///< r, sqrt(lambda_i) / (2 pi)
  int zero_energy_modes = 0;       ///< dropped (rigid motions, hinges, polynomial rotations)
  std::string volume_method;       ///< "tetgen" or "voxel"
  std::string volume_note;         ///< why voxels were used, when they were
  int volume_nodes = 0;
  int tetrahedra = 0;
};

/// The lowest `count` non-zero modes of K phi = lambda M phi with M = diag(mass):
/// eigenvalues ascending, vectors mass-normalised, each with its largest entry positive.
struct VibrationModes {
  Eigen::VectorXd eigenvalues;
  Eigen::MatrixXd vectors;
  int zero_energy_modes = 0;
};
VibrationModes lowest_vibration_modes(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
                                      int count, int expected_zero_modes);

/// Linear modal analysis of the solid the surface bounds. Throws std::invalid_argument for
/// bad options, std::runtime_error when the eigensolver does not converge.
ElasticBasis modal_basis(const TriangleMesh& mesh, const ElasticBasisOptions& options,
                         std::ostream* progress = nullptr);

/// The first options.modes polynomial modes, evaluated in the volume, diagonalised against
/// the reduced stiffness and mass (U' = U Q, SSCC paper section 6). The six rigid motions
/// join the span before the reduced problem is solved, so every kept mode is
/// mass-orthogonal to them (its frequency is then a Rayleigh-Ritz bound from above on a
/// true one, and no mode carries a rigid part); the zero-energy combinations (the rigid
/// motions, the polynomials' linearised rotations among them) are dropped: 27 polynomial
/// modes give 24. Weights (1/lambda + 1/(l lambda_min))^-1 / 2 with l =
/// options.weight_filter_ratio.
ElasticBasis stiffness_scaled_polynomial_basis(const TriangleMesh& mesh, const ElasticBasisOptions& options,
                                               std::ostream* progress = nullptr);

/// Any surface basis (3V x r, e.g. read from a file), stiffness-scaled the same way. The
/// volume sees each mode through its least-strain-energy extension (the interior
/// displacement that matches the mode at the surface with the least energy), so the
/// weights are the energies of the surface motion. options.modes is ignored.
ElasticBasis stiffness_scaled_basis(const TriangleMesh& mesh, const Eigen::MatrixXd& surface_basis,
                                    const ElasticBasisOptions& options, std::ostream* progress = nullptr);

}  // namespace sscc
