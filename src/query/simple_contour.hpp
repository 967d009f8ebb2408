// The second contour test of the normal-cone cull (query/patch_cull.hpp): that a boundary
// cycle, seen along a fixed direction d, stays one simple closed polygon for the whole step.
// It accepts the contours the star-shaped test (query/contour.hpp) refuses for being jagged
// or non-convex (on the meshes of ../shared/data/meshes, nine in ten of the node boundaries
// whose normals stay in a half-space are simple in projection, one in five star-shaped about
// their vertex mean), at a cost of a sort and a few predicates per boundary edge.
// Private to the library.
//
// LEMMA. Let a cycle of distinct mesh vertices move linearly over t in [0, 1], and P be the
// projection along d. Suppose
//  (a) at t = 0 its projection is a simple closed polygon, and
//  (b) no vertex p ever lies in projection on an edge (a, b) of the cycle with p not in
//      {a, b}: the quadratic d . ((a - p) x (b - p))(t) keeps one strict sign over [0, 1]
//      for every such pair whose projected sweeps can meet.
// Then its projection is a simple closed polygon at every t in [0, 1].
//
// PROOF. Simple polygons form an open set of vertex positions, so the times at which the
// projection is not simple form a closed set; suppose it is not empty and let t* be its least
// element (t* > 0 by (a)). At t* two distinct vertices coincide, or two consecutive edges
// overlap beyond their shared vertex, or two non-consecutive edges meet. In the first case the
// one vertex lies on an edge at the other not containing it; in the second the far end of one
// edge lies on the other. In the third, if no end of either edge lies on the other edge, each
// end lies strictly off the other's line (an end on the line but off the segment would make
// the segments meet only at that end, or be collinear, when an end lies on the other), so the
// edges cross properly, which persists under small motion: they met before t*. Every case puts
// a vertex on an edge not containing it at t*, excluded by (b).
//
// DECIDING (a) AND (b). The projected sweeps are boxes in a frame (u, w) computed orthogonal to
// d: a point lying on an edge in projection along d maps, under the exact projection onto
// (u, w), within |lambda| |(u . d, w . d)| of the edge's image, where lambda (the distance
// along d) is at most the diagonal of the cycle's 3D box over the step; the boxes are padded
// by that and by the rounding of the projections, so pairs whose padded boxes are apart are
// never closer than that. Each remaining vertex-edge pair's quadratic is decided through its
// Bernstein coefficients with certified signs (normal_cone.hpp); at t = 0, two edges without a
// shared vertex whose boxes meet must have every end certified strictly on one side of the
// other's line and not cross. Any uncertain sign refuses.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "query/contour.hpp"

namespace sscc::detail {

/// Whether the boundary `chain` (a simple cycle: is_simple_cycle) projects along d (unit
/// length) to one simple closed polygon at every t in [0, 1], for the positions exactly as
/// given (lemma above). Positions of the chain's vertices must be valid in x0 and x1.
bool stays_simple_in_projection(const Eigen::Vector3d& d, const std::vector<DirectedEdge>& chain,
                                const std::vector<Eigen::Vector3d>& x0, const std::vector<Eigen::Vector3d>& x1);

}  // namespace sscc::detail
