// Links against the installed core alone: a sheet whose second triangle pair falls through
// the first during the step; the detector finds it, and a step with certificates inside the
// root radius is decided in O(r).
#include <sscc/model/subspace_model.hpp>
#include <sscc/query/self_ccd.hpp>

#include <cstdio>

int main() {
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), up(0, 0, 1);
  const sscc::TriangleMesh mesh({a, b, c, a + up, b + up, c + up}, {{0, 1, 2}, {3, 4, 5}});
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(18, 1);  // mode 0 lowers the second triangle
  for (int v = 3; v < 6; ++v) basis(3 * v + 2, 0) = -1.0;
  const sscc::SubspaceBvh bvh(sscc::SubspaceModel(mesh, basis, Eigen::VectorXd::Ones(1)));
  const sscc::SelfCcd detector(bvh, sscc::Certificates::precompute(bvh));

  const sscc::SelfCcdReport through = detector.query(Eigen::VectorXd::Zero(1), Eigen::VectorXd::Constant(1, 2.0));
  const sscc::SelfCcdReport certified = detector.query(Eigen::VectorXd::Zero(1), Eigen::VectorXd::Constant(1, 0.5));
  std::printf("through: pairs=%zu toi=%.6f; small step: root_certified=%d\n", through.pairs.size(),
              through.earliest_toi, certified.stats.root_certified);
  const bool found = through.pairs.size() == 1 && through.earliest_toi > 0.49 && through.earliest_toi <= 0.5;
  return found && certified.stats.root_certified && certified.pairs.empty() ? 0 : 1;
}
