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

/// Vertex-face CCD: does the point v(t) touch the closed triangle (f0(t), f1(t), f2(t)) for
/// some t in [0, 1], every point moving linearly from its _t0 to its _t1 position?
///   v_t0, f0_t0, f1_t0, f2_t0: the vertex and the triangle's corners at t = 0 (finite).
///   v_t1, f0_t1, f1_t1, f2_t1: the same at t = 1 (finite).
///   options: toi_tolerance finite and > 0 (below kMinToiTolerance it is raised to it);
///            minimum_separation d >= 0 (0: touching, exact; d > 0: conservative).
/// Returns hit = true with toi in [t* - toi_tolerance, t*] for the first contact t* and the
/// barycentric parameters of f1 and f2 at toi; no hit: hit = false, toi = 1, params 0.
/// Throws std::invalid_argument for a NaN or infinite coordinate or an invalid option.
CcdResult vertex_face_ccd(const Eigen::Vector3d& v_t0, const Eigen::Vector3d& f0_t0, const Eigen::Vector3d& f1_t0,
                          const Eigen::Vector3d& f2_t0, const Eigen::Vector3d& v_t1, const Eigen::Vector3d& f0_t1,
                          const Eigen::Vector3d& f1_t1, const Eigen::Vector3d& f2_t1, const CcdOptions& options = {});

/// Edge-edge CCD: do the closed segments (ea0(t), ea1(t)) and (eb0(t), eb1(t)) touch for
/// some t in [0, 1], every point moving linearly from its _t0 to its _t1 position?
///   ea0_t0, ea1_t0, eb0_t0, eb1_t0: the two edges' ends at t = 0 (finite).
///   ea0_t1, ea1_t1, eb0_t1, eb1_t1: the same at t = 1 (finite).
///   options: as for vertex_face_ccd.
/// Returns hit = true with toi in [t* - toi_tolerance, t*] for the first contact t* and the
/// positions along edge a and edge b (each in [0, 1]) at toi; no hit: hit = false, toi = 1,
/// params 0. Parallel and collinear edges are decided exactly like any other. Throws
/// std::invalid_argument for a NaN or infinite coordinate or an invalid option.
CcdResult edge_edge_ccd(const Eigen::Vector3d& ea0_t0, const Eigen::Vector3d& ea1_t0, const Eigen::Vector3d& eb0_t0,
                        const Eigen::Vector3d& eb1_t0, const Eigen::Vector3d& ea0_t1, const Eigen::Vector3d& ea1_t1,
                        const Eigen::Vector3d& eb0_t1, const Eigen::Vector3d& eb1_t1, const CcdOptions& options = {});

/// Exact discrete test: do the closed triangles (a0, a1, a2) and (b0, b1, b2) share a
/// point? Degenerate (zero-area) triangles are handled as the segments or points they are.
bool triangles_intersect(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1, const Eigen::Vector3d& a2,
                         const Eigen::Vector3d& b0, const Eigen::Vector3d& b1, const Eigen::Vector3d& b2);

}  // namespace sscc::ccd
