// The two self motions of a scene object (scene.hpp): in the object's frame, where rigid
// motion changes nothing, and on world-space straight lines, which cut the chords of a
// turning frame's arcs. A sphere turned by half a turn with q fixed: rigid motion touches
// nothing, while the world-linear paths all cross the axis at t = 1/2.
#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <random>

#include "sscc/certificates/certificates.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "sscc/scene/scene.hpp"
#include "support/pair_reference.hpp"
#include "support/test_meshes.hpp"

namespace {

constexpr int kModes = 9;

struct Fixture {
  sscc::TriangleMesh mesh = sscc::test::uv_sphere(8, 12);
  sscc::SubspaceModel model{mesh, sscc::polynomial_basis(mesh, kModes), Eigen::VectorXd::Ones(kModes)};
  sscc::SubspaceBvh bvh{model};
  sscc::Certificates certificates = sscc::Certificates::precompute(bvh);
  sscc::SelfCcd certified{bvh, certificates};
};

std::vector<Eigen::Vector3d> world_positions(const sscc::SubspaceModel& model, const Eigen::VectorXd& q,
                                             const sscc::RigidFrame& f) {
  std::vector<Eigen::Vector3d> x = model.deformed_positions(q);
  for (auto& p : x) p = f.rotation * p + f.translation;
  return x;
}

/// Every non-adjacent pair through all 15 features on the world-space straight-line paths,
/// positions computed here.
std::vector<sscc::TrianglePairContact> world_brute_force(const sscc::SubspaceModel& model, const sscc::ObjectStep& s) {
  return sscc::test::brute_force_pairs(model.mesh(), world_positions(model, s.q0, s.frame0),
                                       world_positions(model, s.q1, s.frame1));
}

sscc::RigidFrame turned(double angle, const Eigen::Vector3d& axis = Eigen::Vector3d::UnitZ()) {
  sscc::RigidFrame f;
  f.rotation = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  return f;
}

}  // namespace

TEST_CASE(
    "scene self motion: a half-turn collapses the sphere on world-linear paths, and is refused in the object frame",
    "[scene][self_motion]") {
  const Fixture f;
  sscc::ObjectStep half_turn;
  half_turn.q0 = half_turn.q1 = Eigen::VectorXd::Zero(kModes);
  half_turn.frame1.rotation = Eigen::Vector3d(-1.0, -1.0, 1.0).asDiagonal();  // exactly a half-turn about z
  REQUIRE(f.certified.root_certifies(half_turn.q0, half_turn.q1));  // q = 0: the object frame sees nothing move

  sscc::Scene object_frame;
  object_frame.add_object(f.certified);
  CHECK_THROWS_WITH(object_frame.step({half_turn}), Catch::Contains("object 0") &&
                                                        Catch::Contains("max_object_frame_rotation") &&
                                                        Catch::Contains("kWorldLinear"));
  // Told that the object follows its frame rigidly, the object-frame test certifies the step,
  // as documented: rigid motion brings nothing into contact.
  sscc::SceneOptions rigid;
  rigid.max_object_frame_rotation = INFINITY;
  const sscc::SceneReport certified = object_frame.step({half_turn}, rigid);
  CHECK(certified.objects[0].outcome == sscc::SelfTestOutcome::kCertified);
  CHECK_FALSE(certified.collided());

  sscc::Scene world;
  world.add_object(f.certified, {true, true, sscc::SelfMotion::kWorldLinear});
  const sscc::SceneReport collapsed = world.step({half_turn});
  CHECK(collapsed.objects[0].outcome == sscc::SelfTestOutcome::kTraversed);
  const auto expected = world_brute_force(f.model, half_turn);
  // Every vertex off the axis crosses it at t = 1/2: most pairs meet there.
  REQUIRE(expected.size() > static_cast<std::size_t>(f.mesh.triangle_count()));
  sscc::test::require_same_pairs(collapsed.objects[0].report.pairs, expected);
  CHECK(collapsed.earliest_toi <= 0.5);
  // The world-linear test ignores the rotation bound: it is the motion it tests.
  sscc::SceneOptions strict;
  strict.max_object_frame_rotation = 0.0;
  CHECK(world.step({half_turn}, strict).objects[0].report.pairs == collapsed.objects[0].report.pairs);
}

TEST_CASE("scene self motion: the rotation bound, and world-linear steps against brute force", "[scene][self_motion]") {
  const Fixture f;
  sscc::Scene object_frame;
  object_frame.add_object(f.certified);
  sscc::Scene world;
  world.add_object(f.certified, {true, true, sscc::SelfMotion::kWorldLinear});
  sscc::Scene no_self;  // no self test: no rotation bound either
  no_self.add_object(f.certified, {false, true});
  std::mt19937_64 rng(41);
  std::normal_distribution<double> normal;
  const auto random_q = [&](double amplitude) {
    Eigen::VectorXd q(kModes);
    for (int j = 0; j < kModes; ++j) q[j] = amplitude * normal(rng) / 3.0;
    return q;
  };

  sscc::ObjectStep s;
  s.q0 = random_q(0.3);
  s.q1 = s.q0 + random_q(0.3);
  s.frame0 = turned(0.4, {1, 2, 3});
  s.frame1 = turned(0.4 + 0.99 * sscc::kMaxObjectFrameRotation, {1, 2, 3});
  CHECK_NOTHROW(object_frame.step({s}));
  s.frame1 = turned(0.4 + 1.01 * sscc::kMaxObjectFrameRotation, {1, 2, 3});
  CHECK_THROWS_WITH(object_frame.step({s}), Catch::Contains("turns by"));
  CHECK_NOTHROW(no_self.step({s}));
  CHECK_NOTHROW(world.step({s}));

  // Deforming and turning by up to a radian: the world-linear test equals brute force on the
  // world paths; without a turn it is the object-frame query (a translation changes nothing).
  int colliding = 0;
  for (int trial = 0; trial < 6; ++trial) {
    INFO("trial " << trial);
    s.q0 = random_q(0.5);
    s.q1 = s.q0 + random_q(0.5);
    s.frame0 = turned(normal(rng), {normal(rng), normal(rng), normal(rng)});
    s.frame1 = s.frame0;
    s.frame1.translation = Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
    const sscc::SceneReport translated = world.step({s});
    CHECK(translated.objects[0].report.pairs == f.certified.query(s.q0, s.q1).pairs);
    CHECK(translated.objects[0].report.features == f.certified.query(s.q0, s.q1).features);
    s.frame1.rotation = turned(normal(rng), {normal(rng), normal(rng), normal(rng)}).rotation * s.frame0.rotation;
    const sscc::SceneReport r = world.step({s});
    sscc::test::require_same_pairs(r.objects[0].report.pairs, world_brute_force(f.model, s));
    colliding += r.collided();
  }
  CHECK(colliding >= 2);
}

TEST_CASE("scene: a reflection is not a rigid frame", "[scene][frames]") {
  const Fixture f;
  sscc::Scene scene;
  scene.add_object(f.certified);
  sscc::ObjectStep s;
  s.q0 = s.q1 = Eigen::VectorXd::Zero(kModes);
  s.frame1.rotation = Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal();  // orthonormal, det = -1
  CHECK_THROWS_WITH(scene.step({s}), Catch::Contains("object 0") && Catch::Contains("not a rotation"));
  s.frame1 = s.frame0;
  s.frame0.rotation = -Eigen::Matrix3d::Identity();
  CHECK_THROWS_WITH(scene.step({s}), Catch::Contains("not a rotation"));
}
