// The meshes and bases the stress suite is built from: each chosen to break something (far
// from the origin, tiny or huge, degenerate triangles, shared positions, non-manifold
// edges; bases of every rank, nearly dependent columns, columns and weights spanning many
// decades). Deterministic: every random choice comes from the seed given.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <random>
#include <vector>

#include "sscc/mesh/triangle_mesh.hpp"

namespace sscc::validation {

/// A closed latitude-longitude sphere of radius 1 about the origin: 2 segments (rings - 1)
/// triangles.
TriangleMesh stress_sphere(int rings, int segments);

/// A geodesic sphere of radius 1 about the origin: each of the icosahedron's 20 faces cut into
/// f^2 triangles, the vertices pushed out onto the sphere: 20 f^2 nearly equal triangles, no
/// slivers (unlike stress_sphere's near its poles), outward-facing.
TriangleMesh geodesic_sphere(int frequency);

/// Two parallel n x n grids of unit size, `gap` apart (z = 0 and z = gap): 4 n^2 triangles.
TriangleMesh parallel_grids(int n, double gap);

/// parallel_grids with degenerate triangles added: zero-area triangles (three collinear
/// vertices; one with a repeated position) and slivers (a vertex 1e-9 from the opposite edge).
TriangleMesh degenerate_triangle_grids(int n, double gap);

/// parallel_grids where the upper grid's vertices are duplicates (same positions, new
/// indices) of a third grid laid on it, so triangles of the two share positions, not indices.
TriangleMesh duplicated_vertex_grids(int n, double gap);

/// parallel_grids with fins: triangles hung on grid edges, so those edges belong to three
/// or four triangles.
TriangleMesh non_manifold_grids(int n, double gap);

/// A single triangle, and the pairs of triangles that touch at rest: a vertex on a face, an
/// edge across an edge.
TriangleMesh single_triangle();
TriangleMesh vertex_on_face_pair();
TriangleMesh edge_on_edge_pair();

/// The mesh moved by `offset` and scaled by `scale` about the origin (scale first).
TriangleMesh transformed(const TriangleMesh& mesh, double scale, const Eigen::Vector3d& offset);

/// Gaussian entries, each column normalised to `size` (largest vertex displacement of order
/// `size` for a unit coordinate).
Eigen::MatrixXd random_basis(int rows, int modes, double size, std::mt19937_64& rng);

/// A random basis whose columns after the first are the first plus `relative` times a random
/// column: rank r in exact arithmetic, nearly r = 1 in floating point.
Eigen::MatrixXd nearly_dependent_basis(int rows, int modes, double size, double relative, std::mt19937_64& rng);

/// Weights 10^(low + (high - low) i / (r - 1)), i = 0..r-1 (10^low for r = 1).
Eigen::VectorXd decade_weights(int modes, double low, double high);

/// A vector of r standard normal entries, normalised to 1 (r > 0).
Eigen::VectorXd random_direction(int modes, std::mt19937_64& rng);

}  // namespace sscc::validation
