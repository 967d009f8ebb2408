// A mesh that touches itself at rest, its touching pairs excluded: the certificates, every
// query and exhaustive testing answer the same question, and an excluded pair is never
// reported while every other colliding pair is.
#include <catch2/catch.hpp>

#include <cstdio>
#include <random>

#include "brute_force.hpp"
#include "sscc/certificates/certificates.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "sscc/query/self_ccd.hpp"
#include "sscc/scene/scene.hpp"
#include "support/test_meshes.hpp"

namespace {

constexpr int kModes = 27;

struct TouchingModel {
  sscc::TriangleMesh mesh = sscc::test::two_spheres(8, 16, sscc::test::kTwoSpheresOffset);
  sscc::SubspaceModel plain{mesh, sscc::polynomial_basis(mesh, kModes), Eigen::VectorXd::Ones(kModes)};
  sscc::SubspaceModel model = plain.excluding_rest_contacts();
  sscc::SubspaceBvh bvh{model};
  sscc::Certificates certificates = sscc::Certificates::precompute(bvh);
  sscc::SelfCcd ccd{bvh, certificates};
};

Eigen::VectorXd random_q(std::mt19937_64& rng, double amplitude) {
  std::normal_distribution<double> normal;
  Eigen::VectorXd q(kModes);
  for (int j = 0; j < kModes; ++j) q[j] = amplitude * normal(rng) / std::sqrt(double(kModes));
  return q;
}

/// Independent of the library's traversal and feature ownership: every considered pair
/// (neither adjacent nor excluded), all 15 features through the kernels.
std::vector<std::pair<int, int>> brute_force(const sscc::SubspaceModel& model, const Eigen::VectorXd& q0,
                                             const Eigen::VectorXd& q1) {
  const std::vector<Eigen::Vector3d> x0 = model.deformed_positions(q0);
  const std::vector<Eigen::Vector3d> x1 = model.deformed_positions(q1);
  const sscc::TriangleMesh& mesh = model.mesh();
  std::vector<std::pair<int, int>> pairs;
  for (int a = 0; a < mesh.triangle_count(); ++a) {
    for (int b = a + 1; b < mesh.triangle_count(); ++b) {
      if (mesh.adjacent(a, b) || model.excluded_pairs().contains(a, b)) continue;
      if (sscc::validation::triangle_pair_first_contact(x0, x1, mesh.triangles()[a], mesh.triangles()[b]) <= 1.0) {
        pairs.emplace_back(a, b);
      }
    }
  }
  return pairs;
}

std::vector<std::pair<int, int>> pair_list(const sscc::SelfCcdReport& report) {
  std::vector<std::pair<int, int>> pairs;
  for (const auto& p : report.pairs) pairs.emplace_back(p.first, p.second);
  return pairs;
}

}  // namespace

TEST_CASE("excluded pairs: the mesh touches itself at rest, so without the set its root certificate is 0",
          "[query][certificates]") {
  const TouchingModel m;
  REQUIRE(m.model.excluded_pairs().size() >= 8);
  const sscc::SubspaceBvh plain_bvh(m.plain);
  CHECK(sscc::Certificates::precompute(plain_bvh).node_radius(0) == 0.0);
  CHECK(m.certificates.node_radius(0) > 0.0);
  // At rest the discrete query finds exactly the excluded pairs without the set, none with it.
  sscc::SelfCcdOptions no_certificates;
  no_certificates.use_certificates = false;
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(kModes);
  CHECK(pair_list(sscc::SelfCcd(plain_bvh).query_discrete(rest, no_certificates)) == m.model.excluded_pairs().pairs());
  CHECK_FALSE(m.ccd.query_discrete(rest, no_certificates).collided());
  CHECK_FALSE(m.ccd.query_discrete(rest).collided());
}

TEST_CASE("excluded pairs: certificates and queries equal exhaustive testing with the same set", "[query]") {
  const TouchingModel m;
  std::mt19937_64 rng(5);
  sscc::SelfCcdOptions traditional;
  sscc::set_traditional(traditional);
  sscc::SelfCcdOptions one_thread;
  one_thread.threads = 1;
  sscc::SelfCcdOptions cones;  // the cones alone
  sscc::set_traditional(cones);
  cones.use_normal_cones = true;
  int colliding = 0, certified = 0;
  for (double amplitude : {0.2 * m.certificates.node_radius(0), 0.05, 0.2, 0.5}) {
    for (int step = 0; step < 4; ++step) {
      const Eigen::VectorXd q0 = random_q(rng, amplitude);
      const Eigen::VectorXd q1 = q0 + random_q(rng, amplitude);
      INFO("amplitude " << amplitude << " step " << step);
      const sscc::SelfCcdReport all = m.ccd.query_exhaustive(q0, q1);
      const sscc::SelfCcdReport fast = m.ccd.query(q0, q1);
      for (const sscc::SelfCcdReport& other :
           {fast, m.ccd.query(q0, q1, traditional), m.ccd.query(q0, q1, one_thread), m.ccd.query(q0, q1, cones),
            m.ccd.query_positions(m.model.deformed_positions(q0), m.model.deformed_positions(q1))}) {
        CHECK(other.pairs == all.pairs);
        CHECK(other.features == all.features);
      }
      // Every other pair is reported, an excluded one never.
      CHECK(pair_list(all) == brute_force(m.model, q0, q1));
      for (const auto& p : all.pairs) CHECK_FALSE(m.model.excluded_pairs().contains(p.first, p.second));
      colliding += all.collided();
      certified += fast.stats.root_certified;
    }
  }
  CHECK(colliding >= 3);
  CHECK(certified >= 2);
}

TEST_CASE("excluded pairs: a scene's self tests honour the set as the detector does", "[query][scene]") {
  const TouchingModel m;
  sscc::Scene scene;
  for (int i = 0; i < 2; ++i) scene.add_object(m.ccd, {true, false});
  std::mt19937_64 rng(11);
  int colliding = 0;
  for (double amplitude : {0.05, 0.3, 0.5}) {
    std::vector<sscc::ObjectStep> steps(2);
    for (sscc::ObjectStep& step : steps) {
      step.q0 = random_q(rng, amplitude);
      step.q1 = step.q0 + random_q(rng, amplitude);
    }
    const sscc::SceneReport report = scene.step(steps);
    for (int i = 0; i < 2; ++i) {
      const sscc::SelfCcdReport all = m.ccd.query_exhaustive(steps[i].q0, steps[i].q1);
      CHECK(report.objects[i].report.pairs == all.pairs);
      CHECK(report.objects[i].report.features == all.features);
      colliding += all.collided();
    }
  }
  CHECK(colliding >= 2);
}

TEST_CASE("excluded pairs: a certificate file records the set, and a model without it refuses the file",
          "[certificates]") {
  const TouchingModel m;
  const sscc::SubspaceBvh plain_bvh(m.plain);
  const std::string with_path = std::string(SSCC_TEST_OUTPUT_DIR) + "/excluded_with.sscc";
  const std::string without_path = std::string(SSCC_TEST_OUTPUT_DIR) + "/excluded_without.sscc";
  m.certificates.write(with_path);
  sscc::Certificates::precompute(plain_bvh).write(without_path);
  CHECK(sscc::Certificates::read(with_path, m.bvh).node_radius(0) == m.certificates.node_radius(0));
  CHECK_NOTHROW(sscc::Certificates::read(without_path, plain_bvh));
  CHECK_THROWS_AS(sscc::Certificates::read(with_path, plain_bvh), sscc::CertificateFileError);
  CHECK_THROWS_AS(sscc::Certificates::read(without_path, m.bvh), sscc::CertificateFileError);
  CHECK_THROWS_AS(sscc::SelfCcd(plain_bvh, m.certificates), std::invalid_argument);
  // The key depends on the set, not only on its presence.
  const sscc::ExcludedPairs fewer(m.mesh.triangle_count(), {m.model.excluded_pairs().pairs().front()});
  const sscc::SubspaceBvh fewer_bvh(m.plain.excluding(fewer));
  CHECK_THROWS_AS(sscc::Certificates::read(with_path, fewer_bvh), sscc::CertificateFileError);
  std::remove(with_path.c_str());
  std::remove(without_path.c_str());
}
