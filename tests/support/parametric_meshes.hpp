// Meshes sampled from a parametric surface on a grid, and subspace models whose modes move
// them through a sequence of shapes (keyframes): each step between consecutive keyframes
// moves every vertex linearly, as a subspace step does. For tests of self-collision culls on
// folds, pinches and touching coils.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <functional>
#include <vector>

#include "sscc/mesh/triangle_mesh.hpp"
#include "sscc/model/subspace_model.hpp"

namespace sscc::test {

/// A surface point for grid parameters u, v in [0, 1].
using Surface = std::function<Eigen::Vector3d(double u, double v)>;

/// A tube of radius 0.1 around a helix of radius 1 and `pitch` per turn, 2.5 turns: coils
/// touch at pitch 0.2.
inline Surface helix_tube(double pitch) {
  return [pitch](double u, double v) {
    const double phi = 5 * M_PI * u, theta = 2 * M_PI * v;
    const double h = pitch / (2 * M_PI);
    const Eigen::Vector3d centre(std::cos(phi), std::sin(phi), h * phi);
    const Eigen::Vector3d tangent = Eigen::Vector3d(-std::sin(phi), std::cos(phi), h).normalized();
    const Eigen::Vector3d outward(std::cos(phi), std::sin(phi), 0.0);
    const Eigen::Vector3d binormal = tangent.cross(outward);
    return Eigen::Vector3d(centre + 0.1 * (std::cos(theta) * outward + std::sin(theta) * binormal));
  };
}

/// A torus (radii 1 and 0.3) whose tube is pinched around u = 0 by `pinch` (1: shut).
inline Surface pinched_torus(double pinch) {
  return [pinch](double u, double v) {
    const double phi = 2 * M_PI * u, theta = 2 * M_PI * v;
    const double wrapped = std::remainder(phi, 2 * M_PI);
    const double r = 0.3 * (1.0 - pinch * std::exp(-(wrapped * wrapped) / 0.15));
    return Eigen::Vector3d((1 + r * std::cos(theta)) * std::cos(phi), (1 + r * std::cos(theta)) * std::sin(phi),
                           r * std::sin(theta));
  };
}

/// Vertex positions of an nu x nv grid on `surface`; a wrapped direction has no duplicate
/// last row (u = 1 is u = 0).
inline std::vector<Eigen::Vector3d> grid_positions(int nu, int nv, bool wrap_u, bool wrap_v, const Surface& surface) {
  std::vector<Eigen::Vector3d> x;
  const int rows_u = wrap_u ? nu : nu + 1;
  const int rows_v = wrap_v ? nv : nv + 1;
  for (int i = 0; i < rows_u; ++i) {
    for (int j = 0; j < rows_v; ++j) x.push_back(surface(double(i) / nu, double(j) / nv));
  }
  return x;
}

/// The consistently oriented triangles of that grid (two per cell).
inline std::vector<Triangle> grid_triangles(int nu, int nv, bool wrap_u, bool wrap_v) {
  const int rows_v = wrap_v ? nv : nv + 1;
  const auto at = [&](int i, int j) { return (wrap_u ? i % nu : i) * rows_v + (wrap_v ? j % nv : j); };
  std::vector<Triangle> t;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      t.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      t.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return t;
}

/// A model whose rest shape is keyframes[0] and whose mode k - 1 moves it to keyframes[k]
/// (weights 1): q = e_{k-1} is keyframe k, q = 0 keyframe 0.
inline SubspaceModel keyframe_model(std::vector<Triangle> triangles,
                                    const std::vector<std::vector<Eigen::Vector3d>>& keyframes) {
  const int vertices = static_cast<int>(keyframes[0].size());
  const int modes = static_cast<int>(keyframes.size()) - 1;
  Eigen::MatrixXd basis(3 * vertices, modes);
  for (int k = 0; k < modes; ++k) {
    for (int v = 0; v < vertices; ++v) basis.block<3, 1>(3 * v, k) = keyframes[k + 1][v] - keyframes[0][v];
  }
  return SubspaceModel(TriangleMesh(keyframes[0], std::move(triangles)), basis, Eigen::VectorXd::Ones(modes));
}

/// The reduced coordinates of keyframe k of such a model.
inline Eigen::VectorXd keyframe_q(int modes, int k) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(modes);
  if (k > 0) q[k - 1] = 1.0;
  return q;
}

}  // namespace sscc::test
