// Seeded synthetic example poses of a mesh, for tests and demonstrations where no library of
// recorded poses exists.
//
// Each pose is a nonlinear deformation of the rest mesh: random polynomial-mode
// displacements (polynomial_basis.hpp), then a twist about the bounding box's longest axis
// and a bend about its shortest, each by an angle proportional to the position along the
// longest axis:
//   x = c + R_short(beta s) R_long(tau s) (p + U_poly a - c),   s = (p_long - c_long) / h_long,
// with c the bounding box's centre, h_long its half extent along the longest axis (s in
// [-1, 1]), tau and beta uniform in [-twist, twist] and [-bend, bend] per pose, and a the
// modal amplitudes, normal with standard deviation modal_amplitude / sqrt(modes) (so the
// expected ||a||^2 is modal_amplitude^2; U_poly is scaled so that a_i = 1 moves some vertex
// by the box diagonal). Rotations by angles that vary along the mesh are not linear in the
// pose parameters, so the poses span more dimensions than they have parameters: PCA needs
// several components to reproduce them, and large angles fold the mesh onto itself (a bend
// of pi/2 brings the two ends of a bar together).
#pragma once

#include <Eigen/Core>

#include <cstdint>

#include "sscc/mesh/triangle_mesh.hpp"

namespace sscc {

struct ExamplePoseOptions {
  int poses = 40;
  std::uint64_t seed = 1;
  double twist = 0.5;             ///< radians: the largest twist of an end against the centre
  double bend = 0.5;              ///< radians: the largest bend of an end against the centre
  double modal_amplitude = 0.02;  ///< box diagonals: typical size of the polynomial displacement
  int modes = 9;                  ///< polynomial modes displaced (1 to 27)
};

/// options.poses poses of the mesh, 3V x poses, one per column (rows as in
/// example_poses.hpp). The same options give the same poses. Throws std::invalid_argument
/// for a non-positive pose count, negative or non-finite amplitudes, a mode count outside
/// 1..27 or a mesh with no extent.
Eigen::MatrixXd generate_example_poses(const TriangleMesh& mesh, const ExamplePoseOptions& options);

}  // namespace sscc
