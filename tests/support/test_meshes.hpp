// Small meshes generated for tests.
#pragma once

#include <array>
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

namespace sscc::test {

/// The closed surface of the box [0, size_x] x [0, size_y] x [0, size_z], outward
/// oriented, each face an even grid of cells[axis] divisions, split in two triangles.
inline TriangleMesh box_surface(const Eigen::Vector3d& size, const std::array<int, 3>& cells) {
  std::vector<Eigen::Vector3d> v;
  std::vector<Triangle> t;
  std::vector<int> index((cells[0] + 1) * (cells[1] + 1) * (cells[2] + 1), -1);
  const auto vertex = [&](const std::array<int, 3>& g) {
    int& id = index[g[0] + (cells[0] + 1) * (g[1] + (cells[1] + 1) * g[2])];
    if (id < 0) {
      id = static_cast<int>(v.size());
      v.emplace_back(size[0] * g[0] / cells[0], size[1] * g[1] / cells[1], size[2] * g[2] / cells[2]);
    }
    return id;
  };
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      for (int i = 0; i < cells[b]; ++i) {
        for (int j = 0; j < cells[c]; ++j) {
          const auto at = [&](int di, int dj) {
            std::array<int, 3> g{};
            g[a] = side ? cells[a] : 0;
            g[b] = i + di;
            g[c] = j + dj;
            return vertex(g);
          };
          const int p00 = at(0, 0), p10 = at(1, 0), p11 = at(1, 1), p01 = at(0, 1);
          if (side) {
            t.push_back({p00, p10, p11});
            t.push_back({p00, p11, p01});
          } else {
            t.push_back({p00, p11, p10});
            t.push_back({p00, p01, p11});
          }
        }
      }
    }
  }
  return TriangleMesh(std::move(v), std::move(t));
}

}  // namespace sscc::test

namespace sscc::test {

/// The offset of two_spheres that the tests use: the spheres cut each other in a small circle.
inline const Eigen::Vector3d kTwoSpheresOffset(1.8713, 0.0371, 0.0237);

/// Two UV spheres of radius 1, the second moved by `offset`, sharing no vertex: closer than 2
/// they cut each other, a mesh that touches itself at rest. An offset off the axes keeps
/// the two spheres' vertex planes apart (along x alone, edges in the plane y = 0 of one
/// cross edges 1e-16 off it of the other: pairs closer than rounding, certificates 0).
inline TriangleMesh two_spheres(int rings, int segments, const Eigen::Vector3d& offset) {
  const TriangleMesh one = uv_sphere(rings, segments);
  std::vector<Eigen::Vector3d> v = one.vertices();
  std::vector<Triangle> t = one.triangles();
  const int base = one.vertex_count();
  for (const Eigen::Vector3d& p : one.vertices()) v.push_back(p + offset);
  for (const Triangle& tri : one.triangles()) t.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
  return TriangleMesh(std::move(v), std::move(t));
}

}  // namespace sscc::test
