// Ownership is part of the types: a detector built from temporaries owns what it queries,
// so queries after the mesh, model, hierarchy and certificates went out of scope read
// nothing freed (the sanitizer build runs this under AddressSanitizer).
#include <catch2/catch.hpp>

#include <memory>
#include <random>

#include "sscc/certificates/certificates.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "sscc/query/self_ccd.hpp"
#include "sscc/scene/scene.hpp"
#include "support/test_meshes.hpp"

namespace {

/// A detector whose every ingredient was a temporary of this function.
sscc::SelfCcd detector_from_temporaries(bool with_certificates) {
  const sscc::TriangleMesh mesh = sscc::test::parallel_sheets(4, 0.3);
  const sscc::SubspaceBvh bvh(sscc::SubspaceModel(mesh, sscc::polynomial_basis(mesh, 9), Eigen::VectorXd::Ones(9)));
  if (!with_certificates) return sscc::SelfCcd(bvh);
  return sscc::SelfCcd(bvh, sscc::Certificates::precompute(bvh));
}

Eigen::VectorXd squeeze(double amount) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(9);
  q[8] = amount;  // z moved by z (polynomial_basis order): negative brings the sheets together
  return q;
}

}  // namespace

TEST_CASE("ownership: detectors built from temporaries answer like detectors built from kept objects",
          "[query][ownership]") {
  const sscc::TriangleMesh mesh = sscc::test::parallel_sheets(4, 0.3);
  const sscc::SubspaceModel model(mesh, sscc::polynomial_basis(mesh, 9), Eigen::VectorXd::Ones(9));
  const sscc::SubspaceBvh bvh(model);
  const sscc::Certificates certificates = sscc::Certificates::precompute(bvh);
  const sscc::SelfCcd kept(bvh, certificates);

  for (bool with_certificates : {false, true}) {
    INFO("certificates " << with_certificates);
    const sscc::SelfCcd detector = detector_from_temporaries(with_certificates);
    REQUIRE((detector.certificates() != nullptr) == with_certificates);
    std::mt19937_64 rng(5);
    std::normal_distribution<double> normal;
    int colliding = 0;
    for (int step = 0; step < 12; ++step) {
      const Eigen::VectorXd q0 = squeeze(0.02 * normal(rng));
      const Eigen::VectorXd q1 = squeeze(-0.15 + 0.05 * normal(rng));
      sscc::SelfCcdOptions options;
      options.use_certificates = with_certificates;
      const sscc::SelfCcdReport got = detector.query(q0, q1, options);
      const sscc::SelfCcdReport want = kept.query(q0, q1, options);
      CHECK(got.pairs == want.pairs);
      CHECK(got.features == want.features);
      colliding += got.collided() ? 1 : 0;
    }
    CHECK(colliding > 0);  // the squeeze brings the sheets together on some steps
  }
}

TEST_CASE("ownership: copies of a detector and a scene outlive the original", "[query][ownership]") {
  auto original = std::make_unique<sscc::SelfCcd>(detector_from_temporaries(true));
  const sscc::SelfCcd copy = *original;
  sscc::Scene scene;
  scene.add_object(*original);
  const Eigen::VectorXd q0 = squeeze(0.0), q1 = squeeze(-0.15);
  const sscc::SelfCcdReport before = original->query(q0, q1);
  REQUIRE(before.collided());
  original.reset();
  CHECK(copy.query(q0, q1).pairs == before.pairs);
  sscc::ObjectStep step;
  step.q0 = q0;
  step.q1 = q1;
  const sscc::SceneReport report = scene.step({step});
  REQUIRE(report.objects.size() == 1);
  CHECK(report.objects[0].report.pairs == before.pairs);
}
