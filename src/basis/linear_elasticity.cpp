#include "sscc/basis/linear_elasticity.hpp"

#include <Eigen/LU>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace sscc {

namespace {

/// Volume and the gradients of the four linear shape functions of tetrahedron t.
double shape_gradients(const VolumeMesh& volume, int t, Eigen::Matrix<double, 3, 4>& gradients) {
  const Tetrahedron& tet = volume.tetrahedra[t];
  Eigen::Matrix3d edges;
  for (int k = 0; k < 3; ++k) edges.col(k) = volume.nodes[tet[k + 1]] - volume.nodes[tet[0]];
  const double size = edges.cwiseAbs().maxCoeff();
  const double vol = edges.determinant() / 6.0;
  if (!(vol > 1e-14 * size * size * size)) {
    throw std::invalid_argument("tetrahedron " + std::to_string(t) + " has non-positive volume " + std::to_string(vol));
  }
  // x = x0 + E xi: the barycentric coordinates xi_1..3 have gradients the rows of E^{-1}.
  const Eigen::Matrix3d inverse = edges.inverse();
  gradients.rightCols<3>() = inverse.transpose();
  gradients.col(0) = -gradients.rightCols<3>().rowwise().sum();
  return vol;
}

}  // namespace

void ElasticMaterial::validate() const {
  if (!(youngs_modulus > 0.0) || !std::isfinite(youngs_modulus)) {
    throw std::invalid_argument("Young's modulus must be positive and finite (Pa), got " +
                                std::to_string(youngs_modulus));
  }
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5)) {
    throw std::invalid_argument("Poisson ratio must lie in (-1, 0.5), got " + std::to_string(poisson_ratio));
  }
  if (!(density > 0.0) || !std::isfinite(density)) {
    throw std::invalid_argument("density must be positive and finite (kg/m^3), got " + std::to_string(density));
  }
}

Eigen::SparseMatrix<double> stiffness_matrix(const VolumeMesh& volume, const ElasticMaterial& material) {
  material.validate();
  const double nu = material.poisson_ratio;
  const double mu = material.youngs_modulus / (2.0 * (1.0 + nu));
  const double lambda = material.youngs_modulus * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(volume.tetrahedra.size() * 144);
  Eigen::Matrix<double, 3, 4> g;
  for (int t = 0; t < static_cast<int>(volume.tetrahedra.size()); ++t) {
    const double vol = shape_gradients(volume, t, g);
    const Tetrahedron& tet = volume.tetrahedra[t];
    // Hessian of mu eps:eps + lambda/2 tr(eps)^2 for eps = sym(sum_i u_i g_i^T).
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) {
        const Eigen::Matrix3d block =
            vol * (lambda * g.col(i) * g.col(j).transpose() + mu * g.col(j) * g.col(i).transpose() +
                   mu * g.col(i).dot(g.col(j)) * Eigen::Matrix3d::Identity());
        for (int a = 0; a < 3; ++a) {
          for (int b = 0; b < 3; ++b) entries.emplace_back(3 * tet[i] + a, 3 * tet[j] + b, block(a, b));
        }
      }
    }
  }
  const Eigen::Index n = 3 * static_cast<Eigen::Index>(volume.nodes.size());
  Eigen::SparseMatrix<double> stiffness(n, n);
  stiffness.setFromTriplets(entries.begin(), entries.end());
  return stiffness;
}

Eigen::VectorXd lumped_mass(const VolumeMesh& volume, const ElasticMaterial& material) {
  material.validate();
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(3 * static_cast<Eigen::Index>(volume.nodes.size()));
  Eigen::Matrix<double, 3, 4> g;
  for (int t = 0; t < static_cast<int>(volume.tetrahedra.size()); ++t) {
    const double share = material.density * shape_gradients(volume, t, g) / 4.0;
    for (int node : volume.tetrahedra[t]) mass.segment<3>(3 * node).array() += share;
  }
  return mass;
}

}  // namespace sscc
