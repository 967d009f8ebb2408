// Many callers at once: Scene::step called from several threads on one scene whose objects
// share detectors (with certificates and without), each step's report compared with the
// answer of the same step run alone on one thread. Part of the ThreadSanitizer job.
#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <limits>
#include <random>
#include <thread>
#include <vector>

#include "sscc/certificates/certificates.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "sscc/scene/scene.hpp"
#include "support/test_meshes.hpp"

namespace {

constexpr int kModes = 9;
constexpr int kCallers = 4;  // more than this machine's cores: calls interleave
constexpr int kSteps = 12;

/// Four spheres in a square, two sharing a detector with certificates and two one without,
/// each step deforming them (some self-contacts) and closing the square (contacts between
/// them). Step k's amplitude grows with k, so early steps are certified and late ones collide.
std::vector<std::vector<sscc::ObjectStep>> load_steps(int objects) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal;
  std::vector<std::vector<sscc::ObjectStep>> steps(kSteps, std::vector<sscc::ObjectStep>(objects));
  for (int k = 0; k < kSteps; ++k) {
    const double amplitude = 0.05 + 0.1 * k;
    const double closing = 0.05 * k;
    for (int o = 0; o < objects; ++o) {
      sscc::ObjectStep& s = steps[k][o];
      s.q0 = Eigen::VectorXd::Zero(kModes);
      s.q1 = Eigen::VectorXd::Zero(kModes);
      for (int i = 0; i < kModes; ++i) {
        s.q0[i] = amplitude * normal(rng) / 3;
        s.q1[i] = amplitude * normal(rng) / 3;
      }
      const Eigen::Vector3d corner(2.2 * (o % 2), 2.2 * (o / 2), 0.0);
      const Eigen::Vector3d centre(1.1, 1.1, 0.0);
      s.frame0.translation = corner;
      s.frame1.translation = corner + closing * (centre - corner);
      s.frame1.rotation = Eigen::AngleAxisd(0.1 * k, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    }
  }
  return steps;
}

}  // namespace

TEST_CASE("scene: steps from many threads at once on shared detectors equal the serial answers", "[scene][load]") {
  const sscc::TriangleMesh mesh = sscc::test::uv_sphere(6, 10);
  const sscc::SubspaceModel model(mesh, sscc::polynomial_basis(mesh, kModes), Eigen::VectorXd::Ones(kModes));
  const sscc::SubspaceBvh bvh(model);
  const sscc::SelfCcd certified(bvh, sscc::Certificates::precompute(bvh));
  const sscc::SelfCcd plain(bvh);
  sscc::Scene scene;
  scene.add_object(certified);
  scene.add_object(plain);
  scene.add_object(certified);
  scene.add_object(plain);
  const auto steps = load_steps(scene.object_count());

  // The objects follow their frames rigidly (turns of up to 1.1 rad a step here).
  sscc::SceneOptions rigid;
  rigid.max_object_frame_rotation = std::numeric_limits<double>::infinity();
  sscc::SceneOptions serial = rigid;
  serial.threads = 1;
  std::vector<sscc::SceneReport> expected;
  long self_pairs = 0, inter_contacts = 0, certified_objects = 0;
  for (const auto& step : steps) {
    expected.push_back(scene.step(step, serial));
    for (const sscc::ObjectSelfResult& o : expected.back().objects) self_pairs += long(o.report.pairs.size());
    inter_contacts += long(expected.back().contacts.size());
    certified_objects += expected.back().stats.objects_certified;
  }
  // The comparison below means something only if the answers hold contacts of both kinds
  // and the certificates decide some objects.
  REQUIRE(self_pairs > 0);
  REQUIRE(inter_contacts > 0);
  REQUIRE(certified_objects > 0);

  // Each caller runs every step, starting at a different one, on the default thread count
  // (so OpenMP teams run inside concurrent calls).
  std::vector<std::vector<sscc::SceneReport>> got(kCallers, std::vector<sscc::SceneReport>(kSteps));
  std::vector<std::thread> callers;
  for (int c = 0; c < kCallers; ++c) {
    callers.emplace_back([&, c] {
      for (int i = 0; i < kSteps; ++i) {
        const int k = (i + 3 * c) % kSteps;
        got[c][k] = scene.step(steps[k], rigid);
      }
    });
  }
  for (std::thread& t : callers) t.join();
  for (int c = 0; c < kCallers; ++c) {
    for (int k = 0; k < kSteps; ++k) {
      INFO("caller " << c << ", step " << k);
      const sscc::SceneReport& a = expected[k];
      const sscc::SceneReport& b = got[c][k];
      REQUIRE(a.objects.size() == b.objects.size());
      for (std::size_t o = 0; o < a.objects.size(); ++o) {
        CHECK(a.objects[o].outcome == b.objects[o].outcome);
        CHECK(a.objects[o].report.pairs == b.objects[o].report.pairs);
        CHECK(a.objects[o].report.features == b.objects[o].report.features);
      }
      CHECK(a.contacts == b.contacts);
      CHECK(a.features == b.features);
      CHECK(a.earliest_toi == b.earliest_toi);
    }
  }
}
