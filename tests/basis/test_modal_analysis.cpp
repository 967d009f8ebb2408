#include <catch2/catch.hpp>

#include <cmath>

#include "sscc/basis/linear_elasticity.hpp"
#include "sscc/basis/modal_analysis.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "support/test_meshes.hpp"

namespace {

constexpr double kLength = 1.0;     // m
constexpr double kThickness = 0.1;  // m, square cross-section: slenderness 10

sscc::ElasticBasisOptions beam_options(int cells_across, int modes) {
  sscc::ElasticBasisOptions options;
  options.modes = modes;
  options.material.youngs_modulus = 1.0e6;
  options.material.poisson_ratio = 0.3;
  options.material.density = 1000.0;
  options.volume.method = sscc::VolumeMethod::tetgen;
  const double cell = kThickness / cells_across;
  options.volume.tetgen_max_volume = cell * cell * cell / 6.0;
  return options;
}

sscc::TriangleMesh beam(int cells_across) {
  const int along = static_cast<int>(std::lround(cells_across * kLength / kThickness));
  return sscc::test::box_surface({kLength, kThickness, kThickness}, {along, cells_across, cells_across});
}

/// Euler-Bernoulli, free-free: f = (beta L)^2 / (2 pi L^2) sqrt(E I / (rho A)), beta L = 4.7300.
double first_bending_hz(const sscc::ElasticMaterial& m) {
  const double area = kThickness * kThickness, inertia = std::pow(kThickness, 4) / 12.0;
  return 4.7300 * 4.7300 / (2 * M_PI * kLength * kLength) * std::sqrt(m.youngs_modulus * inertia / (m.density * area));
}
/// A free-free bar's first axial mode: f = sqrt(E / rho) / (2 L).
double first_axial_hz(const sscc::ElasticMaterial& m) {
  return std::sqrt(m.youngs_modulus / m.density) / (2 * kLength);
}

}  // namespace

TEST_CASE("modal analysis of a slender free beam converges to beam theory", "[basis][modal]") {
  double previous_error = INFINITY;
  for (int cells : {2, 4, 6}) {
    const sscc::ElasticBasisOptions options = beam_options(cells, 8);
    const sscc::ElasticBasis b = sscc::modal_basis(beam(cells), options);
    CAPTURE(cells, b.frequencies_hz.transpose());
    CHECK(b.zero_energy_modes == 6);
    CHECK(b.volume_method == "tetgen");
    const double bending = first_bending_hz(options.material);
    // The two lowest modes: bending in the two (equal) directions of the square section,
    // split by the mesh's asymmetry.
    CHECK(b.frequencies_hz[1] == Approx(b.frequencies_hz[0]).epsilon(cells == 6 ? 0.01 : 0.05));
    const double error = std::fabs(b.frequencies_hz[0] / bending - 1.0);
    CHECK(error < previous_error);  // refinement converges (linear tetrahedra: from above)
    CHECK(b.frequencies_hz[0] > bending * 0.97);
    previous_error = error;
    if (cells == 6) {
      CHECK(error < 0.05);
      // The axial mode: the first mode near sqrt(E/rho)/(2L) (within 1%).
      const double axial = first_axial_hz(options.material);
      double nearest = INFINITY;
      for (Eigen::Index i = 0; i < b.frequencies_hz.size(); ++i) {
        nearest = std::min(nearest, std::fabs(b.frequencies_hz[i] / axial - 1.0));
      }
      CHECK(nearest < 0.01);
    }
    // Weights make ||q||_M^2 the strain energy of mass-normalised modes: omega^2 / 2.
    for (Eigen::Index i = 0; i < b.weights.size(); ++i) {
      CHECK(b.weights[i] == Approx(0.5 * std::pow(2 * M_PI * b.frequencies_hz[i], 2)));
    }
    CHECK(b.basis.rows() == 3 * beam(cells).vertex_count());
    CHECK(b.basis.cols() == 8);
  }
}

TEST_CASE("vibration modes solve K phi = lambda M phi, mass-normalised", "[basis][modal]") {
  const sscc::VolumeMesh volume = sscc::voxelize_surface(sscc::test::uv_sphere(8, 12), 6);
  const sscc::ElasticMaterial material;
  const Eigen::SparseMatrix<double> k = sscc::stiffness_matrix(volume, material);
  const Eigen::VectorXd m = sscc::lumped_mass(volume, material);
  const sscc::VibrationModes modes = sscc::lowest_vibration_modes(k, m, 10, 6);
  CHECK(modes.zero_energy_modes == 6);
  const Eigen::MatrixXd gram = modes.vectors.transpose() * m.asDiagonal() * modes.vectors;
  CHECK((gram - Eigen::MatrixXd::Identity(10, 10)).norm() < 1e-8);
  for (int i = 0; i < 10; ++i) {
    CHECK(modes.eigenvalues[i] > 0.0);
    if (i > 0) CHECK(modes.eigenvalues[i] >= modes.eigenvalues[i - 1]);
    const Eigen::VectorXd residual =
        k * modes.vectors.col(i) - modes.eigenvalues[i] * m.cwiseProduct(modes.vectors.col(i));
    CHECK(residual.norm() < 1e-6 * modes.eigenvalues[i] * m.cwiseProduct(modes.vectors.col(i)).norm());
  }
  // Rigid motions (a lower count expected) are found and skipped anyway.
  const sscc::VibrationModes again = sscc::lowest_vibration_modes(k, m, 4, 0);
  CHECK(again.zero_energy_modes == 6);
  CHECK((again.eigenvalues - modes.eigenvalues.head(4)).norm() < 1e-8 * modes.eigenvalues[3]);
}

TEST_CASE("stiffness-scaled polynomial modes: rotations dropped, Rayleigh-Ritz above the modes, filtered weights",
          "[basis][modal]") {
  const sscc::ElasticBasisOptions options = beam_options(2, 27);
  const sscc::TriangleMesh mesh = beam(2);
  const sscc::ElasticBasis scaled = sscc::stiffness_scaled_polynomial_basis(mesh, options);
  CHECK(scaled.zero_energy_modes == 6);  // rigid motions (the polynomials' rotations among them)
  CHECK(scaled.basis.cols() == 24);
  const sscc::ElasticBasis modal = sscc::modal_basis(mesh, beam_options(2, 1));
  // A Ritz subspace's lowest frequency is never below the true lowest one.
  CHECK(scaled.frequencies_hz[0] >= modal.frequencies_hz[0] * (1 - 1e-9));
  const double lambda_min = std::pow(2 * M_PI * scaled.frequencies_hz[0], 2);
  for (Eigen::Index i = 0; i < scaled.weights.size(); ++i) {
    const double lambda = std::pow(2 * M_PI * scaled.frequencies_hz[i], 2);
    CHECK(scaled.weights[i] == Approx(0.5 / (1 / lambda + 1 / (options.weight_filter_ratio * lambda_min))));
    CHECK(scaled.weights[i] <= 0.5 * options.weight_filter_ratio * lambda_min);
  }
}

TEST_CASE("a given surface basis is stiffness-scaled through its least-energy extension", "[basis][modal]") {
  // With the surface vertices as nodes (TetGen), linear fields extend into the volume as
  // themselves (the elements pass the patch test), so scaling their surface traces must
  // equal scaling the exact volume fields. (A voxel shell around the surface may relax.)
  {
    const sscc::ElasticBasisOptions options = beam_options(2, 9);
    const sscc::TriangleMesh mesh = beam(2);
    const sscc::ElasticBasis exact = sscc::stiffness_scaled_polynomial_basis(mesh, options);
    const sscc::ElasticBasis extended = sscc::stiffness_scaled_basis(mesh, sscc::polynomial_basis(mesh, 9), options);
    REQUIRE(extended.frequencies_hz.size() == exact.frequencies_hz.size());
    CHECK((extended.frequencies_hz - exact.frequencies_hz).norm() < 1e-6 * exact.frequencies_hz.norm());
    CHECK((extended.weights - exact.weights).norm() < 1e-6 * exact.weights.norm());
  }
  CHECK_THROWS_WITH(sscc::stiffness_scaled_basis(beam(2), Eigen::MatrixXd::Ones(9, 2), beam_options(2, 2)),
                    Catch::Contains("rows"));
}
