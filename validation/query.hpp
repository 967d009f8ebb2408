// One CCD query in both forms: exact rationals (for the reference) and doubles (for the
// kernels). Points in the kernels' argument order.
#pragma once

#include <Eigen/Core>

#include <array>
#include <optional>

#include "sscc/ccd/ccd_types.hpp"
#include "sscc/ccd/exact/reference.hpp"

namespace sscc::validation {

enum class Kind { kVertexFace, kEdgeEdge };
const char* to_string(Kind kind);

struct Query {
  Kind kind = Kind::kVertexFace;
  /// vertex-face: v_t0, f0_t0, f1_t0, f2_t0, v_t1, f0_t1, f1_t1, f2_t1;
  /// edge-edge: ea0_t0, ea1_t0, eb0_t0, eb1_t0, ea0_t1, ea1_t1, eb0_t1, eb1_t1.
  std::array<Eigen::Vector3d, 8> points;
};

ccd::CcdResult run_kernel(const Query& q, const ccd::CcdOptions& options = {});
exact::ContactTime run_reference(const Query& q);

/// Smallest distance between the primitives over a (steps + 1)^3 grid of samples of
/// (t, u, v): an upper bound on the true minimum distance over the step.
double sampled_min_distance(const Query& q, int steps);

}  // namespace sscc::validation
