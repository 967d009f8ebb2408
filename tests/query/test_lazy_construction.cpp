#include <catch2/catch.hpp>

#include <memory>

#include "sscc/certificates/certificates.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "sscc/query/self_ccd.hpp"
#include "sscc/scene/scene.hpp"
#include "support/test_meshes.hpp"

namespace {

struct Fixture {
  sscc::TriangleMesh mesh = sscc::test::uv_sphere(10, 20);
  sscc::SubspaceModel model{mesh, sscc::polynomial_basis(mesh, 27), Eigen::VectorXd::Ones(27)};
  sscc::SubspaceBvh bvh{model};
  sscc::Certificates certificates = sscc::Certificates::precompute(bvh);
  /// A step from rest to a configuration of `times` the root's radius along mode 0.
  Eigen::VectorXd beyond_root(double times) const {
    Eigen::VectorXd q = Eigen::VectorXd::Zero(27);
    q[0] = times * certificates.node_radius(0);
    return q;
  }
};

bool nothing_built(const sscc::SelfCcdBuiltParts& p) {
  return !p.cone_boundaries && !p.cone_radii && !p.unconsidered_leaf_pairs && !p.certified_radii &&
         !p.displacement_bounds;
}

bool cones_built(const sscc::SelfCcdBuiltParts& p) {
  return p.cone_boundaries || p.cone_radii || p.unconsidered_leaf_pairs || p.certified_radii;
}

}  // namespace

TEST_CASE("self-CCD construction: a detector builds only what its queries' options use", "[query]") {
  const Fixture f;
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(27);
  sscc::SelfCcdOptions no_cones;
  no_cones.use_normal_cones = false;

  SECTION("with certificates and the cones off: nothing, even on a step the traversal decides") {
    const sscc::SelfCcd detector(f.bvh, f.certificates);
    REQUIRE(nothing_built(detector.built_parts()));
    const sscc::SelfCcdReport report = detector.query(rest, f.beyond_root(3.0), no_cones);
    REQUIRE_FALSE(report.stats.root_certified);
    detector.prepare(no_cones);
    REQUIRE(nothing_built(detector.built_parts()));
    // The defaults build the cones' parts, for the detector and its copies.
    const sscc::SelfCcd copy = detector;
    copy.query(rest, f.beyond_root(3.0));
    const sscc::SelfCcdBuiltParts built = detector.built_parts();
    REQUIRE(built.cone_radii);
    REQUIRE(built.unconsidered_leaf_pairs);
    REQUIRE(built.certified_radii);
    REQUIRE_FALSE(built.displacement_bounds);  // not used with certificates
  }
  SECTION("without certificates, the cones off: the displacement bounds only") {
    const sscc::SelfCcd detector(f.bvh);
    detector.query(rest, f.beyond_root(3.0), no_cones);
    const sscc::SelfCcdBuiltParts built = detector.built_parts();
    REQUIRE_FALSE(cones_built(built));
    REQUIRE(built.displacement_bounds);
  }
  SECTION("the traditional query and query_positions without cones: nothing") {
    const sscc::SelfCcd detector(f.bvh, f.certificates);
    sscc::SelfCcdOptions traditional;
    sscc::set_traditional(traditional);
    detector.query(rest, f.beyond_root(3.0), traditional);
    const auto x0 = f.model.deformed_positions(rest);
    detector.query_positions(x0, f.model.deformed_positions(f.beyond_root(3.0)), no_cones);
    detector.query_discrete(f.beyond_root(3.0));
    detector.query_exhaustive(rest, f.beyond_root(0.5));
    REQUIRE(nothing_built(detector.built_parts()));
  }
  SECTION("a scene of instances, stepped with the cones off: nothing") {
    const auto detector = std::make_shared<const sscc::SelfCcd>(
        std::make_shared<const sscc::SubspaceBvh>(f.bvh), std::make_shared<const sscc::Certificates>(f.certificates));
    sscc::Scene scene;
    for (int i = 0; i < 3; ++i) scene.add_object(*detector);
    REQUIRE(nothing_built(detector->built_parts()));
    std::vector<sscc::ObjectStep> steps(3);
    for (auto& step : steps) {
      step.q0 = rest;
      step.q1 = f.beyond_root(3.0);
    }
    steps[1].frame0.translation = steps[1].frame1.translation = Eigen::Vector3d(10, 0, 0);  // apart
    steps[2].frame0.translation = steps[2].frame1.translation = Eigen::Vector3d(-10, 0, 0);
    sscc::SceneOptions options;
    options.use_normal_cones = false;
    scene.step(steps, options);
    REQUIRE(nothing_built(detector->built_parts()));
  }
}
