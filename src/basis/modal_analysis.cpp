#include "sscc/basis/modal_analysis.hpp"

#include <Spectra/SymEigsShiftSolver.h>
#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/sign_convention.hpp"
#include "sscc/common/timing.hpp"
#include "sscc/model/polynomial_basis.hpp"

namespace sscc {

namespace {

/// y = (D^-1/2 K D^-1/2 - sigma I)^-1 x = D^1/2 (K - sigma D)^-1 D^1/2 x, the operator of
/// shift-invert Lanczos on the mass-scaled standard problem.
class ScaledShiftInvert {
 public:
  using Scalar = double;

  ScaledShiftInvert(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass)
      : stiffness_(stiffness), mass_(mass), sqrt_mass_(mass.cwiseSqrt()) {}

  Eigen::Index rows() const { return stiffness_.rows(); }
  Eigen::Index cols() const { return stiffness_.cols(); }

  void set_shift(double sigma) {
    Eigen::SparseMatrix<double> shifted = stiffness_;
    for (Eigen::Index i = 0; i < shifted.rows(); ++i) shifted.coeffRef(i, i) -= sigma * mass_[i];
    factor_.compute(shifted);
    if (factor_.info() != Eigen::Success) {
      throw std::runtime_error("modal analysis: K - sigma M is not positive definite (is the stiffness valid?)");
    }
  }

  void perform_op(const double* x_in, double* y_out) const {
    const Eigen::Map<const Eigen::VectorXd> x(x_in, rows());
    Eigen::Map<Eigen::VectorXd>(y_out, rows()) = sqrt_mass_.cwiseProduct(factor_.solve(sqrt_mass_.cwiseProduct(x)));
  }

 private:
  const Eigen::SparseMatrix<double>& stiffness_;
  const Eigen::VectorXd& mass_;
  Eigen::VectorXd sqrt_mass_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor_;
};

struct ElasticSystem {
  VolumeMesh volume;
  Eigen::SparseMatrix<double> stiffness;
  Eigen::VectorXd mass;
};

ElasticSystem elastic_system(const TriangleMesh& mesh, const ElasticBasisOptions& options, std::ostream* progress) {
  options.material.validate();
  const auto start = std::chrono::steady_clock::now();
  ElasticSystem system;
  system.volume = volume_mesh(mesh, options.volume);
  system.stiffness = stiffness_matrix(system.volume, options.material);
  system.mass = lumped_mass(system.volume, options.material);
  for (Eigen::Index i = 0; i < system.mass.size(); ++i) {
    if (!(system.mass[i] > 0.0)) {
      throw std::invalid_argument("volume node " + std::to_string(i / 3) + " belongs to no tetrahedron");
    }
  }
  if (progress) {
    *progress << "volume: " << system.volume.method << ", " << system.volume.nodes.size() << " nodes, "
              << system.volume.tetrahedra.size() << " tetrahedra"
              << (system.volume.note.empty() ? "" : " (" + system.volume.note + ")") << ", " << seconds_since(start)
              << " s\n";
  }
  return system;
}

ElasticBasis describe(const ElasticSystem& system) {
  ElasticBasis result;
  result.volume_method = system.volume.method;
  result.volume_note = system.volume.note;
  result.volume_nodes = static_cast<int>(system.volume.nodes.size());
  result.tetrahedra = static_cast<int>(system.volume.tetrahedra.size());
  return result;
}

Eigen::VectorXd frequencies_of(const Eigen::VectorXd& eigenvalues) {
  return eigenvalues.cwiseMax(0.0).cwiseSqrt() / (2.0 * M_PI);
}

}  // namespace

VibrationModes lowest_vibration_modes(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& mass,
                                      int count, int expected_zero_modes) {
  const Eigen::Index n = stiffness.rows();
  if (count < 1 || stiffness.cols() != n || mass.size() != n) {
    throw std::invalid_argument("lowest_vibration_modes: sizes do not match or no modes requested");
  }
  const double scale = (stiffness.diagonal().array() / mass.array()).mean();
  const double zero_threshold = kZeroEnergyFraction * scale;
  ScaledShiftInvert op(stiffness, mass);
  int zero = std::max(0, expected_zero_modes);
  for (int attempt = 0; attempt < 4; ++attempt) {
    const Eigen::Index nev = count + zero;
    if (nev >= n) throw std::invalid_argument("lowest_vibration_modes: more modes requested than degrees of freedom");
    const Eigen::Index ncv = std::min<Eigen::Index>(n, std::max<Eigen::Index>(2 * nev + 1, 20));
    Spectra::SymEigsShiftSolver<ScaledShiftInvert> solver(op, nev, ncv, -kModalShiftFraction * scale);
    solver.init();
    solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-10);
    if (solver.info() != Spectra::CompInfo::Successful) {
      throw std::runtime_error("modal analysis: the eigensolver did not converge for " + std::to_string(nev) +
                               " modes");
    }
    std::vector<Eigen::Index> order(static_cast<std::size_t>(nev));
    std::iota(order.begin(), order.end(), 0);
    const Eigen::VectorXd unsorted = solver.eigenvalues();
    std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return unsorted[a] < unsorted[b]; });
    const Eigen::MatrixXd unsorted_vectors = solver.eigenvectors();
    Eigen::VectorXd values(nev);
    Eigen::MatrixXd vectors(n, nev);
    for (Eigen::Index k = 0; k < nev; ++k) {
      values[k] = unsorted[order[k]];
      vectors.col(k) = unsorted_vectors.col(order[k]);
    }
    const int found_zero = static_cast<int>((values.array() < zero_threshold).count());
    if (found_zero > zero) {  // hinges or pieces beyond the expected: ask for more modes
      zero = found_zero + 6;
      continue;
    }
    VibrationModes modes;
    modes.zero_energy_modes = found_zero;
    modes.eigenvalues = values.segment(found_zero, count);
    modes.vectors = mass.cwiseSqrt().cwiseInverse().asDiagonal() * vectors.middleCols(found_zero, count);
    make_largest_entries_positive(modes.vectors);
    return modes;
  }
  throw std::runtime_error("modal analysis: too many zero-energy modes (a mesh in many loose pieces?)");
}

ElasticBasis modal_basis(const TriangleMesh& mesh, const ElasticBasisOptions& options, std::ostream* progress) {
  if (options.modes < 1) throw std::invalid_argument("modal_basis: at least one mode is needed");
  const ElasticSystem system = elastic_system(mesh, options, progress);
  const auto start = std::chrono::steady_clock::now();
  const VibrationModes modes =
      lowest_vibration_modes(system.stiffness, system.mass, options.modes, 6 * connected_pieces(system.volume));
  if (progress) *progress << "eigensolver: " << options.modes << " modes, " << seconds_since(start) << " s\n";
  ElasticBasis result = describe(system);
  result.basis = embed_in_surface(system.volume, modes.vectors);
  result.weights = 0.5 * modes.eigenvalues;
  result.frequencies_hz = frequencies_of(modes.eigenvalues);
  result.zero_energy_modes = modes.zero_energy_modes;
  return result;
}

namespace {

/// The surface basis' extension into the volume with the least strain energy: for each
/// column u, argmin n^T K n subject to embedding(n) = u, from the saddle-point system
/// [K E^T; E 0] [n; mu] = [0; u] (E: the embedding, per coordinate), factored once.
Eigen::MatrixXd least_energy_extension(const ElasticSystem& system, const Eigen::MatrixXd& surface_basis) {
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& embedding = system.volume.embedding;
  const Eigen::Index dofs = system.stiffness.rows();
  const Eigen::Index constraints = 3 * embedding.rows();
  if (surface_basis.rows() != constraints) {
    throw std::invalid_argument("stiffness scaling: the basis has " + std::to_string(surface_basis.rows()) +
                                " rows; the mesh needs " + std::to_string(constraints));
  }
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(system.stiffness.nonZeros() + 6 * 3 * embedding.nonZeros()));
  for (Eigen::Index c = 0; c < system.stiffness.outerSize(); ++c) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(system.stiffness, c); it; ++it) {
      entries.emplace_back(it.row(), it.col(), it.value());
    }
  }
  for (Eigen::Index v = 0; v < embedding.outerSize(); ++v) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(embedding, v); it; ++it) {
      for (Eigen::Index k = 0; k < 3; ++k) {
        entries.emplace_back(dofs + 3 * v + k, 3 * it.col() + k, it.value());
        entries.emplace_back(3 * it.col() + k, dofs + 3 * v + k, it.value());
      }
    }
  }
  Eigen::SparseMatrix<double> saddle(dofs + constraints, dofs + constraints);
  saddle.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> factor;
  factor.compute(saddle);
  if (factor.info() != Eigen::Success) {
    throw std::runtime_error("stiffness scaling: the surface does not determine the volume's motion");
  }
  Eigen::MatrixXd right = Eigen::MatrixXd::Zero(dofs + constraints, surface_basis.cols());
  right.bottomRows(constraints) = surface_basis;
  const Eigen::MatrixXd solution = factor.solve(right);
  return solution.topRows(dofs);
}

/// The six rigid motions of the volume's nodes (translations, linearised rotations about
/// the centroid), 3N x 6.
Eigen::MatrixXd rigid_motions(const VolumeMesh& volume) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : volume.nodes) centroid += p / static_cast<double>(volume.nodes.size());
  Eigen::MatrixXd rigid = Eigen::MatrixXd::Zero(3 * static_cast<Eigen::Index>(volume.nodes.size()), 6);
  for (std::size_t n = 0; n < volume.nodes.size(); ++n) {
    const Eigen::Vector3d x = volume.nodes[n] - centroid;
    const Eigen::Index row = 3 * static_cast<Eigen::Index>(n);
    for (int k = 0; k < 3; ++k) {
      rigid(row + k, k) = 1.0;
      // e_k x x
      rigid.block<3, 1>(row, 3 + k) = Eigen::Vector3d::Unit(k).cross(x);
    }
  }
  return rigid;
}

/// A mass-orthonormal basis of span(columns): modified Gram-Schmidt in the M inner product,
/// twice (so that orthogonality holds to round-off); a column that keeps less than
/// kDependentFraction of its norm after projection lies in the span of those before it and
/// is dropped.
Eigen::MatrixXd mass_orthonormal(const Eigen::MatrixXd& columns, const Eigen::VectorXd& mass) {
  constexpr double kDependentFraction = 1e-8;
  Eigen::MatrixXd basis(columns.rows(), columns.cols());
  Eigen::Index kept = 0;
  for (Eigen::Index c = 0; c < columns.cols(); ++c) {
    Eigen::VectorXd v = columns.col(c);
    const double original = std::sqrt(v.dot(mass.cwiseProduct(v)));
    if (!(original > 0.0)) continue;
    for (int pass = 0; pass < 2; ++pass) {
      for (Eigen::Index j = 0; j < kept; ++j) v -= basis.col(j).dot(mass.cwiseProduct(v)) * basis.col(j);
    }
    const double remaining = std::sqrt(v.dot(mass.cwiseProduct(v)));
    if (remaining <= kDependentFraction * original) continue;
    basis.col(kept++) = v / remaining;
  }
  return basis.leftCols(kept);
}

/// U' = U Q from the reduced problem (U^T K U) Q = (U^T M U) Q Lambda. The rigid motions
/// join the span first, so that every kept mode is mass-orthogonal to them: the Ritz
/// values are then bounds from above on the true frequencies, and no mode carries a
/// rigid part that would lower its weight. Zero-energy combinations (the rigid motions,
/// and the linearised rotations the polynomial modes contain) are dropped; weights
/// (1/lambda + 1/(l lambda_min))^-1 / 2.
ElasticBasis stiffness_scale(const ElasticSystem& system, const Eigen::MatrixXd& node_basis,
                             const ElasticBasisOptions& options) {
  Eigen::MatrixXd columns(node_basis.rows(), 6 + node_basis.cols());
  columns << rigid_motions(system.volume), node_basis;
  const Eigen::MatrixXd orthonormal = mass_orthonormal(columns, system.mass);
  const Eigen::MatrixXd reduced_stiffness = orthonormal.transpose() * (system.stiffness * orthonormal);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(0.5 * (reduced_stiffness + reduced_stiffness.transpose()));
  if (solver.info() != Eigen::Success) throw std::runtime_error("stiffness scaling: the reduced eigensolver failed");
  const Eigen::VectorXd& lambda = solver.eigenvalues();  // ascending
  const double zero_threshold =
      kZeroEnergyFraction * (system.stiffness.diagonal().array() / system.mass.array()).mean();
  int zero = 0;
  while (zero < lambda.size() && lambda[zero] < zero_threshold) ++zero;
  const int kept = static_cast<int>(lambda.size()) - zero;
  if (kept == 0) throw std::runtime_error("stiffness scaling: every mode has zero strain energy");
  const Eigen::VectorXd elastic = lambda.tail(kept);
  const double cap = options.weight_filter_ratio * elastic[0];
  Eigen::MatrixXd rotated = orthonormal * solver.eigenvectors().rightCols(kept);
  make_largest_entries_positive(rotated);
  ElasticBasis result = describe(system);
  result.basis = embed_in_surface(system.volume, rotated);
  result.weights = 0.5 * (elastic.cwiseInverse().array() + 1.0 / cap).inverse().matrix();
  result.frequencies_hz = frequencies_of(elastic);
  result.zero_energy_modes = zero;
  return result;
}

void check_filter_ratio(const ElasticBasisOptions& options) {
  if (!(options.weight_filter_ratio > 0.0) || !std::isfinite(options.weight_filter_ratio)) {
    throw std::invalid_argument("the weight filter ratio must be positive and finite");
  }
}

}  // namespace

ElasticBasis stiffness_scaled_polynomial_basis(const TriangleMesh& mesh, const ElasticBasisOptions& options,
                                               std::ostream* progress) {
  check_filter_ratio(options);
  const ElasticSystem system = elastic_system(mesh, options, progress);
  return stiffness_scale(system, polynomial_displacements(system.volume.nodes, mesh, options.modes), options);
}

ElasticBasis stiffness_scaled_basis(const TriangleMesh& mesh, const Eigen::MatrixXd& surface_basis,
                                    const ElasticBasisOptions& options, std::ostream* progress) {
  check_filter_ratio(options);
  if (surface_basis.cols() < 1) throw std::invalid_argument("stiffness scaling: the basis has no modes");
  const ElasticSystem system = elastic_system(mesh, options, progress);
  return stiffness_scale(system, least_energy_extension(system, surface_basis), options);
}

}  // namespace sscc
