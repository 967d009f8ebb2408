#include <catch2/catch.hpp>

#include "sscc/ccd/kernels.hpp"
#include "sscc/mesh/excluded_pairs.hpp"
#include "support/test_meshes.hpp"

namespace {

/// Every non-adjacent pair of the mesh through the exact discrete test: the reference.
std::vector<std::pair<int, int>> touching_by_all_pairs(const sscc::TriangleMesh& mesh) {
  std::vector<std::pair<int, int>> touching;
  const auto& x = mesh.vertices();
  for (int a = 0; a < mesh.triangle_count(); ++a) {
    for (int b = a + 1; b < mesh.triangle_count(); ++b) {
      if (mesh.adjacent(a, b)) continue;
      const sscc::Triangle& ta = mesh.triangles()[a];
      const sscc::Triangle& tb = mesh.triangles()[b];
      if (sscc::ccd::triangles_intersect(x[ta[0]], x[ta[1]], x[ta[2]], x[tb[0]], x[tb[1]], x[tb[2]])) {
        touching.emplace_back(a, b);
      }
    }
  }
  return touching;
}

}  // namespace

TEST_CASE("excluded pairs: touching_at_rest finds exactly the non-adjacent pairs that meet at rest", "[mesh]") {
  SECTION("two spheres cutting each other") {
    const sscc::TriangleMesh mesh = sscc::test::two_spheres(8, 16, sscc::test::kTwoSpheresOffset);
    const sscc::ExcludedPairs found = sscc::ExcludedPairs::touching_at_rest(mesh);
    const auto expected = touching_by_all_pairs(mesh);
    CHECK(expected.size() >= 8);
    CHECK(found.pairs() == expected);
  }
  SECTION("two coincident sheets (coplanar contact everywhere, edges and vertices on each other)") {
    const sscc::TriangleMesh mesh = sscc::test::parallel_sheets(3, 0.0);
    const sscc::ExcludedPairs found = sscc::ExcludedPairs::touching_at_rest(mesh);
    const auto expected = touching_by_all_pairs(mesh);
    CHECK(expected.size() > 18);  // every triangle meets at least its twin
    CHECK(found.pairs() == expected);
  }
  SECTION("a sphere alone touches nothing") {
    CHECK(sscc::ExcludedPairs::touching_at_rest(sscc::test::uv_sphere(8, 16)).empty());
  }
}

TEST_CASE("excluded pairs: lookup in either order, repeats merged, bad pairs refused", "[mesh]") {
  const sscc::ExcludedPairs set(10, {{3, 7}, {7, 3}, {1, 9}, {3, 2}});
  CHECK(set.size() == 3);
  CHECK(set.pairs() == std::vector<std::pair<int, int>>{{1, 9}, {2, 3}, {3, 7}});
  CHECK(set.triangle_count() == 10);
  for (int a = 0; a < 10; ++a) {
    for (int b = 0; b < 10; ++b) {
      const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
      const bool listed = std::find(set.pairs().begin(), set.pairs().end(), key) != set.pairs().end();
      CHECK(set.contains(a, b) == listed);
    }
  }
  CHECK_FALSE(sscc::ExcludedPairs().contains(0, 1));
  CHECK_THROWS_AS(sscc::ExcludedPairs(4, {{1, 4}}), std::invalid_argument);
  CHECK_THROWS_AS(sscc::ExcludedPairs(4, {{-1, 2}}), std::invalid_argument);
  CHECK_THROWS_AS(sscc::ExcludedPairs(4, {{2, 2}}), std::invalid_argument);
}
