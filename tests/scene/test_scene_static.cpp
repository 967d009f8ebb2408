// A static object is skipped: nothing comes into contact during a step in which nothing
// moves, and a contact that already exists at t = 0 is not reported (the header says so);
// the same object moved by the smallest step reports it, and the discrete query finds it.
#include <catch2/catch.hpp>

#include "sscc/model/polynomial_basis.hpp"
#include "sscc/scene/scene.hpp"

TEST_CASE("scene: a static object in contact with itself at rest is skipped, not reported", "[scene]") {
  // Two non-adjacent triangles touching at rest: a corner of the second on the first's face.
  const sscc::TriangleMesh mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, 0}, {0.3, 0.2, 0.5}, {0.2, 0.3, 0.5}},
                                {{0, 1, 2}, {3, 4, 5}});
  const sscc::SubspaceBvh bvh(sscc::SubspaceModel(mesh, sscc::polynomial_basis(mesh, 3), Eigen::VectorXd::Ones(3)));
  const sscc::SelfCcd detector(bvh);
  sscc::Scene scene;
  scene.add_object(detector);

  sscc::ObjectStep still;
  still.q0 = still.q1 = Eigen::VectorXd::Zero(3);
  const sscc::SceneReport skipped = scene.step({still});
  CHECK(skipped.objects[0].outcome == sscc::SelfTestOutcome::kStatic);
  CHECK_FALSE(skipped.collided());
  CHECK(detector.query_discrete(still.q0).pairs.size() == 1);  // the contact exists

  sscc::ObjectStep nudged = still;
  nudged.q1[0] = 1e-9;  // moving: the contact at t = 0 is a contact during the step
  const sscc::SceneReport traversed = scene.step({nudged});
  CHECK(traversed.objects[0].outcome == sscc::SelfTestOutcome::kTraversed);
  REQUIRE(traversed.collided());
  CHECK(traversed.earliest_toi == 0.0);
}
