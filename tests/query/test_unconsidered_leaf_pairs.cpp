// The leaf pairs the cones' traversal skips (unconsidered_leaf_pairs.hpp) against brute force:
// a listed pair holds no considered triangle pair, and without exclusions every leaf pair
// that holds none is listed.
#include <catch2/catch.hpp>

#include <random>
#include <utility>
#include <vector>

#include "query/unconsidered_leaf_pairs.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "support/test_meshes.hpp"

namespace {

constexpr int kModes = 9;

/// Whether leaves a and b hold no pair of triangles the model considers, every pair checked.
bool holds_no_considered_pair(const sscc::SubspaceBvh& bvh, int a, int b) {
  const auto& na = bvh.nodes()[a];
  const auto& nb = bvh.nodes()[b];
  for (int i = na.triangle_begin; i < na.triangle_end; ++i) {
    for (int j = nb.triangle_begin; j < nb.triangle_end; ++j) {
      if (bvh.model().considers(bvh.triangle_order()[i], bvh.triangle_order()[j])) return false;
    }
  }
  return true;
}

/// Every pair of distinct nodes: listed ones are leaves holding no considered pair; with
/// `complete`, every such leaf pair is listed. Returns the ordered pairs listed.
long check_every_pair(const sscc::SubspaceBvh& bvh, bool complete) {
  const sscc::detail::UnconsideredLeafPairs table(bvh);
  const int nodes = static_cast<int>(bvh.nodes().size());
  long listed = 0;
  for (int a = 0; a < nodes; ++a) {
    for (int b = 0; b < nodes; ++b) {
      if (a == b) continue;
      const bool leaves = bvh.nodes()[a].is_leaf() && bvh.nodes()[b].is_leaf();
      const bool none = leaves && holds_no_considered_pair(bvh, a, b);
      if (table.contains(a, b)) {
        ++listed;
        REQUIRE(none);
      } else if (complete) {
        REQUIRE_FALSE(none);
      }
    }
  }
  return listed;
}

}  // namespace

TEST_CASE("unconsidered leaf pairs: listed exactly when no triangle pair is considered", "[unconsidered_leaf_pairs]") {
  const sscc::TriangleMesh mesh = sscc::test::uv_sphere(12, 24);
  const sscc::SubspaceModel model(mesh, sscc::polynomial_basis(mesh, kModes), Eigen::VectorXd::Ones(kModes));
  const sscc::SubspaceBvh bvh(model);
  const long listed = check_every_pair(bvh, true);
  CHECK(listed > 0);  // the fans at the poles and neighbouring leaves elsewhere
}

TEST_CASE("unconsidered leaf pairs: with excluded pairs, listed pairs hold no considered pair",
          "[unconsidered_leaf_pairs]") {
  const sscc::TriangleMesh mesh = sscc::test::uv_sphere(12, 24);
  const sscc::SubspaceModel plain(mesh, sscc::polynomial_basis(mesh, kModes), Eigen::VectorXd::Ones(kModes));
  // Exclude, for a seeded third of the triangles, every non-adjacent triangle within two
  // rings: leaf pairs then hold no considered pair without sharing vertices throughout.
  const auto around = [&](int t) {
    std::vector<int> ring;
    for (int v : mesh.triangles()[t])
      ring.insert(ring.end(), mesh.triangles_of_vertex_begin(v), mesh.triangles_of_vertex_end(v));
    return ring;
  };
  std::mt19937_64 rng(7);
  std::vector<std::pair<int, int>> excluded;
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    if (rng() % 3 != 0) continue;
    for (int w : around(t)) {
      for (int u : around(w)) {
        if (u != t && !mesh.adjacent(t, u)) excluded.emplace_back(t, u);
      }
    }
  }
  const sscc::SubspaceModel model = plain.excluding(sscc::ExcludedPairs(mesh.triangle_count(), excluded));
  const sscc::SubspaceBvh bvh(model);
  const sscc::SubspaceBvh plain_bvh(plain);
  CHECK(check_every_pair(bvh, false) >= check_every_pair(plain_bvh, true));
}
