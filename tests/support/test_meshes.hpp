// Small meshes generated for tests.
#pragma once

#include <cmath>

#include "sscc/mesh/triangle_mesh.hpp"

namespace sscc::test {

/// A UV sphere of radius 1: `rings` latitude bands, `segments` longitude segments.
inline TriangleMesh uv_sphere(int rings, int segments) {
  std::vector<Eigen::Vector3d> v;
  std::vector<Triangle> t;
  v.emplace_back(0, 0, 1);
  for (int i = 1; i < rings; ++i) {
    const double theta = M_PI * i / rings;
    for (int j = 0; j < segments; ++j) {
      const double phi = 2 * M_PI * j / segments;
      v.emplace_back(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    }
  }
  v.emplace_back(0, 0, -1);
  const int south = static_cast<int>(v.size()) - 1;
  const auto ring = [&](int i, int j) { return 1 + (i - 1) * segments + (j % segments); };
  for (int j = 0; j < segments; ++j) t.push_back({0, ring(1, j), ring(1, j + 1)});
  for (int i = 1; i + 1 < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      t.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      t.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
  }
  for (int j = 0; j < segments; ++j) t.push_back({south, ring(rings - 1, j + 1), ring(rings - 1, j)});
  return TriangleMesh(std::move(v), std::move(t));
}

}  // namespace sscc::test

namespace sscc::test {

/// Two parallel square sheets, [0, 1]^2 at z = 0 and at z = gap, each an n x n grid of
/// square cells split in two triangles; the sheets share no vertex.
inline TriangleMesh parallel_sheets(int n, double gap) {
  std::vector<Eigen::Vector3d> v;
  std::vector<Triangle> t;
  for (int sheet = 0; sheet < 2; ++sheet) {
    const int base = static_cast<int>(v.size());
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; j <= n; ++j) v.emplace_back(double(i) / n, double(j) / n, sheet * gap);
    }
    const auto at = [&](int i, int j) { return base + i * (n + 1) + j; };
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        t.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        t.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  }
  return TriangleMesh(std::move(v), std::move(t));
}

}  // namespace sscc::test
