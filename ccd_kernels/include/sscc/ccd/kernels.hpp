// Continuous collision kernels for primitives whose vertices move linearly over t in [0, 1]:
// vertex-face (a point against a closed triangle) and edge-edge (two closed segments).
//
// Guarantee (minimum separation 0): the contact decision is exact for the given double
// inputs: no false negatives and no false positives, degenerate cases included (motion
// that stays coplanar, multiple roots, parallel or collinear edges, zero motion, zero-area
// triangles, contact exactly at t = 0 or t = 1). Floating-point filters with proven
// rounding-error bounds decide almost every query; whatever they cannot decide goes to
// exact rational arithmetic. The time of impact is never later than the true first
// contact and within the requested tolerance of it. The contact parameters are computed
// in floating point at the reported time and are approximate.
//
// With a minimum separation d > 0 the decision is conservative: never a false negative;
// a false positive only when the distance comes within d (1 + kSeparationRelativeTolerance).
//
// Non-finite coordinates throw std::invalid_argument. Coordinates of any finite magnitude
// are handled; the filters work best for magnitudes between 1e-100 and 1e100.
//
// Thread-safe: the kernels have no state.
#pragma once

#include <Eigen/Core>

#include "sscc/ccd/ccd_types.hpp"

namespace sscc::ccd {

CcdResult vertex_face_ccd(const Eigen::Vector3d& v_t0, const Eigen::Vector3d& f0_t0,
                          const Eigen::Vector3d& f1_t0, const Eigen::Vector3d& f2_t0,
                          const Eigen::Vector3d& v_t1, const Eigen::Vector3d& f0_t1,
                          const Eigen::Vector3d& f1_t1, const Eigen::Vector3d& f2_t1,
                          const CcdOptions& options = {});

CcdResult edge_edge_ccd(const Eigen::Vector3d& ea0_t0, const Eigen::Vector3d& ea1_t0,
                        const Eigen::Vector3d& eb0_t0, const Eigen::Vector3d& eb1_t0,
                        const Eigen::Vector3d& ea0_t1, const Eigen::Vector3d& ea1_t1,
                        const Eigen::Vector3d& eb0_t1, const Eigen::Vector3d& eb1_t1,
                        const CcdOptions& options = {});

/// Exact discrete test: do the closed triangles (a0, a1, a2) and (b0, b1, b2) share a
/// point? Degenerate (zero-area) triangles are handled as the segments or points they are.
bool triangles_intersect(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1,
                         const Eigen::Vector3d& a2, const Eigen::Vector3d& b0,
                         const Eigen::Vector3d& b1, const Eigen::Vector3d& b2);

}  // namespace sscc::ccd
