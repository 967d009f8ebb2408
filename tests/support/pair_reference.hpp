// The tests' triangle-pair reference on explicit vertex paths: every pair sharing no vertex
// (and not excluded) through all 15 features (validation/brute_force.hpp), and the
// comparison of a query's pairs with it.
#pragma once

#include <catch2/catch.hpp>

#include <Eigen/Core>

#include <cmath>
#include <vector>

#include "brute_force.hpp"
#include "sscc/ccd/kernels.hpp"
#include "sscc/mesh/excluded_pairs.hpp"
#include "sscc/query/self_ccd.hpp"

namespace sscc::test {

/// The earliest time per colliding pair, pairs in (first, second) order, for vertices moving
/// linearly from x0 to x1.
inline std::vector<TrianglePairContact> brute_force_pairs(const TriangleMesh& mesh,
                                                          const std::vector<Eigen::Vector3d>& x0,
                                                          const std::vector<Eigen::Vector3d>& x1,
                                                          const ExcludedPairs& excluded = {}) {
  std::vector<TrianglePairContact> pairs;
  for (int a = 0; a < mesh.triangle_count(); ++a) {
    for (int b = a + 1; b < mesh.triangle_count(); ++b) {
      if (mesh.adjacent(a, b) || excluded.contains(a, b)) continue;
      const double toi = validation::triangle_pair_first_contact(x0, x1, mesh.triangles()[a], mesh.triangles()[b]);
      if (toi <= 1.0) pairs.push_back({a, b, toi});
    }
  }
  return pairs;
}

/// The same pairs, each at a time within the kernels' tolerance of the reference's (both are
/// within it below the first contact, features seen in another order).
inline void require_same_pairs(const std::vector<TrianglePairContact>& found,
                               const std::vector<TrianglePairContact>& expected) {
  REQUIRE(found.size() == expected.size());
  for (std::size_t i = 0; i < found.size(); ++i) {
    CHECK(found[i].first == expected[i].first);
    CHECK(found[i].second == expected[i].second);
    CHECK(std::abs(found[i].toi - expected[i].toi) <= ccd::kDefaultToiTolerance);
  }
}

}  // namespace sscc::test
