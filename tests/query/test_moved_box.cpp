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

Eigen::VectorXd random_unit(std::mt19937_64& rng, int r) {
  std::normal_distribution<double> normal;
  Eigen::VectorXd d(r);
  for (int j = 0; j < r; ++j) d[j] = normal(rng);
  return d.normalized();
}

/// Chains of `count` steps of length `step` from q: every node's box moved from the last
/// step's (as consecutive queries hand them on) holds its computed end positions, and grows
/// by at most `growth` per step. Returns the boxes checked.
long check_chain(const sscc::SubspaceBvh& bvh, Eigen::VectorXd q, double step, int count, double growth,
                 std::mt19937_64& rng) {
  const int r = bvh.model().mode_count();
  std::vector<sscc::Aabb> boxes(bvh.nodes().size());
  for (std::size_t n = 0; n < boxes.size(); ++n) boxes[n] = computed_box(bvh, static_cast<int>(n), q);
  long checked = 0;
  for (int k = 0; k < count; ++k) {
    const Eigen::VectorXd next = q + step * random_unit(rng, r);
    const Eigen::VectorXd delta = next - q;
    const double s = std::max(q.stableNorm(), next.stableNorm());
    for (std::size_t n = 0; n < boxes.size(); ++n) {
      const int node = static_cast<int>(n);
      const sscc::Aabb end =
          sscc::detail::moved_box(boxes[n], bvh.subspace_bound(node), delta, delta.stableNorm(), s, r);
      REQUIRE(holds(end, computed_box(bvh, node, next)));
      // And useful: grown by about the step, not by the node's size.
      REQUIRE(((end.hi - end.lo) - (boxes[n].hi - boxes[n].lo)).maxCoeff() <=
              growth + 4.0 * step * bvh.subspace_bound(node).rate.norm());
      boxes[n] = end;
      ++checked;
    }
    q = next;
  }
  return checked;
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
    long checked = 0;
    for (const double step : {1e-13, 1e-9, 1e-5, 1e-2, 1.0}) {
      INFO("step length " << step);
      checked += check_chain(bvh, 0.5 * random_unit(rng, r), step, 12, 1e-6 * (2.0 + offset), rng);
    }
    CHECK(checked > 1000);
  }
}

TEST_CASE("moved box: holds when large coordinates cancel near the origin (rounding of U q, not of the rest shape)",
          "[query]") {
  // Two modes nearly opposite, coordinates of 1e6 along both: each vertex's U q is a
  // difference of terms 1e6 times larger, whose rounding moves with q even at steps of 1e-13,
  // while the rest positions (about 1e-3) and the step cover none of it.
  const sscc::TriangleMesh sphere = sscc::test::uv_sphere(4, 8);
  std::vector<Eigen::Vector3d> small = sphere.vertices();
  for (Eigen::Vector3d& p : small) p *= 1e-3;
  const sscc::TriangleMesh mesh(small, sphere.triangles());
  std::mt19937_64 rng(67);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd basis(3 * mesh.vertex_count(), 2);
  for (int i = 0; i < basis.rows(); ++i) {
    basis(i, 0) = normal(rng);
    basis(i, 1) = -basis(i, 0) + 1e-6 * normal(rng);
  }
  const sscc::SubspaceModel model(mesh, basis, Eigen::VectorXd::Ones(2));
  const sscc::SubspaceBvh bvh(model);
  long checked = 0;
  for (const double step : {1e-13, 1e-10}) {
    INFO("step length " << step);
    checked += check_chain(bvh, Eigen::Vector2d(1e6, 1e6), step, 40, 1e-6, rng);
  }
  CHECK(checked > 100);
}
