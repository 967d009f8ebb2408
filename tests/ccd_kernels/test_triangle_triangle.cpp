#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include <gmpxx.h>

#include "sscc/ccd/kernels.hpp"

using V = Eigen::Vector3d;

namespace {

/// Independent reference, sharing nothing with the kernel's edge-against-triangle
/// decomposition: the closed triangles meet iff some point is a convex combination of the
/// vertices of both, i.e. the linear program
///   sum_i alpha_i a_i - sum_j beta_j b_j = 0, sum_i alpha_i = 1, sum_j beta_j = 1, alpha, beta >= 0
/// is feasible. A feasible program has a basic feasible solution, supported on linearly
/// independent columns, so every set of independent columns is solved exactly (rational
/// Gaussian elimination) and its solution's signs checked.
bool reference_intersect(const std::array<V, 3>& a, const std::array<V, 3>& b) {
  std::array<std::array<mpq_class, 5>, 6> column;
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      column[i][k] = mpq_class(a[i][k]);
      column[3 + i][k] = -mpq_class(b[i][k]);
    }
    column[i][3] = 1;
    column[i][4] = 0;
    column[3 + i][3] = 0;
    column[3 + i][4] = 1;
  }
  for (int support = 1; support < 64; ++support) {
    std::vector<int> used;
    for (int c = 0; c < 6; ++c) {
      if (support & (1 << c)) used.push_back(c);
    }
    const int k = static_cast<int>(used.size());
    // Rows: 5 equations over the used columns, right-hand side (0, 0, 0, 1, 1).
    std::vector<std::vector<mpq_class>> m(5, std::vector<mpq_class>(k + 1));
    for (int r = 0; r < 5; ++r) {
      for (int c = 0; c < k; ++c) m[r][c] = column[used[c]][r];
      m[r][k] = r >= 3 ? 1 : 0;
    }
    bool independent = true;
    for (int c = 0; c < k && independent; ++c) {
      int pivot = c;
      while (pivot < 5 && m[pivot][c] == 0) ++pivot;
      if (pivot == 5) {
        independent = false;
        break;
      }
      std::swap(m[c], m[pivot]);
      for (int r = 0; r < 5; ++r) {
        if (r == c || m[r][c] == 0) continue;
        const mpq_class factor = m[r][c] / m[c][c];
        for (int j = c; j <= k; ++j) m[r][j] -= factor * m[c][j];
      }
    }
    if (!independent) continue;
    bool consistent = true;
    for (int r = k; r < 5; ++r) consistent = consistent && m[r][k] == 0;
    bool non_negative = true;
    for (int c = 0; c < k; ++c) non_negative = non_negative && m[c][k] / m[c][c] >= 0;
    if (consistent && non_negative) return true;
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
