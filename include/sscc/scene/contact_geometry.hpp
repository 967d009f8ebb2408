// What a contact response needs from one reported feature contact, computed from the
// positions of its four vertices at both ends of the step (each vertex moving linearly, as
// the queries assume): the contact points at the time of impact, as barycentric weights,
// and the contact normal there.
//
// At the time of impact the vertex lies on the triangle (vertex-face) or the two edges cross
// (edge-edge), so the weights are those of the closest points at that time (exact up to the
// rounding of toi and of the closest-point computation, in floating point). The normal is
// the triangle's (vertex-face) or the edges' cross product (edge-edge) at toi, oriented so
// that the first side lay on its positive side at the start of the step: the gap
// n . sum_i w_i x_i is then positive before the contact and negative once the features have
// passed through each other. Degenerate cases (a triangle with no area, parallel edges at
// toi) fall back to the direction between the contact points at the start of the step, then
// to the reverse of their relative motion.
//
// Which positions: those the query's motion is linear in. A SelfCcd report's features in the
// model's frame (x = p + U q at q0 and q1), a PositionCcd report's at the given positions, a
// scene's self contacts in the object's frame (SelfMotion::kObjectFrame) or in the world
// (kWorldLinear), and its contacts between objects in the world.
#pragma once

#include <Eigen/Core>

#include <array>

#include "sscc/mesh/triangle_mesh.hpp"
#include "sscc/query/self_ccd.hpp"

namespace sscc {

struct ContactFrame {
  /// The contact points as weights of the four vertices: vertex-face (1, -b0, -b1, -b2) for
  /// the vertex and the triangle's barycentrics; edge-edge (1 - s, s, -(1 - u), -u) for the
  /// parameters along the first and the second edge. The weights of each side sum to +1 and -1.
  std::array<double, 4> weights{};
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit, from the second side towards the first
};

/// The four vertices of a feature contact, in contact_frame's order: vertex-face (the vertex
/// `first` of `first_mesh`, then the three vertices of triangle `second` of `second_mesh`);
/// edge-edge (the two vertices of edge `first` of `first_mesh`, then those of edge `second`
/// of `second_mesh`, as TriangleMesh::edges() lists them). For a self contact both meshes
/// are the object's. Throws std::out_of_range for an index out of range.
std::array<int, 4> contact_vertices(const TriangleMesh& first_mesh, const TriangleMesh& second_mesh, FeatureKind kind,
                                    int first, int second);

/// `start`, `end`: the four vertices at the two ends of the step, in the order of the weights
/// (the vertex then the triangle, or the first edge then the second); toi in [0, 1].
ContactFrame contact_frame(FeatureKind kind, const std::array<Eigen::Vector3d, 4>& start,
                           const std::array<Eigen::Vector3d, 4>& end, double toi);

/// The signed gap sum_i w_i x_i along the normal for the four vertices at `x`.
double contact_gap(const ContactFrame& frame, const std::array<Eigen::Vector3d, 4>& x);

}  // namespace sscc
