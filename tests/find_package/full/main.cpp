// Links against an installed sscc: one kernel query (a vertex falling through a triangle
// halfway through the step), and certificates for two triangles, one moving onto the other.
#include <sscc/sscc.hpp>

#include <cstdio>

int main() {
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const auto r =
      sscc::ccd::vertex_face_ccd(Eigen::Vector3d(0.2, 0.2, 1), a, b, c, Eigen::Vector3d(0.2, 0.2, -1), a, b, c);
  std::printf("hit=%d toi=%.6f\n", r.hit, r.toi);

  // The second triangle lies 1 above the first; mode 0 lowers it by 1 per unit.
  const sscc::TriangleMesh mesh(
      {a, b, c, a + Eigen::Vector3d(0, 0, 1), b + Eigen::Vector3d(0, 0, 1), c + Eigen::Vector3d(0, 0, 1)},
      {{0, 1, 2}, {3, 4, 5}});
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(18, 1);
  for (int v = 3; v < 6; ++v) basis(3 * v + 2, 0) = -1.0;
  const sscc::SubspaceModel model(mesh, basis, Eigen::VectorXd::Ones(1));
  const sscc::SubspaceBvh bvh(model);
  const sscc::Certificates certificates = sscc::Certificates::precompute(bvh);
  const double radius = certificates.node_radius(0);
  std::printf("root radius %.6f\n", radius);
  const bool kernel_ok = r.hit && r.toi <= 0.5 && r.toi > 0.49;
  return kernel_ok && radius <= 1.0 && radius > 0.5 ? 0 : 1;  // 0.866: R_global clamps it
}
