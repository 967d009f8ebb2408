#include <catch2/catch.hpp>

#include <cmath>

#include "demo/ear_drop.hpp"
#include "demo/modal_dynamics.hpp"
#include "demo/spring_mesh.hpp"
#include "demo/spring_scene.hpp"
#include "sscc/basis/modal_analysis.hpp"
#include "sscc/query/self_ccd.hpp"
#include "support/test_meshes.hpp"

TEST_CASE("modal dynamics: the exact damped oscillator, step after step", "[demo]") {
  const Eigen::Vector2d omega_squared(4.0, 100.0);
  const double zeta = 0.05, dt = 0.013;
  sscc::validation::ModalDynamics m(omega_squared, zeta, dt);
  m.add_impulse(Eigen::Vector2d(1.0, -2.0));  // q(0) = 0, q'(0) = v0
  for (int k = 1; k <= 200; ++k) {
    m.step();
    const double t = k * dt;
    for (int i = 0; i < 2; ++i) {
      const double omega = std::sqrt(omega_squared[i]);
      const double w = omega * std::sqrt(1 - zeta * zeta);
      const double v0 = i == 0 ? 1.0 : -2.0;
      const double q = v0 / w * std::exp(-zeta * omega * t) * std::sin(w * t);
      CHECK(m.q()[i] == Approx(q).margin(1e-12));
    }
  }
  CHECK_THROWS(sscc::validation::ModalDynamics(Eigen::Vector2d(1.0, 0.0), 0.0, 0.01));
  CHECK_THROWS(sscc::validation::ModalDynamics(omega_squared, 1.0, 0.01));
}

TEST_CASE("modal impulse: Phi^T J through the scaled basis", "[demo]") {
  const sscc::TriangleMesh mesh = sscc::test::uv_sphere(4, 6);
  Eigen::MatrixXd phi = Eigen::MatrixXd::Random(3 * mesh.vertex_count(), 3);
  const Eigen::Vector3d weights(2.0, 8.0, 50.0);
  const sscc::SubspaceModel model(mesh, phi, weights);
  const std::vector<int> vertices{1, 4, 7};
  const Eigen::Vector3d total(0.3, -1.2, 2.0);
  Eigen::VectorXd expected = Eigen::VectorXd::Zero(3);
  for (int v : vertices) expected += phi.middleRows<3>(3 * v).transpose() * (total / 3.0);
  CHECK((sscc::validation::modal_impulse(model, vertices, total) - expected).norm() < 1e-12);
  CHECK_THROWS(sscc::validation::modal_impulse(model, {}, total));
}

TEST_CASE("the double-helix spring is one closed tube that does not touch itself", "[demo]") {
  sscc::validation::SpringShape shape;
  shape.rings = 160;
  shape.segments = 8;
  shape.turns = 2;
  const sscc::TriangleMesh spring = sscc::validation::double_helix_spring(shape);
  CHECK(spring.triangle_count() == 2 * shape.rings * shape.segments);
  CHECK(sscc::is_closed_manifold(spring));
  const sscc::SubspaceModel still(spring, Eigen::MatrixXd::Zero(3 * spring.vertex_count(), 1),
                                  Eigen::VectorXd::Ones(1));
  const sscc::SubspaceBvh bvh(still);
  CHECK_FALSE(sscc::SelfCcd(bvh).query_discrete(Eigen::VectorXd::Zero(1)).collided());
  // The coils of the two helices interleave: at the axis' side x = coil radius, the tube
  // meets the plane y = 0 about every half pitch.
  int crossings = 0;
  for (const auto& p : spring.vertices()) crossings += std::fabs(p.y()) < 0.3 * shape.tube_radius && p.x() > 0;
  CHECK(crossings > 0);
  shape.tube_radius = shape.pitch / 3;
  CHECK_THROWS_WITH(sscc::validation::double_helix_spring(shape), Catch::Contains("pitch / 4"));
}

TEST_CASE("demo scenes: seeded, rigid frames, impacts and strikes excite the modes", "[demo]") {
  const sscc::TriangleMesh box = sscc::test::box_surface({1, 0.6, 0.5}, {4, 3, 2});
  sscc::ElasticBasisOptions options;
  options.modes = 6;
  const sscc::ElasticBasis modal = sscc::modal_basis(box, options);
  const sscc::SubspaceModel model(box, modal.basis, modal.weights);
  sscc::validation::EarDropOptions drop_options;
  drop_options.motion.objects = 3;
  drop_options.drop_height_max = 0.3;
  sscc::validation::EarDrop a(model, 300.0, drop_options), b(model, 300.0, drop_options);
  double largest = 0.0;
  for (int k = 0; k < 150; ++k) {
    const auto sa = a.step(), sb = b.step();
    REQUIRE(sa.size() == 3);
    for (int i = 0; i < 3; ++i) {
      CHECK(sa[i].q1 == sb[i].q1);
      CHECK(sa[i].frame1 == sb[i].frame1);
      CHECK(sa[i].q0.size() == 6);
      CHECK((sa[i].frame1.rotation.transpose() * sa[i].frame1.rotation - Eigen::Matrix3d::Identity()).norm() < 1e-12);
      CHECK(sa[i].frame1.translation.y() >= -1e-12);  // the box (lowest y 0) never sinks below the ground
      largest = std::max(largest, sa[i].q1.norm());
    }
  }
  CHECK(a.events() >= 3);
  CHECK(largest > 0.0);

  sscc::validation::SpringSceneOptions spring_options;
  spring_options.strike_interval = 0.2;
  spring_options.initial_compression = 0.1;
  sscc::validation::SpringScene spring(model, 300.0, spring_options);
  // Held at the static compression that shortens the box (height 0.5 along z) by a tenth of
  // its height: the mean z of its top vertices against its bottom ones, then released.
  const auto first = spring.step();
  const std::vector<Eigen::Vector3d> held = model.deformed_positions(first[0].q0);
  double top = 0.0, bottom = 0.0;
  int tops = 0, bottoms = 0;
  for (int v = 0; v < box.vertex_count(); ++v) {
    if (box.vertices()[v].z() >= 0.5 - 0.05 * 0.5) top += held[v].z() - box.vertices()[v].z(), ++tops;
    if (box.vertices()[v].z() <= 0.05 * 0.5) bottom += held[v].z() - box.vertices()[v].z(), ++bottoms;
  }
  CHECK(bottom / bottoms - top / tops == Approx(0.1 * 0.5).epsilon(1e-9));
  CHECK(first[0].q1 != first[0].q0);
  for (int k = 0; k < 60; ++k) spring.step();
  CHECK(spring.events() >= 2);
}
