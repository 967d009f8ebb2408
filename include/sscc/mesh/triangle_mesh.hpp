// A triangle mesh with the connectivity collision queries need: each triangle's vertices
// and edges, the unique edges, and the triangles around each vertex. Two triangles are
// adjacent when they share a vertex; adjacent pairs are never reported as colliding.
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

#include "sscc/geometry/aabb.hpp"

namespace sscc {

using Triangle = std::array<int, 3>;  ///< vertex indices
using Edge = std::array<int, 2>;      ///< vertex indices, first < second

class TriangleMesh {
 public:
  /// Throws std::invalid_argument for a non-finite coordinate, a vertex index out of range,
  /// or a triangle that repeats a vertex.
  TriangleMesh(std::vector<Eigen::Vector3d> vertices, std::vector<Triangle> triangles);

  int vertex_count() const { return static_cast<int>(vertices_.size()); }
  int triangle_count() const { return static_cast<int>(triangles_.size()); }
  const std::vector<Eigen::Vector3d>& vertices() const { return vertices_; }
  const std::vector<Triangle>& triangles() const { return triangles_; }
  /// The unique edges, sorted.
  const std::vector<Edge>& edges() const { return edges_; }
  /// Indices into edges() of triangle t's edges (v0 v1), (v1 v2), (v2 v0).
  const std::array<int, 3>& triangle_edges(int t) const { return triangle_edges_[t]; }
  // Inline: the collision queries call these in their innermost loops.
  /// The triangles that contain vertex v.
  const int* triangles_of_vertex_begin(int v) const { return vertex_triangles_.data() + vertex_triangle_offsets_[v]; }
  const int* triangles_of_vertex_end(int v) const { return vertex_triangles_.data() + vertex_triangle_offsets_[v + 1]; }
  /// The triangles that contain edge e (two on a closed manifold).
  const int* triangles_of_edge_begin(int e) const { return edge_triangles_.data() + edge_triangle_offsets_[e]; }
  const int* triangles_of_edge_end(int e) const { return edge_triangles_.data() + edge_triangle_offsets_[e + 1]; }
  /// Whether triangles a and b share a vertex (a triangle is adjacent to itself).
  bool adjacent(int a, int b) const {
    const Triangle& x = triangles_[a];
    const Triangle& y = triangles_[b];
    // Nine comparisons or-ed bitwise, without branches: the traversal asks this for every
    // triangle pair it meets, and the answer is rarely known before the last comparison.
    int shared = 0;
    for (int i = 0; i < 3; ++i) {
      shared |= static_cast<int>(x[i] == y[0]) | static_cast<int>(x[i] == y[1]) | static_cast<int>(x[i] == y[2]);
    }
    return shared != 0;
  }
  /// The rest positions' bounding box (empty for no vertices).
  Aabb bounding_box() const;
  /// Length of the diagonal of the rest positions' bounding box (0 for no vertices).
  double bounding_box_diagonal() const;

 private:
  std::vector<Eigen::Vector3d> vertices_;
  std::vector<Triangle> triangles_;
  std::vector<Edge> edges_;
  std::vector<std::array<int, 3>> triangle_edges_;
  std::vector<int> vertex_triangle_offsets_;  // CSR: triangles of vertex v are
  std::vector<int> vertex_triangles_;         // [offsets[v], offsets[v + 1])
  std::vector<int> edge_triangle_offsets_;    // likewise for edges
  std::vector<int> edge_triangles_;
};

}  // namespace sscc
