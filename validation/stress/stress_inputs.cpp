#include "stress_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace sscc::validation {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Vertices of an (n + 1) x (n + 1) unit grid at height z, appended; returns the first index.
int add_grid_vertices(std::vector<Eigen::Vector3d>& vertices, int n, double z) {
  const int first = static_cast<int>(vertices.size());
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) vertices.emplace_back(double(i) / n, double(j) / n, z);
  }
  return first;
}

/// The 2 n^2 triangles of a grid whose vertices start at `first`.
void add_grid_triangles(std::vector<Triangle>& triangles, int n, int first) {
  const auto at = [&](int i, int j) { return first + j * (n + 1) + i; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
}

}  // namespace

TriangleMesh geodesic_sphere(int f) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> corners{{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                                       {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  const std::vector<Triangle> faces{{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                                    {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  std::vector<Eigen::Vector3d> vertices;
  for (const Eigen::Vector3d& c : corners) vertices.push_back(c.normalized());
  // The f - 1 points inside each icosahedron edge (a < b), from a to b.
  std::map<std::pair<int, int>, int> edge_first;
  const auto on_edge = [&](int a, int b, int k) {  // k steps of f from a towards b
    if (k == 0) return a;
    if (k == f) return b;
    const int low = std::min(a, b), high = std::max(a, b);
    auto [it, added] = edge_first.emplace(std::make_pair(low, high), static_cast<int>(vertices.size()));
    if (added) {
      for (int i = 1; i < f; ++i)
        vertices.push_back((corners[low] + (corners[high] - corners[low]) * (double(i) / f)).normalized());
    }
    return it->second + (a == low ? k : f - k) - 1;
  };
  std::vector<Triangle> triangles;
  for (const Triangle& face : faces) {
    const int a = face[0], b = face[1], c = face[2];
    // Point (i, j) of the face: a + (b - a) i / f + (c - a) j / f, i + j <= f.
    std::vector<int> index((f + 1) * (f + 1), -1);
    const auto at = [&](int i, int j) -> int& { return index[j * (f + 1) + i]; };
    for (int j = 0; j <= f; ++j) {
      for (int i = 0; i + j <= f; ++i) {
        if (j == 0) {
          at(i, j) = on_edge(a, b, i);
        } else if (i == 0) {
          at(i, j) = on_edge(a, c, j);
        } else if (i + j == f) {
          at(i, j) = on_edge(b, c, j);
        } else {
          at(i, j) = static_cast<int>(vertices.size());
          vertices.push_back(
              (corners[a] + (corners[b] - corners[a]) * (double(i) / f) + (corners[c] - corners[a]) * (double(j) / f))
                  .normalized());
        }
      }
    }
    for (int j = 0; j < f; ++j) {
      for (int i = 0; i + j < f; ++i) {
        triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        if (i + j + 1 < f) triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  }
  return TriangleMesh(std::move(vertices), std::move(triangles));
}

TriangleMesh stress_sphere(int rings, int segments) {
  std::vector<Eigen::Vector3d> vertices{{0, 0, 1}};
  for (int k = 1; k < rings; ++k) {
    const double polar = kPi * k / rings;
    for (int s = 0; s < segments; ++s) {
      const double azimuth = 2 * kPi * s / segments;
      vertices.emplace_back(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
    }
  }
  vertices.emplace_back(0, 0, -1);
  const int south = static_cast<int>(vertices.size()) - 1;
  const auto ring = [&](int k, int s) { return 1 + (k - 1) * segments + (s % segments); };
  std::vector<Triangle> triangles;
  for (int s = 0; s < segments; ++s) {
    triangles.push_back({0, ring(1, s), ring(1, s + 1)});
    triangles.push_back({south, ring(rings - 1, s + 1), ring(rings - 1, s)});
  }
  for (int k = 1; k + 1 < rings; ++k) {
    for (int s = 0; s < segments; ++s) {
      triangles.push_back({ring(k, s), ring(k + 1, s), ring(k + 1, s + 1)});
      triangles.push_back({ring(k, s), ring(k + 1, s + 1), ring(k, s + 1)});
    }
  }
  return TriangleMesh(std::move(vertices), std::move(triangles));
}

TriangleMesh parallel_grids(int n, double gap) {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Triangle> triangles;
  add_grid_triangles(triangles, n, add_grid_vertices(vertices, n, 0.0));
  add_grid_triangles(triangles, n, add_grid_vertices(vertices, n, gap));
  return TriangleMesh(std::move(vertices), std::move(triangles));
}

TriangleMesh degenerate_triangle_grids(int n, double gap) {
  const TriangleMesh grids = parallel_grids(n, gap);
  std::vector<Eigen::Vector3d> vertices = grids.vertices();
  std::vector<Triangle> triangles = grids.triangles();
  const int row = n + 1;
  // Zero-area triangles: three consecutive vertices of a row (collinear), on both grids.
  for (int grid = 0; grid < 2; ++grid) {
    const int base = grid * row * row + (n / 2) * row;
    for (int i = 0; i + 2 <= n; i += 2) triangles.push_back({base + i, base + i + 1, base + i + 2});
  }
  // A zero-area triangle with two vertices at one position.
  vertices.push_back(vertices[row + 1]);
  triangles.push_back({row + 1, static_cast<int>(vertices.size()) - 1, row + 2});
  // Slivers: vertices pulled to within 1e-9 of their opposite diagonal.
  for (int grid = 0; grid < 2; ++grid) {
    for (int j = 1; j < n; j += 3) {
      const int v = grid * row * row + j * row + j + 1;
      vertices[v].x() = vertices[v].x() - (1.0 / n - 1e-9) * 0.5;
      vertices[v].y() = vertices[v].y() + (1.0 / n - 1e-9) * 0.5;
    }
  }
  return TriangleMesh(std::move(vertices), std::move(triangles));
}

TriangleMesh duplicated_vertex_grids(int n, double gap) {
  const TriangleMesh grids = parallel_grids(n, gap);
  std::vector<Eigen::Vector3d> vertices = grids.vertices();
  std::vector<Triangle> triangles = grids.triangles();
  // A third grid on the upper one, its own vertex indices at the same positions, its
  // triangles split along the other diagonal.
  const int first = static_cast<int>(vertices.size());
  const int row = n + 1;
  for (int v = row * row; v < 2 * row * row; ++v) vertices.push_back(vertices[v]);
  const auto at = [&](int i, int j) { return first + j * row + i; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
      triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return TriangleMesh(std::move(vertices), std::move(triangles));
}

TriangleMesh non_manifold_grids(int n, double gap) {
  const TriangleMesh grids = parallel_grids(n, gap);
  std::vector<Eigen::Vector3d> vertices = grids.vertices();
  std::vector<Triangle> triangles = grids.triangles();
  const int row = n + 1;
  // Fins between the grids on every other row edge of the lower grid: one fin up (third
  // triangle on the edge), and on some a second fin down (fourth).
  for (int j = 1; j < n; j += 2) {
    for (int i = 0; i < n; i += 2) {
      const int a = j * row + i, b = a + 1;
      vertices.push_back(0.5 * (vertices[a] + vertices[b]) + Eigen::Vector3d(0, 0, 0.45 * gap));
      triangles.push_back({a, b, static_cast<int>(vertices.size()) - 1});
      if (i % 4 == 0) {
        vertices.push_back(0.5 * (vertices[a] + vertices[b]) - Eigen::Vector3d(0, 0, 0.45 * gap));
        triangles.push_back({b, a, static_cast<int>(vertices.size()) - 1});
      }
    }
  }
  return TriangleMesh(std::move(vertices), std::move(triangles));
}

TriangleMesh single_triangle() { return TriangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}); }

TriangleMesh vertex_on_face_pair() {
  return TriangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, 0}, {0.5, 0.25, 0.5}, {0.25, 0.5, 0.5}},
                      {{0, 1, 2}, {3, 4, 5}});
}

TriangleMesh edge_on_edge_pair() {
  return TriangleMesh({{0, 0, 0}, {1, 0, 0}, {0.5, 0, -1}, {0.5, -0.5, 0}, {0.5, 0.5, 0}, {0.5, 0, 1}},
                      {{0, 1, 2}, {3, 4, 5}});
}

TriangleMesh transformed(const TriangleMesh& mesh, double scale, const Eigen::Vector3d& offset) {
  std::vector<Eigen::Vector3d> vertices = mesh.vertices();
  for (Eigen::Vector3d& x : vertices) x = scale * x + offset;
  return TriangleMesh(std::move(vertices), mesh.triangles());
}

Eigen::MatrixXd random_basis(int rows, int modes, double size, std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::MatrixXd basis(rows, modes);
  for (int c = 0; c < modes; ++c) {
    for (int i = 0; i < rows; ++i) basis(i, c) = normal(rng);
    basis.col(c) *= size / basis.col(c).cwiseAbs().maxCoeff();
  }
  return basis;
}

Eigen::MatrixXd nearly_dependent_basis(int rows, int modes, double size, double relative, std::mt19937_64& rng) {
  Eigen::MatrixXd basis = random_basis(rows, modes, size, rng);
  for (int c = 1; c < modes; ++c) basis.col(c) = basis.col(0) + relative * basis.col(c);
  return basis;
}

Eigen::VectorXd decade_weights(int modes, double low, double high) {
  Eigen::VectorXd weights(modes);
  for (int i = 0; i < modes; ++i) weights[i] = std::pow(10.0, modes == 1 ? low : low + (high - low) * i / (modes - 1));
  return weights;
}

Eigen::VectorXd random_direction(int modes, std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::VectorXd d(modes);
  for (int i = 0; i < modes; ++i) d[i] = normal(rng);
  return d / d.norm();
}

}  // namespace sscc::validation
