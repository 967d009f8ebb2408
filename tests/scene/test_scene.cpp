#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>
#include <tuple>

#include "brute_force.hpp"
#include "sscc/certificates/certificates.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "sscc/scene/scene.hpp"
#include "support/test_meshes.hpp"

namespace {

constexpr int kModes = 9;

struct Fixture {
  sscc::TriangleMesh mesh = sscc::test::uv_sphere(8, 12);
  sscc::SubspaceModel model{mesh, sscc::polynomial_basis(mesh, kModes), Eigen::VectorXd::Ones(kModes)};
  sscc::SubspaceBvh bvh{model};
  sscc::SelfCcd ccd{bvh};
};

sscc::RigidFrame frame(const Eigen::Vector3d& axis, double angle, const Eigen::Vector3d& translation) {
  sscc::RigidFrame f;
  f.rotation = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  f.translation = translation;
  return f;
}

Eigen::VectorXd random_q(std::mt19937_64& rng, double amplitude) {
  std::normal_distribution<double> normal;
  Eigen::VectorXd q(kModes);
  for (int j = 0; j < kModes; ++j) q[j] = amplitude * normal(rng) / 3.0;
  return q;
}

std::vector<Eigen::Vector3d> world_positions(const sscc::SubspaceModel& model, const Eigen::VectorXd& q,
                                             const sscc::RigidFrame& f) {
  std::vector<Eigen::Vector3d> x = model.deformed_positions(q);
  for (auto& p : x) p = f.rotation * p + f.translation;
  return x;
}

/// Independent of the library's inter-object code: all triangle pairs of all object pairs,
/// all 15 features through the kernels, world positions computed here.
std::vector<sscc::InterObjectContact> brute_force(const sscc::SubspaceModel& model,
                                                  const std::vector<sscc::ObjectStep>& steps) {
  std::vector<sscc::InterObjectContact> contacts;
  const int n = model.mesh().vertex_count();
  for (std::size_t a = 0; a < steps.size(); ++a) {
    for (std::size_t b = a + 1; b < steps.size(); ++b) {
      std::vector<Eigen::Vector3d> x0 = world_positions(model, steps[a].q0, steps[a].frame0);
      std::vector<Eigen::Vector3d> x1 = world_positions(model, steps[a].q1, steps[a].frame1);
      const auto y0 = world_positions(model, steps[b].q0, steps[b].frame0);
      const auto y1 = world_positions(model, steps[b].q1, steps[b].frame1);
      x0.insert(x0.end(), y0.begin(), y0.end());
      x1.insert(x1.end(), y1.begin(), y1.end());
      for (int ta = 0; ta < model.mesh().triangle_count(); ++ta) {
        for (int tb = 0; tb < model.mesh().triangle_count(); ++tb) {
          sscc::Triangle shifted = model.mesh().triangles()[tb];
          for (int& v : shifted) v += n;
          const double toi =
              sscc::validation::triangle_pair_first_contact(x0, x1, model.mesh().triangles()[ta], shifted);
          if (toi <= 1.0) contacts.push_back({int(a), ta, int(b), tb, toi});
        }
      }
    }
  }
  std::sort(contacts.begin(), contacts.end(), [](const auto& x, const auto& y) {
    return std::make_tuple(x.object_first, x.first, x.object_second, x.second) <
           std::make_tuple(y.object_first, y.first, y.object_second, y.second);
  });
  return contacts;
}

/// Three deforming, rotating spheres, each moving a fraction `closing` of the way to a common
/// point and turning by up to `turn` radians. Turns past kMaxObjectFrameRotation need
/// SceneOptions::max_object_frame_rotation raised.
std::vector<sscc::ObjectStep> random_steps(std::mt19937_64& rng, double amplitude, double closing, double turn = 0.2) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<sscc::ObjectStep> steps(3);
  const Eigen::Vector3d centres[3] = {{0, 0, 0}, {3.6, 0.45, 0}, {1.65, 3.45, 0.3}};
  const Eigen::Vector3d middle(1.8, 1.35, 0.15);
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d axis(uniform(rng), uniform(rng), uniform(rng) + 2.0);
    steps[i].q0 = random_q(rng, amplitude);
    steps[i].q1 = steps[i].q0 + random_q(rng, amplitude);
    const double angle = uniform(rng);
    steps[i].frame0 = frame(axis, angle, centres[i]);
    steps[i].frame1 = frame(axis, angle + turn * uniform(rng), centres[i] + closing * (middle - centres[i]));
  }
  return steps;
}

}  // namespace

TEST_CASE("scene: inter-object contacts equal exhaustive and brute-force testing", "[scene]") {
  const Fixture f;
  sscc::Scene scene;
  for (int i = 0; i < 3; ++i) scene.add_object(f.ccd);
  std::mt19937_64 rng(7);
  int colliding = 0, apart = 0;
  // Turns of up to 2 radians: world paths far from rigid motion between objects; the self
  // tests, in the objects' frames, are told to accept them.
  sscc::SceneOptions wide;
  wide.max_object_frame_rotation = INFINITY;
  for (double closing : {0.0, 0.3, 0.45, 0.6}) {
    for (int trial = 0; trial < 3; ++trial) {
      const auto steps = random_steps(rng, 0.3, closing, 2.0);
      const sscc::SceneReport r = scene.step(steps, wide);
      INFO("closing " << closing << " trial " << trial);
      CHECK(r.contacts == scene.inter_object_exhaustive(steps));
      const auto expected = brute_force(f.model, steps);
      REQUIRE(r.contacts.size() == expected.size());
      for (std::size_t k = 0; k < expected.size(); ++k) {
        CHECK(r.contacts[k].object_first == expected[k].object_first);
        CHECK(r.contacts[k].first == expected[k].first);
        CHECK(r.contacts[k].object_second == expected[k].object_second);
        CHECK(r.contacts[k].second == expected[k].second);
        CHECK(std::abs(r.contacts[k].toi - expected[k].toi) <= sscc::ccd::kDefaultToiTolerance);
      }
      // Self contacts are each object's own query.
      for (int i = 0; i < 3; ++i) CHECK(r.objects[i].report.pairs == f.ccd.query(steps[i].q0, steps[i].q1).pairs);
      (r.contacts.empty() ? apart : colliding) += 1;
      if (!r.contacts.empty()) {
        double earliest = 1.0;
        for (const auto& c : r.contacts) earliest = std::min(earliest, c.toi);
        CHECK(r.earliest_toi <= earliest);
        CHECK(r.collided());
      }
    }
  }
  CHECK(colliding >= 3);
  CHECK(apart >= 3);
}

TEST_CASE("scene: earliest-only and any-hit modes", "[scene]") {
  const Fixture f;
  sscc::Scene scene;
  for (int i = 0; i < 3; ++i) scene.add_object(f.ccd);
  std::mt19937_64 rng(11);
  int tested = 0;
  for (int trial = 0; trial < 6; ++trial) {
    const auto steps = random_steps(rng, 0.3, 0.6);
    const sscc::SceneReport all = scene.step(steps);
    if (!all.collided()) continue;
    ++tested;
    sscc::SceneOptions earliest;
    earliest.mode = sscc::SelfCcdMode::kEarliest;
    const sscc::SceneReport first = scene.step(steps, earliest);
    CHECK(first.earliest_toi == all.earliest_toi);
    for (const auto& c : first.contacts) CHECK(c.toi == all.earliest_toi);
    for (const auto& o : first.objects) {
      for (const auto& p : o.report.pairs) CHECK(p.toi == all.earliest_toi);
    }
    sscc::SceneOptions any;
    any.mode = sscc::SelfCcdMode::kAnyHit;
    CHECK(scene.step(steps, any).collided());
  }
  CHECK(tested >= 3);
}

TEST_CASE("scene: a scene where nothing moves costs nothing; certified objects cost O(r)", "[scene]") {
  const Fixture f;
  const sscc::Certificates certificates = sscc::Certificates::precompute(f.bvh);
  const sscc::SelfCcd certified(f.bvh, certificates);
  sscc::Scene scene;
  for (int i = 0; i < 4; ++i) scene.add_object(certified);
  std::vector<sscc::ObjectStep> steps(4);
  for (int i = 0; i < 4; ++i) {
    steps[i].q0 = steps[i].q1 = Eigen::VectorXd::Constant(kModes, 0.01 * i);
    steps[i].frame0 = steps[i].frame1 = frame({0, 0, 1}, 0.3 * i, {4.0 * i, 0, 0});
  }
  const sscc::SceneReport still = scene.step(steps);
  CHECK(still.stats.objects_static == 4);
  CHECK(still.stats.object_pairs == 6);
  CHECK(still.stats.object_pairs_culled == 6);
  CHECK(still.stats.inter_vertices_computed == 0);
  CHECK(still.stats.inter_box_tests == 0);
  for (const auto& o : still.objects) CHECK(o.outcome == sscc::SelfTestOutcome::kStatic);
  CHECK_FALSE(still.collided());

  // Small deformations, far apart: certified, one box test per pair, no vertex computed.
  const double radius = certificates.node_radius(0);
  REQUIRE(radius > 0.0);
  for (int i = 0; i < 4; ++i) {
    steps[i].q0 = Eigen::VectorXd::Constant(kModes, 0.2 * radius / 3.0);
    steps[i].q1 = Eigen::VectorXd::Constant(kModes, -0.2 * radius / 3.0);
    steps[i].frame1.translation += Eigen::Vector3d(0, 0.1, 0);
  }
  const sscc::SceneReport modest = scene.step(steps);
  CHECK(modest.stats.objects_certified == 4);
  for (const auto& o : modest.objects) CHECK(o.outcome == sscc::SelfTestOutcome::kCertified);
  CHECK(modest.stats.object_pairs_culled == 6);
  CHECK(modest.stats.inter_box_tests == 6);
  CHECK(modest.stats.inter_vertices_computed == 0);
}

TEST_CASE("scene: per-object switches, bad input, concurrent steps", "[scene]") {
  const Fixture f;
  sscc::Scene scene;
  scene.add_object(f.ccd);
  scene.add_object(f.ccd, {false, true});
  scene.add_object(f.ccd, {true, false});
  std::mt19937_64 rng(7);  // a step where all three objects fold onto themselves
  const auto steps = random_steps(rng, 1.2, 0.6);
  const sscc::SceneReport r = scene.step(steps);
  CHECK(r.objects[1].outcome == sscc::SelfTestOutcome::kSwitchedOff);
  CHECK(r.stats.object_pairs == 1);
  // With every switch on, the same step has more: object 1's self contacts and contacts with
  // object 2. The switches remove exactly those.
  sscc::Scene all_on;
  for (int i = 0; i < 3; ++i) all_on.add_object(f.ccd);
  const sscc::SceneReport full = all_on.step(steps);
  REQUIRE(full.objects[1].report.collided());
  std::vector<sscc::InterObjectContact> between_0_and_1;
  for (const auto& c : full.contacts) {
    if (c.object_second != 2) between_0_and_1.push_back(c);
  }
  REQUIRE(between_0_and_1.size() < full.contacts.size());
  REQUIRE_FALSE(between_0_and_1.empty());
  CHECK(r.contacts == between_0_and_1);
  for (int i : {0, 2}) {
    REQUIRE(r.objects[i].report.collided());
    CHECK(r.objects[i].report.features == full.objects[i].report.features);
  }

  std::vector<sscc::SceneReport> concurrent(2);
  std::thread other([&] { concurrent[0] = scene.step(steps); });
  concurrent[1] = scene.step(steps);
  other.join();
  for (const auto& c : concurrent) {
    CHECK(c.contacts == r.contacts);
    CHECK(c.features == r.features);
    for (int i : {0, 2}) CHECK(c.objects[i].report.features == r.objects[i].report.features);
  }

  CHECK_THROWS_WITH(scene.step({steps[0]}), Catch::Contains("1 object steps given for 3"));
  auto bad = steps;
  bad[2].frame1.rotation(0, 1) += 0.1;
  CHECK_THROWS_WITH(scene.step(bad), Catch::Contains("object 2") && Catch::Contains("not a rotation"));
  bad = steps;
  bad[1].q0[3] = std::nan("");
  CHECK_THROWS_WITH(scene.step(bad), Catch::Contains("object 1") && Catch::Contains("not finite"));
  bad = steps;
  bad[0].q1 = Eigen::VectorXd::Zero(2);
  CHECK_THROWS_WITH(scene.step(bad), Catch::Contains("object 0"));
}

TEST_CASE("scene: a minimum separation widens the inter-object culls", "[scene]") {
  const sscc::TriangleMesh one({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  const sscc::SubspaceModel model(one, Eigen::MatrixXd::Zero(9, 1), Eigen::VectorXd::Ones(1));
  const sscc::SubspaceBvh bvh(model);
  const sscc::SelfCcd ccd(bvh);
  sscc::Scene scene;
  scene.add_object(ccd);
  scene.add_object(ccd);
  std::vector<sscc::ObjectStep> steps(2);
  for (auto& s : steps) s.q0 = s.q1 = Eigen::VectorXd::Zero(1);
  steps[1].frame0.translation = Eigen::Vector3d(0, 0, 2);
  steps[1].frame1.translation = Eigen::Vector3d(0, 0, 0.5);  // comes within 0.5, never touches
  sscc::SceneOptions thick;
  thick.kernel.minimum_separation = 1.0;
  CHECK(scene.step(steps, thick).contacts.size() == 1);
  CHECK(scene.inter_object_exhaustive(steps, thick).size() == 1);
  CHECK(scene.step(steps).contacts.empty());
  thick.kernel.minimum_separation = 0.4;
  CHECK(scene.step(steps, thick).contacts.empty());
}

namespace {

void require_same_scene_report(const sscc::SceneReport& parallel, const sscc::SceneReport& serial) {
  REQUIRE(parallel.objects.size() == serial.objects.size());
  for (std::size_t i = 0; i < serial.objects.size(); ++i) {
    INFO("object " << i);
    REQUIRE(parallel.objects[i].outcome == serial.objects[i].outcome);
    REQUIRE(parallel.objects[i].report.pairs == serial.objects[i].report.pairs);
    REQUIRE(parallel.objects[i].report.features == serial.objects[i].report.features);
    REQUIRE(parallel.objects[i].report.earliest_toi == serial.objects[i].report.earliest_toi);
  }
  REQUIRE(parallel.contacts == serial.contacts);
  REQUIRE(parallel.features == serial.features);
  REQUIRE(parallel.earliest_toi == serial.earliest_toi);
  REQUIRE(parallel.stats.objects_static == serial.stats.objects_static);
  REQUIRE(parallel.stats.objects_certified == serial.stats.objects_certified);
  REQUIRE(parallel.stats.objects_traversed == serial.stats.objects_traversed);
  REQUIRE(parallel.stats.object_pairs == serial.stats.object_pairs);
  REQUIRE(parallel.stats.object_pairs_culled == serial.stats.object_pairs_culled);
}

}  // namespace

TEST_CASE("scene: reports equal on every thread count, in every mode, with certificates and without",
          "[scene][parallel]") {
  const Fixture f;
  const sscc::Certificates certificates = sscc::Certificates::precompute(f.bvh);
  const sscc::SelfCcd certified(f.bvh, certificates);
  // Three objects as in the other tests plus a still one and a certified one beside them.
  sscc::Scene scene;
  for (int i = 0; i < 3; ++i) scene.add_object(i == 1 ? certified : f.ccd);
  scene.add_object(f.ccd);
  scene.add_object(certified);
  std::mt19937_64 rng(17);
  int colliding = 0;
  int one_traversal = 0;
  for (int trial = 0; trial < 8; ++trial) {
    std::vector<sscc::ObjectStep> steps = random_steps(rng, 0.3, trial % 2 ? 0.6 : 0.2);
    steps.push_back(steps[0]);  // still, apart from the others
    steps[3].q1 = steps[3].q0;
    steps[3].frame1 = steps[3].frame0;
    steps[3].frame0.translation = steps[3].frame1.translation = Eigen::Vector3d(-8, 0, 0);
    steps.push_back(steps[0]);  // well inside its root certificate
    steps[4].q0 = Eigen::VectorXd::Constant(kModes, 0.1 * certificates.node_radius(0) / 3.0);
    steps[4].q1 = -steps[4].q0;
    steps[4].frame0.translation = steps[4].frame1.translation = Eigen::Vector3d(8, 0, 0);
    if (trial >= 6) {  // one object alone needs a traversal: it gets every thread
      for (int i : {0, 2}) steps[i].q1 = steps[i].q0, steps[i].frame1 = steps[i].frame0;
      steps[1].q0 = 3.0 * steps[1].q0;
    }
    for (sscc::SelfCcdMode mode :
         {sscc::SelfCcdMode::kAllContacts, sscc::SelfCcdMode::kEarliest, sscc::SelfCcdMode::kAnyHit}) {
      for (bool use_certificates : {true, false}) {
        sscc::SceneOptions options;
        options.mode = mode;
        options.use_certificates = use_certificates;
        options.threads = 1;
        const sscc::SceneReport serial = scene.step(steps, options);
        if (mode == sscc::SelfCcdMode::kAllContacts && use_certificates) {
          colliding += serial.collided();
          one_traversal += serial.stats.objects_traversed == 1;
          CHECK(serial.objects[3].outcome == sscc::SelfTestOutcome::kStatic);
          CHECK(serial.objects[4].outcome == sscc::SelfTestOutcome::kCertified);
        }
        for (int threads : {2, 3, 5}) {
          INFO("trial " << trial << " mode " << int(mode) << " certificates " << use_certificates << " threads "
                        << threads);
          options.threads = threads;
          require_same_scene_report(scene.step(steps, options), serial);
        }
      }
    }
  }
  CHECK(colliding >= 3);
  CHECK(one_traversal >= 1);
}

TEST_CASE("scene: an error inside the tasks is the first in task order on every thread count", "[scene][parallel]") {
  // The kernels refuse a zero toi_tolerance when first called, naming their kind. Object 0's
  // world-linear self test (task 0) first calls a vertex-face kernel, object 1's object-frame
  // self test without certificates (task 1, which would traverse on every thread) an edge-edge
  // one: the step must report task 0's error as one thread does.
  const Fixture f;
  sscc::Scene scene;
  scene.add_object(f.ccd, {true, false, sscc::SelfMotion::kWorldLinear});
  scene.add_object(f.ccd, {true, false, sscc::SelfMotion::kObjectFrame});
  std::mt19937_64 rng(1);
  std::vector<sscc::ObjectStep> steps = random_steps(rng, 0.9, 0.0);
  steps.pop_back();
  steps[1].frame0 = steps[1].frame1 = frame(Eigen::Vector3d::UnitZ(), 0.0, Eigen::Vector3d(10, 0, 0));
  sscc::SceneOptions options;
  options.kernel.toi_tolerance = 0.0;
  const auto error = [&](int threads) -> std::string {
    options.threads = threads;
    try {
      scene.step(steps, options);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "no error";
  };
  const std::string serial = error(1);
  REQUIRE_THAT(serial, Catch::Contains("toi_tolerance"));
  for (int threads : {2, 3}) {
    INFO("threads " << threads);
    CHECK(error(threads) == serial);
  }
}
