// The vertices in the hierarchy's order (hierarchy_vertices.hpp): a permutation that lists
// each leaf's vertices near each other, with each vertex's basis block copied bit for bit (so
// that SubspaceModel::position_pair computes the model's positions from the copy: the model's
// own position_pair is the same function on its own block).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <vector>

#include "certificates/certificate_fixtures.hpp"
#include "query/hierarchy_vertices.hpp"

TEST_CASE("hierarchy vertices: a permutation in the hierarchy's order, with the model's blocks and positions",
          "[query]") {
  // A sphere with one vertex no triangle uses: it still has a place, last.
  sscc::TriangleMesh sphere = sscc::test::uv_sphere(8, 16);
  std::vector<Eigen::Vector3d> vertices = sphere.vertices();
  vertices.push_back(Eigen::Vector3d(3.0, 0.0, 0.0));
  const sscc::TriangleMesh mesh(vertices, sphere.triangles());
  const sscc::SubspaceModel model(mesh, sscc::polynomial_basis(mesh, 27), Eigen::VectorXd::LinSpaced(27, 1.0, 3.0));
  const sscc::SubspaceBvh bvh(model);
  const sscc::detail::HierarchyVertices order(bvh);
  const int count = mesh.vertex_count();
  REQUIRE(order.count() == count);
  std::vector<int> seen(count, 0);
  for (int i = 0; i < count; ++i) {
    const int v = order.vertex(i);
    REQUIRE(v >= 0);
    REQUIRE(v < count);
    REQUIRE(order.rank(v) == i);
    ++seen[v];
    REQUIRE(std::memcmp(order.rows(i), model.vertex_block(v), 3 * 27 * sizeof(double)) == 0);
  }
  REQUIRE(std::count(seen.begin(), seen.end(), 1) == count);
  REQUIRE(order.vertex(count - 1) == count - 1);
  // Ranks follow the first use in the hierarchy's triangle order.
  int next = 0;
  for (int t : bvh.triangle_order()) {
    for (int v : mesh.triangles()[t]) {
      if (order.rank(v) >= next) REQUIRE(order.rank(v) == next++);
    }
  }
  REQUIRE(next == count - 1);
}
