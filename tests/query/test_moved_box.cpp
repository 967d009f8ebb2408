// The box of a node's end positions moved from a box of its start positions (moved_box.hpp),
// against the positions the model computes: along chains of steps from 1e-13 to 1 of the
// coordinates' scale, each step's box moved from the last one's (as consecutive queries hand
// them on), on a mesh far from the origin, where the positions' rounding outweighs small
// steps.
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include "query/moved_box.hpp"
#include "sscc/bvh/subspace_bvh.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "support/test_meshes.hpp"

namespace {

/// The box of node n's vertices at scaled coordinates q_hat, as the model computes them.
sscc::Aabb computed_box(const sscc::SubspaceBvh& bvh, int n, const Eigen::VectorXd& q_hat) {
  const sscc::SubspaceBvh::Node& node = bvh.nodes()[n];
  sscc::Aabb box = sscc::Aabb::empty();
  for (int i = node.triangle_begin; i < node.triangle_end; ++i) {
    for (int v : bvh.model().mesh().triangles()[bvh.triangle_order()[i]]) box.add(bvh.model().position(v, q_hat));
  }
  return box;
}

bool holds(const sscc::Aabb& outer, const sscc::Aabb& inner) {
  return (outer.lo.array() <= inner.lo.array()).all() && (inner.hi.array() <= outer.hi.array()).all();
}

}  // namespace

TEST_CASE("moved box: holds the node's computed end positions along chains of steps of every size", "[query]") {
  const sscc::TriangleMesh sphere = sscc::test::uv_sphere(8, 16);
  const int r = 27;
  const Eigen::MatrixXd basis = sscc::polynomial_basis(sphere, r);
  for (const double offset : {0.0, 1e6}) {
    INFO("mesh moved by " << offset);
    std::vector<Eigen::Vector3d> moved = sphere.vertices();
    for (Eigen::Vector3d& p : moved) p += Eigen::Vector3d(offset, -0.5 * offset, 0.25 * offset);
    const sscc::TriangleMesh mesh(moved, sphere.triangles());
    const sscc::SubspaceModel model(mesh, basis, Eigen::VectorXd::Ones(r));  // scaled coordinates are q
    const sscc::SubspaceBvh bvh(model);
    std::mt19937_64 rng(61);
    std::normal_distribution<double> normal;
    const auto random_unit = [&] {
      Eigen::VectorXd d(r);
      for (int j = 0; j < r; ++j) d[j] = normal(rng);
      return Eigen::VectorXd(d.normalized());
    };
    long checked = 0;
    for (const double step : {1e-13, 1e-9, 1e-5, 1e-2, 1.0}) {
      INFO("step length " << step);
      Eigen::VectorXd q = 0.5 * random_unit();
      std::vector<sscc::Aabb> boxes(bvh.nodes().size());
      for (std::size_t n = 0; n < boxes.size(); ++n) boxes[n] = computed_box(bvh, static_cast<int>(n), q);
      for (int k = 0; k < 12; ++k) {
        const Eigen::VectorXd next = q + step * random_unit();
        const Eigen::VectorXd delta = next - q;
        const double s = std::max(q.stableNorm(), next.stableNorm());
        for (std::size_t n = 0; n < boxes.size(); ++n) {
          const int node = static_cast<int>(n);
          const sscc::Aabb end =
              sscc::detail::moved_box(boxes[n], bvh.subspace_bound(node), delta, delta.stableNorm(), s, r);
          const sscc::Aabb exact = computed_box(bvh, node, next);
          REQUIRE(holds(end, exact));
          // And useful: grown by about the step, not by the node's size.
          const Eigen::Vector3d size = boxes[n].hi - boxes[n].lo;
          const double allowed = 1e-6 * (size.norm() + offset) + 4.0 * step * bvh.subspace_bound(node).rate.norm();
          REQUIRE(((end.hi - end.lo) - size).maxCoeff() <= allowed);
          boxes[n] = end;  // the next step starts from this bound, as the queries chain them
          ++checked;
        }
        q = next;
      }
    }
    CHECK(checked > 1000);
  }
}
