// Polynomial modes (Witkin and Welch 1990): displacements along each axis that are linear
// or quadratic functions of rest position, so everything runs without a finite-element
// model. In order: the 9 linear modes (axis a moved by coordinate b, a-major), then the 18
// quadratic ones (axis a moved by xx, yy, zz, xy, yz, zx). Coordinates are centred on the
// bounding box and divided by its half extent; each mode is then scaled so that q_i = 1
// moves the vertex it moves most by the bounding-box diagonal. Weights are 1.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "sscc/mesh/triangle_mesh.hpp"

namespace sscc {

inline constexpr int kMaxPolynomialModes = 27;

/// The first `modes` polynomial modes (1 to 27) for the mesh's vertices, 3V x modes.
/// Throws std::invalid_argument for a count out of range or a mesh with no extent.
Eigen::MatrixXd polynomial_basis(const TriangleMesh& mesh, int modes);

/// The same polynomial functions (centred and scaled by the mesh's bounding box, not
/// normalised per mode) evaluated at arbitrary points, 3P x modes: the extension of the
/// modes into a volume mesh.
Eigen::MatrixXd polynomial_displacements(const std::vector<Eigen::Vector3d>& points, const TriangleMesh& mesh,
                                         int modes);

}  // namespace sscc
