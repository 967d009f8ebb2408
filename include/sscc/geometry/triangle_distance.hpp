// Closest points between two triangles in R^3, with barycentric coordinates.
//
// Guarantee: floating point, not exact. The returned points lie on the triangles (up to
// rounding) and are optimal up to rounding when the triangles do not intersect: the minimum
// over the six vertex-triangle and nine segment-segment subproblems, each solved in closed
// form. Intersecting triangles are not detected here (the minimum of the subproblems is then
// larger than the distance, zero); callers that need a lower bound test intersection first.
#pragma once

#include <Eigen/Core>

#include <array>

namespace sscc {

struct TriangleClosestPoints {
  double distance = 0.0;
  Eigen::Vector3d first_weights;   ///< barycentric coordinates on the first triangle
  Eigen::Vector3d second_weights;  ///< on the second
};

/// Closest points of triangles (a0, a1, a2) and (b0, b1, b2), assumed disjoint.
TriangleClosestPoints closest_points_disjoint_triangles(const std::array<Eigen::Vector3d, 3>& a,
                                                        const std::array<Eigen::Vector3d, 3>& b);

}  // namespace sscc
