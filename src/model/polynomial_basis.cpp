#include "sscc/model/polynomial_basis.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sscc {

namespace {

struct PolynomialFrame {
  Eigen::Vector3d centre;
  Eigen::Vector3d half;  ///< half extents; a flat axis keeps 1 (its coordinate is 0 anyway)
  double diagonal = 0.0;
};

PolynomialFrame frame_of(const TriangleMesh& mesh, int modes) {
  if (modes < 1 || modes > kMaxPolynomialModes) {
    throw std::invalid_argument("polynomial_basis: " + std::to_string(modes) + " modes requested; there are 1 to " +
                                std::to_string(kMaxPolynomialModes));
  }
  if (mesh.vertex_count() == 0) throw std::invalid_argument("polynomial_basis: the mesh has no vertices");
  const Aabb box = mesh.bounding_box();
  const Eigen::Vector3d& lo = box.lo;
  const Eigen::Vector3d& hi = box.hi;
  PolynomialFrame frame;
  frame.diagonal = (hi - lo).norm();
  if (!(frame.diagonal > 0.0)) throw std::invalid_argument("polynomial_basis: the mesh has no extent");
  frame.centre = 0.5 * (lo + hi);
  frame.half = (0.5 * (hi - lo)).unaryExpr([](double h) { return h > 0.0 ? h : 1.0; });
  return frame;
}

Eigen::MatrixXd evaluate(const std::vector<Eigen::Vector3d>& points, const PolynomialFrame& frame, int modes) {
  const long n = static_cast<long>(points.size());
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(3 * n, modes);
  for (long v = 0; v < n; ++v) {
    const Eigen::Vector3d x = (points[v] - frame.centre).cwiseQuotient(frame.half);
    const double functions[9] = {x[0],        x[1],        x[2],        x[0] * x[0], x[1] * x[1],
                                 x[2] * x[2], x[0] * x[1], x[1] * x[2], x[2] * x[0]};
    for (int m = 0; m < modes; ++m) {
      const int axis = m < 9 ? m / 3 : (m - 9) / 6;
      const int function = m < 9 ? m % 3 : 3 + (m - 9) % 6;
      basis(3 * v + axis, m) = functions[function];
    }
  }
  return basis;
}

}  // namespace

Eigen::MatrixXd polynomial_displacements(const std::vector<Eigen::Vector3d>& points, const TriangleMesh& mesh,
                                         int modes) {
  return evaluate(points, frame_of(mesh, modes), modes);
}

Eigen::MatrixXd polynomial_basis(const TriangleMesh& mesh, int modes) {
  const PolynomialFrame frame = frame_of(mesh, modes);
  Eigen::MatrixXd basis = evaluate(mesh.vertices(), frame, modes);
  const int n = mesh.vertex_count();
  for (int m = 0; m < modes; ++m) {
    double largest = 0.0;
    for (int v = 0; v < n; ++v) largest = std::max(largest, basis.col(m).segment<3>(3L * v).norm());
    if (largest > 0.0) basis.col(m) *= frame.diagonal / largest;
  }
  return basis;
}

}  // namespace sscc
