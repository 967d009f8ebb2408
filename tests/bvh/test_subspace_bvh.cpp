#include <catch2/catch.hpp>

#include "sscc/bvh/subspace_bvh.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "support/test_meshes.hpp"

TEST_CASE("BVH: structure and bounds hold at sampled configurations", "[bvh]") {
  const sscc::TriangleMesh mesh = sscc::test::uv_sphere(12, 24);
  for (int modes : {1, 9, 27}) {
    INFO(modes << " modes");
    const sscc::SubspaceModel model(mesh, sscc::polynomial_basis(mesh, modes), Eigen::VectorXd::Ones(modes));
    const sscc::SubspaceBvh bvh(model, 3);
    CHECK(bvh.validate(30, 2.0, 4) == "");
    const auto& stats = bvh.build_stats();
    CHECK(stats.leaves > mesh.triangle_count() / sscc::kMaxLeafTriangles);
    CHECK(stats.largest_leaf <= sscc::kMaxLeafTriangles);
    CHECK(stats.depth >= 3);
  }
}

TEST_CASE("BVH: the swept box contains the node along the whole step", "[bvh]") {
  const sscc::TriangleMesh mesh = sscc::test::uv_sphere(8, 16);
  const sscc::SubspaceModel model(mesh, sscc::polynomial_basis(mesh, 27), Eigen::VectorXd::Ones(27));
  const sscc::SubspaceBvh bvh(model);
  std::mt19937_64 rng(9);
  std::normal_distribution<double> normal;
  for (int step = 0; step < 20; ++step) {
    Eigen::VectorXd q0(27), q1(27);
    for (int j = 0; j < 27; ++j) q0[j] = 0.2 * normal(rng), q1[j] = 0.2 * normal(rng);
    const double s = std::max(q0.norm(), q1.norm());
    for (int n = 0; n < static_cast<int>(bvh.nodes().size()); ++n) {
      const sscc::Aabb box = bvh.swept_box(n, q0, q1, s);
      for (double t = 0.0; t <= 1.0; t += 0.125) {
        const Eigen::VectorXd q = (1 - t) * q0 + t * q1;
        for (int i = bvh.nodes()[n].triangle_begin; i < bvh.nodes()[n].triangle_end; ++i) {
          for (int v : mesh.triangles()[bvh.triangle_order()[i]]) CHECK(box.contains(model.position(v, q)));
        }
      }
    }
  }
}
