// The exact reference ("oracle") for continuous collision of linearly moving primitives:
// simple and obviously correct rather than fast. Tests and validation hold the kernels
// against it; it is never on the kernels' path.
//
// Guarantee: exact for rational inputs. The answer (contact or not) and the time of impact
// (as an exact algebraic number) are both exact.
//
// Method (deliberately different from the kernels' own exact fallback, which works with
// projected 2D orientations): the contact times are roots of the coplanarity cubic f(t),
// and at each root the inside test is done in 3D against the triangle normal (vertex-face)
// or by solving for the edge parameters (edge-edge). When f vanishes identically the
// motion is planar, and the first contact is either at t = 0 or where a vertex reaches an
// edge, so the question reduces to point-edge problems, which reduce the same way to
// point-point ones.
#pragma once

#include <optional>

#include "sscc/ccd/exact/polynomial.hpp"

namespace sscc::exact {

/// The earliest contact time, or nothing when the primitives never touch for t in [0, 1].
using ContactTime = std::optional<RealRoot>;

/// Point v against the closed triangle (f0, f1, f2), all moving linearly over t in [0, 1].
ContactTime reference_vertex_face(const Vec3q& v_t0, const Vec3q& f0_t0, const Vec3q& f1_t0, const Vec3q& f2_t0,
                                  const Vec3q& v_t1, const Vec3q& f0_t1, const Vec3q& f1_t1, const Vec3q& f2_t1);

/// Closed segment (ea0, ea1) against closed segment (eb0, eb1), moving linearly.
ContactTime reference_edge_edge(const Vec3q& ea0_t0, const Vec3q& ea1_t0, const Vec3q& eb0_t0, const Vec3q& eb1_t0,
                                const Vec3q& ea0_t1, const Vec3q& ea1_t1, const Vec3q& eb0_t1, const Vec3q& eb1_t1);

}  // namespace sscc::exact
