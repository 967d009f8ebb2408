#include <catch2/catch.hpp>

#include <random>

#include "sscc/basis/linear_elasticity.hpp"
#include "support/test_meshes.hpp"

namespace {

/// Node displacements of the linear field u(x) = G x + b.
Eigen::VectorXd linear_field(const sscc::VolumeMesh& volume, const Eigen::Matrix3d& gradient,
                             const Eigen::Vector3d& b) {
  Eigen::VectorXd u(3 * volume.nodes.size());
  for (std::size_t n = 0; n < volume.nodes.size(); ++n) u.segment<3>(3 * n) = gradient * volume.nodes[n] + b;
  return u;
}

}  // namespace

TEST_CASE("stiffness: symmetric, rigid motions cost nothing, uniform strain costs its energy density", "[basis]") {
  const sscc::VolumeMesh volume = sscc::tetrahedralize_surface(sscc::test::box_surface({2, 1, 0.5}, {4, 2, 1}), 1.414);
  sscc::ElasticMaterial material;
  material.youngs_modulus = 3.0e5;
  material.poisson_ratio = 0.3;
  const Eigen::SparseMatrix<double> k = sscc::stiffness_matrix(volume, material);
  CHECK((Eigen::SparseMatrix<double>(k.transpose()) - k).norm() <= 1e-12 * k.norm());

  std::mt19937_64 rng(3);
  std::normal_distribution<double> normal;
  Eigen::Matrix3d random;
  for (int i = 0; i < 9; ++i) random.data()[i] = normal(rng);
  const Eigen::Matrix3d skew = random - random.transpose();
  const Eigen::VectorXd rigid = linear_field(volume, skew, Eigen::Vector3d(1, -2, 3));
  CHECK((k * rigid).norm() <= 1e-10 * k.norm() * rigid.norm());

  // Patch test: a uniform strain eps has energy V (mu eps:eps + lambda/2 tr(eps)^2).
  const Eigen::Matrix3d strain = 0.5 * (random + random.transpose());
  const Eigen::VectorXd u = linear_field(volume, strain, Eigen::Vector3d::Zero());
  const double nu = material.poisson_ratio, e = material.youngs_modulus;
  const double mu = e / (2 * (1 + nu)), lambda = e * nu / ((1 + nu) * (1 - 2 * nu));
  const double expected = 1.0 * (mu * strain.squaredNorm() + 0.5 * lambda * strain.trace() * strain.trace());
  CHECK(0.5 * u.dot(k * u) == Approx(expected).epsilon(1e-10));
}

TEST_CASE("lumped mass adds up to the body's mass", "[basis]") {
  const sscc::VolumeMesh volume = sscc::voxelize_surface(sscc::test::box_surface({1, 1, 1}, {3, 3, 3}), 6);
  sscc::ElasticMaterial material;
  material.density = 800.0;
  const Eigen::VectorXd m = sscc::lumped_mass(volume, material);
  double vol = 0.0;
  for (const auto& t : volume.tetrahedra) vol += sscc::signed_volume(volume.nodes, t);
  CHECK(m.sum() == Approx(3 * 800.0 * vol));
  CHECK(m.minCoeff() > 0.0);
}

TEST_CASE("material parameters are checked with their units", "[basis]") {
  sscc::ElasticMaterial material;
  material.poisson_ratio = 0.5;
  CHECK_THROWS_WITH(material.validate(), Catch::Contains("Poisson"));
  material = {};
  material.youngs_modulus = -1;
  CHECK_THROWS_WITH(material.validate(), Catch::Contains("Pa"));
  material = {};
  material.density = 0;
  CHECK_THROWS_WITH(material.validate(), Catch::Contains("kg/m^3"));
}
