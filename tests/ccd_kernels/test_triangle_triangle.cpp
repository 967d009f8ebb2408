#include <catch2/catch.hpp>

#include <random>

#include "sscc/ccd/exact/reference.hpp"
#include "sscc/ccd/kernels.hpp"

using V = Eigen::Vector3d;

namespace {

/// Independent reference: some edge of one triangle meets the other, decided by the
/// exact oracle with the edge as the path of a moving vertex.
bool reference_intersect(const std::array<V, 3>& a, const std::array<V, 3>& b) {
  auto q = [](const V& p) { return sscc::exact::to_rational(p[0], p[1], p[2]); };
  for (int side = 0; side < 2; ++side) {
    const auto& e = side == 0 ? a : b;
    const auto& t = side == 0 ? b : a;
    for (int i = 0; i < 3; ++i) {
      if (sscc::exact::reference_vertex_face(q(e[i]), q(t[0]), q(t[1]), q(t[2]), q(e[(i + 1) % 3]), q(t[0]), q(t[1]),
                                             q(t[2]))) {
        return true;
      }
    }
  }
  return false;
}

}  // namespace

TEST_CASE("discrete triangle-triangle intersection: named cases", "[kernels][discrete]") {
  const V o(0, 0, 0), x(1, 0, 0), y(0, 1, 0);
  const double tiny = 0x1p-60;
  CHECK(sscc::ccd::triangles_intersect(o, x, y, V(0.2, 0.2, -1), V(0.2, 0.2, 1), V(5, 5, 0)));
  CHECK(sscc::ccd::triangles_intersect(o, x, y, V(0.1, 0.1, 0), V(2, 0.1, 0), V(0.1, 2, 0)));
  CHECK_FALSE(sscc::ccd::triangles_intersect(o, x, y, V(1, 1, 0), V(2, 1, 0), V(1, 2, 0)));
  CHECK(sscc::ccd::triangles_intersect(o, x, y, x, V(2, 0, 1), V(2, 1, 1)));
  CHECK(sscc::ccd::triangles_intersect(o, x, y, V(0.25, 0.25, 0), V(1, 1, 1), V(0, 1, 1)));
  CHECK_FALSE(sscc::ccd::triangles_intersect(o, x, y, V(0.25, 0.25, tiny), V(1, 1, 1), V(0, 1, 1)));
  CHECK(sscc::ccd::triangles_intersect(o, x, y, V(0.3, 0.3, -1), V(0.3, 0.3, 1), V(0.3, 0.3, 2)));
}

TEST_CASE("discrete triangle-triangle intersection against the exact reference", "[kernels][discrete]") {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> grid(-2, 2);
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    std::array<V, 3> a, b;
    for (auto* tri : {&a, &b}) {
      for (auto& p : *tri) p = V(grid(rng), grid(rng), grid(rng)) * 0.5;
    }
    if (i % 2 == 0) b[0][2] += 0x1p-50;  // near-touching variants
    const bool expected = reference_intersect(a, b);
    INFO("trial " << i);
    CHECK(sscc::ccd::triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2]) == expected);
    hits += expected ? 1 : 0;
  }
  CHECK(hits > 300);
  CHECK(hits < 2700);
}
