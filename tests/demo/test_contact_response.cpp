#include <catch2/catch.hpp>

#include <random>

#include "demo/contact_geometry.hpp"
#include "demo/contact_response.hpp"
#include "demo/ear_drop.hpp"
#include "demo/spring_mesh.hpp"
#include "sscc/basis/modal_analysis.hpp"
#include "sscc/scene/scene.hpp"
#include "support/test_meshes.hpp"

namespace {

using sscc::FeatureKind;
using Points = std::array<Eigen::Vector3d, 4>;

}  // namespace

TEST_CASE("contact frame: the contact point and normal at the time of impact", "[demo][response]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    // A vertex falling through the triangle z = 0 at a known point and time, the triangle at rest.
    const Points triangle_and_vertex_at_rest{Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 0),
                                             Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(0, 2, 0)};
    const double b1 = 0.1 + 0.35 * (uniform(rng) + 1), b2 = 0.1 + 0.3 * (uniform(rng) + 1) * (0.9 - b1);
    const Eigen::Vector3d crossing = b1 * triangle_and_vertex_at_rest[2] + b2 * triangle_and_vertex_at_rest[3];
    const double toi = 0.5 + 0.4 * uniform(rng);
    const Eigen::Vector3d drift(uniform(rng), uniform(rng), 0.0);
    const double fall = 1.0 + uniform(rng) * 0.5;
    const bool from_above = trial % 2 == 0;
    const Eigen::Vector3d velocity = drift + Eigen::Vector3d(0, 0, from_above ? -fall : fall);
    Points start = triangle_and_vertex_at_rest, end = triangle_and_vertex_at_rest;
    start[0] = crossing - toi * velocity;
    end[0] = crossing + (1 - toi) * velocity;
    const sscc::validation::ContactFrame f = sscc::validation::contact_frame(FeatureKind::kVertexFace, start, end, toi);
    CHECK(f.weights[0] == 1.0);
    CHECK(-f.weights[2] == Approx(b1).margin(1e-12));
    CHECK(-f.weights[3] == Approx(b2).margin(1e-12));
    CHECK(f.weights[1] + f.weights[2] + f.weights[3] == Approx(-1.0).margin(1e-12));
    CHECK(f.normal.z() == Approx(from_above ? 1.0 : -1.0).margin(1e-12));
    // Positive before, zero at, negative after the time of impact.
    CHECK(sscc::validation::contact_gap(f, start) > 0);
    CHECK(sscc::validation::contact_gap(f, end) < 0);
  }
  // Two edges crossing at s = 0.25 on the first and u = 0.75 on the second.
  const Points start{Eigen::Vector3d(-0.25, 0, 1), Eigen::Vector3d(0.75, 0, 1), Eigen::Vector3d(0, -0.75, 0),
                     Eigen::Vector3d(0, 0.25, 0)};
  Points end = start;
  for (int i = 0; i < 2; ++i) end[i].z() = -1;
  const sscc::validation::ContactFrame f = sscc::validation::contact_frame(FeatureKind::kEdgeEdge, start, end, 0.5);
  CHECK(f.weights[0] == Approx(0.75));
  CHECK(f.weights[1] == Approx(0.25));
  CHECK(f.weights[2] == Approx(-0.25));
  CHECK(f.weights[3] == Approx(-0.75));
  CHECK(f.normal.z() == Approx(1.0));
  CHECK(sscc::validation::contact_gap(f, end) == Approx(-1.0));
}

TEST_CASE("contact response: a drop and a strike end free of interpenetration, using the reported contacts",
          "[demo][response]") {
  // Two soft double-helix springs lying side by side, dropped and then struck: their coils
  // meet each other, and the springs each other.
  sscc::validation::SpringShape shape;
  shape.turns = 2;
  shape.rings = 120;
  shape.segments = 8;
  const sscc::TriangleMesh spring = sscc::validation::double_helix_spring(shape);
  sscc::ElasticBasisOptions options;
  options.modes = 8;
  options.material = {2.0e6, 0.4, 1100.0};
  const sscc::ElasticBasis modal = sscc::modal_basis(spring, options);
  const sscc::SubspaceModel model(spring, modal.basis, modal.weights);
  const sscc::SubspaceBvh bvh(model);
  const sscc::SelfCcd detector(bvh, sscc::Certificates::precompute(bvh));
  const double mass = 1100.0 * sscc::validation::enclosed_volume(spring);

  const auto run = [&](bool respond, long& contacts, int& penetrating_steps) {
    sscc::validation::EarDropOptions drop;
    drop.motion = {2, 0.005, 0.02, 3};
    drop.drop_height_min = 0.3;
    drop.drop_height_max = 0.6;
    drop.spacing = 0.55;
    drop.strike_speed = 30.0;
    drop.strike_wait_min = 0.05;
    drop.strike_wait_max = 0.1;
    sscc::validation::EarDrop scene_motion(model, mass, drop);
    sscc::Scene scene;
    for (int i = 0; i < 2; ++i) scene.add_object(detector);
    contacts = 0;
    penetrating_steps = 0;
    std::vector<Eigen::VectorXd> last;
    for (int k = 0; k < 200; ++k) {
      const std::vector<sscc::ObjectStep> steps = scene_motion.step();
      const sscc::SceneReport report = scene.step(steps);
      if (respond) {
        const sscc::validation::ResponseRecord used = scene_motion.respond(report, steps);
        // The response's constraints are exactly the contacts the step reported.
        REQUIRE(used.self.size() == 2);
        for (int i = 0; i < 2; ++i) CHECK(used.self[i] == report.objects[i].report.features);
        CHECK(used.inter == report.features);
        CHECK(used.ground == 0);
        // The projection never deepens a penetration (in a few modes it may not remove all).
        CHECK(used.residual_penetration <= used.deepest_penetration);
      }
      long found = static_cast<long>(report.features.size());
      for (const auto& o : report.objects) found += static_cast<long>(o.report.features.size());
      contacts += found;
      last = scene_motion.configurations();
      bool penetrating = false;
      for (const Eigen::VectorXd& q : last) penetrating = penetrating || detector.query_discrete(q).collided();
      penetrating_steps += penetrating;
    }
    for (const Eigen::VectorXd& q : last) CHECK_FALSE((respond && detector.query_discrete(q).collided()));
    CHECK(scene_motion.events() >= 4);  // two landings and two strikes at least
  };
  long contacts_free = 0, contacts_responded = 0;
  int penetrating_free = 0, penetrating_responded = 0;
  run(false, contacts_free, penetrating_free);
  run(true, contacts_responded, penetrating_responded);
  // Without a response the coils pass through each other and stay so for many steps.
  CHECK(contacts_free > 0);
  CHECK(penetrating_free > 10);
  CHECK(contacts_responded > 0);
  INFO("steps ending interpenetrating: " << penetrating_responded << " with the response, " << penetrating_free
                                         << " without");
  CHECK(penetrating_responded * 10 <= penetrating_free);
}

TEST_CASE("contact response: a vertex below the ground is pushed out and stops approaching", "[demo][response]") {
  const sscc::TriangleMesh box = sscc::test::box_surface({1, 0.6, 0.5}, {2, 2, 2});
  std::mt19937_64 rng(3);
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::MatrixXd phi(3 * box.vertex_count(), 4);
  for (Eigen::Index i = 0; i < phi.size(); ++i) phi.data()[i] = normal(rng);
  const sscc::SubspaceModel model(box, phi, Eigen::Vector4d(1.0, 2.0, 3.0, 4.0));
  const int vertex = 5;
  for (const bool rigid : {false, true}) {
    sscc::validation::ModalDynamics modes(2.0 * model.weights(), 0.0, 0.01);
    modes.hold_at(Eigen::Vector4d(0.1, -0.2, 0.05, 0.3));
    // Modal velocities that move the vertex down: -Phi_v^T z.
    modes.add_impulse(-phi.middleRows<3>(3 * vertex).transpose() * Eigen::Vector3d::UnitZ());
    sscc::RigidFrame frame;
    frame.translation = Eigen::Vector3d(0.3, -0.1, 0.2);
    Eigen::Vector3d velocity(0.0, 0.0, -2.0);
    const double mass = 3.0, restitution = 0.5;
    const auto world = [&](const Eigen::VectorXd& q) {
      return Eigen::Vector3d(frame.rotation * model.position(vertex, model.scaled_coordinates(q)) + frame.translation);
    };
    const auto vertex_velocity = [&] {
      const Eigen::Vector3d modal = phi.middleRows<3>(3 * vertex) * modes.velocity();
      return Eigen::Vector3d(modal + (rigid ? velocity : Eigen::Vector3d::Zero()));
    };
    const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
    const double ground = world(modes.q()).z() + 0.01;  // the vertex is 1 cm below it
    const double approach = vertex_velocity().z();
    REQUIRE(approach < 0);
    std::vector<sscc::ObjectStep> steps(1);
    steps[0].q0 = steps[0].q1 = modes.q();
    steps[0].frame0 = steps[0].frame1 = frame;
    sscc::SceneReport report;
    report.objects.resize(1);
    sscc::validation::ContactResponseOptions options;
    options.restitution = restitution;
    const sscc::validation::ResponseRecord used = sscc::validation::respond_to_contacts(
        report, steps, {{&model, &modes, &frame, rigid ? &velocity : nullptr, Eigen::Vector3d::Ones(), mass}},
        {{0, vertex, up, ground}}, options);
    CHECK(used.ground == 1);
    CHECK(used.deepest_penetration == Approx(0.01));
    CHECK(used.residual_penetration == Approx(0.0).margin(1e-12));
    CHECK(world(modes.q()).z() == Approx(ground).margin(1e-12));
    CHECK(vertex_velocity().z() == Approx(-restitution * approach).margin(1e-12));
    if (rigid) {
      // The impulse splits between the frame (1 / m) and the modes (|a|^2), as their inverse masses.
      CHECK(velocity.x() == 0.0);
      CHECK(velocity.z() > -2.0);
    }
  }
}
