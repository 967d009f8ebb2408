#include "sscc/model/polynomial_basis.hpp"

#include <stdexcept>
#include <string>

namespace sscc {

Eigen::MatrixXd polynomial_basis(const TriangleMesh& mesh, int modes) {
  if (modes < 1 || modes > kMaxPolynomialModes) {
    throw std::invalid_argument("polynomial_basis: " + std::to_string(modes) +
                                " modes requested; there are 1 to " +
                                std::to_string(kMaxPolynomialModes));
  }
  const int n = mesh.vertex_count();
  if (n == 0) throw std::invalid_argument("polynomial_basis: the mesh has no vertices");
  Eigen::Vector3d lo = mesh.vertices()[0];
  Eigen::Vector3d hi = lo;
  for (const auto& p : mesh.vertices()) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double diagonal = (hi - lo).norm();
  if (!(diagonal > 0.0)) throw std::invalid_argument("polynomial_basis: the mesh has no extent");
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  // Half extents; a flat axis keeps scale 1 (its coordinate is 0 anyway).
  const Eigen::Vector3d half = (0.5 * (hi - lo)).unaryExpr([](double h) { return h > 0.0 ? h : 1.0; });
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(3L * n, modes);
  for (int v = 0; v < n; ++v) {
    const Eigen::Vector3d x = (mesh.vertices()[v] - centre).cwiseQuotient(half);
    const double functions[9] = {x[0], x[1], x[2], x[0] * x[0], x[1] * x[1], x[2] * x[2],
                                 x[0] * x[1], x[1] * x[2], x[2] * x[0]};
    for (int m = 0; m < modes; ++m) {
      const int axis = m < 9 ? m / 3 : (m - 9) / 6;
      const int function = m < 9 ? m % 3 : 3 + (m - 9) % 6;
      basis(3L * v + axis, m) = functions[function];
    }
  }
  for (int m = 0; m < modes; ++m) {
    double largest = 0.0;
    for (int v = 0; v < n; ++v) largest = std::max(largest, basis.col(m).segment<3>(3L * v).norm());
    if (largest > 0.0) basis.col(m) *= diagonal / largest;
  }
  return basis;
}

}  // namespace sscc
