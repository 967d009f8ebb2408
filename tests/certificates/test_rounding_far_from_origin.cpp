// A contact that exists only through the rounding of the query's positions, far from the
// origin where a unit of roundoff is large: the certificates must leave it to the traversal,
// so that the reports with and without them are identical.
#include <catch2/catch.hpp>

#include <cmath>

#include "sscc/certificates/certificates.hpp"
#include "sscc/query/self_ccd.hpp"

namespace {

/// Triangle a at height z, triangle b above it at z + 1 (inside a's outline); one mode
/// lowers b by 1 per unit, weight 1: contact at ||q|| = 1 exactly.
struct StackedTriangles {
  explicit StackedTriangles(double z)
      : mesh({{0, 0, z}, {10, 0, z}, {0, 10, z}, {1, 1, z + 1}, {8, 1, z + 1}, {1, 8, z + 1}}, {{0, 1, 2}, {3, 4, 5}}),
        model(mesh, lowering_basis(), Eigen::VectorXd::Ones(1)),
        bvh(model),
        certificates(sscc::Certificates::precompute(bvh)),
        detector(bvh, certificates) {}
  static Eigen::MatrixXd lowering_basis() {
    Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(18, 1);
    for (int v = 3; v < 6; ++v) basis(3 * v + 2, 0) = -1.0;
    return basis;
  }
  sscc::TriangleMesh mesh;
  sscc::SubspaceModel model;
  sscc::SubspaceBvh bvh;
  sscc::Certificates certificates;
  sscc::SelfCcd detector;
};

}  // namespace

TEST_CASE("certificates: contacts through rounding far from the origin are not certified away",
          "[certificates][rounding]") {
  for (double z : {0.0, 1024.0, 131072.0, 1099511627776.0}) {
    INFO("z = " << z);
    const StackedTriangles s(z);
    const double root = s.certificates.node_radius(0);
    CHECK(root <= 1.0);
    sscc::SelfCcdOptions traditional;
    sscc::set_traditional(traditional);
    // Steps from rest to just below the root radius and to points around the true contact.
    for (double q : {root * (1 - 1e-9), root * (1 - 1e-15), std::nextafter(root, 0.0), 1.0 - 1.2e-11, 1.0 - 1e-15, 1.0,
                     1.0 + 1e-12}) {
      INFO("q = " << q);
      const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(1), q1 = Eigen::VectorXd::Constant(1, q);
      const sscc::SelfCcdReport with = s.detector.query(q0, q1);
      const sscc::SelfCcdReport without = s.detector.query(q0, q1, traditional);
      CHECK(with.pairs == without.pairs);
      CHECK(with.features == without.features);
    }
  }
}
