#include "sscc/mesh/triangle_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/scaled_norm.hpp"

namespace sscc {

TriangleMesh::TriangleMesh(std::vector<Eigen::Vector3d> vertices, std::vector<Triangle> triangles)
    : vertices_(std::move(vertices)), triangles_(std::move(triangles)) {
  const int n = vertex_count();
  for (int v = 0; v < n; ++v) {
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(vertices_[v][k])) {
        throw std::invalid_argument("TriangleMesh: vertex " + std::to_string(v) + " has a non-finite coordinate");
      }
    }
  }
  std::vector<std::pair<Edge, int>> half_edges;  // (edge, triangle * 3 + slot)
  half_edges.reserve(3 * triangles_.size());
  for (int t = 0; t < triangle_count(); ++t) {
    const Triangle& tri = triangles_[t];
    for (int k = 0; k < 3; ++k) {
      if (tri[k] < 0 || tri[k] >= n) {
        throw std::invalid_argument("TriangleMesh: triangle " + std::to_string(t) + " has vertex index " +
                                    std::to_string(tri[k]) + " outside [0, " + std::to_string(n) + ")");
      }
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) {
      throw std::invalid_argument("TriangleMesh: triangle " + std::to_string(t) + " repeats a vertex");
    }
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k];
      const int b = tri[(k + 1) % 3];
      half_edges.push_back({{std::min(a, b), std::max(a, b)}, 3 * t + k});
    }
  }
  std::sort(half_edges.begin(), half_edges.end());
  triangle_edges_.resize(triangles_.size());
  for (std::size_t i = 0; i < half_edges.size(); ++i) {
    if (i == 0 || half_edges[i].first != half_edges[i - 1].first) edges_.push_back(half_edges[i].first);
    const int slot = half_edges[i].second;
    triangle_edges_[slot / 3][slot % 3] = static_cast<int>(edges_.size()) - 1;
  }
  vertex_triangle_offsets_.assign(n + 1, 0);
  for (const Triangle& tri : triangles_) {
    for (int v : tri) ++vertex_triangle_offsets_[v + 1];
  }
  for (int v = 0; v < n; ++v) vertex_triangle_offsets_[v + 1] += vertex_triangle_offsets_[v];
  vertex_triangles_.resize(3 * triangles_.size());
  std::vector<int> fill(vertex_triangle_offsets_.begin(), vertex_triangle_offsets_.end() - 1);
  for (int t = 0; t < triangle_count(); ++t) {
    for (int v : triangles_[t]) vertex_triangles_[fill[v]++] = t;
  }
  // half_edges is sorted by edge: each edge's triangles are consecutive there.
  edge_triangle_offsets_.assign(edges_.size() + 1, 0);
  edge_triangles_.reserve(half_edges.size());
  for (std::size_t i = 0; i < half_edges.size(); ++i) {
    const int t = half_edges[i].second / 3;
    edge_triangles_.push_back(t);
    ++edge_triangle_offsets_[triangle_edges_[t][half_edges[i].second % 3] + 1];
  }
  for (std::size_t e = 0; e < edges_.size(); ++e) edge_triangle_offsets_[e + 1] += edge_triangle_offsets_[e];
}

Aabb TriangleMesh::bounding_box() const {
  Aabb box = Aabb::empty();
  for (const auto& v : vertices_) box.add(v);
  return box;
}

double TriangleMesh::bounding_box_diagonal() const {
  if (vertices_.empty()) return 0.0;
  const Aabb box = bounding_box();
  // Scaled: the squares of extents above about 1e154 overflow (a mesh in those units is rare,
  // not invalid).
  const Eigen::Vector3d extent = box.hi - box.lo;
  return detail::length3(extent.x(), extent.y(), extent.z());
}

}  // namespace sscc
