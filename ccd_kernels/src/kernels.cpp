#include "sscc/ccd/kernels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "contact_params.hpp"
#include "exact/projected_decider.hpp"
#include "filter/coplanar_filter.hpp"
#include "separation/separation_search.hpp"
#include "sscc/ccd/moving_frame.hpp"

namespace sscc::ccd {

const char* to_string(DecidedBy stage) {
  switch (stage) {
    case DecidedBy::kSweptBoxes:
      return "swept-boxes";
    case DecidedBy::kCoplanaritySign:
      return "coplanarity-sign";
    case DecidedBy::kIntervalFilter:
      return "interval-filter";
    case DecidedBy::kExact:
      return "exact";
    case DecidedBy::kSeparationSearch:
      return "separation-search";
  }
  return "unknown";
}

namespace {

/// Relative margin on the swept-box gap when a minimum separation inflates the boxes,
/// covering the rounding of the gap's subtraction.
constexpr double kBoxGapSlack = 1.0 + 1e-12;

const char* name_of(PrimitivePair pair) {
  return pair == PrimitivePair::kVertexFace ? "sscc::ccd::vertex_face_ccd" : "sscc::ccd::edge_edge_ccd";
}

void check_options(PrimitivePair pair, const CcdOptions& options) {
  if (!(options.minimum_separation >= 0.0) || !std::isfinite(options.minimum_separation)) {
    throw std::invalid_argument(std::string(name_of(pair)) + ": minimum_separation must be finite and >= 0");
  }
  if (!(options.toi_tolerance > 0.0) || !std::isfinite(options.toi_tolerance)) {
    throw std::invalid_argument(std::string(name_of(pair)) + ": toi_tolerance must be finite and > 0");
  }
}

enum class Frame : std::uint8_t {
  kFixed,   ///< the coordinates as given
  kMoving,  ///< moving with the four points' mean displacement (moving_frame.hpp)
};

/// Per axis, the bounds over the whole step of the first group of points (the triangle, or
/// edge a) and of the second (the vertex, or edge b).
struct SweptBoxes {
  double lo[2][3];
  double hi[2][3];

  SweptBoxes(const FourPointMotion& m, Frame frame) {
    const int split = m.pair == PrimitivePair::kVertexFace ? 3 : 2;
    for (int k = 0; k < 3; ++k) {
      for (int g = 0; g < 2; ++g) {
        lo[g][k] = INFINITY;
        hi[g][k] = -INFINITY;
      }
      double shift = 0.0;
      if (frame == Frame::kMoving) {
        for (int i = 0; i < 4; ++i) shift += 0.25 * (m.t1[i][k] - m.t0[i][k]);
      }
      for (int i = 0; i < 4; ++i) {
        const int g = i < split ? 0 : 1;
        const double a = m.t0[i][k];
        const double b_lo = frame == Frame::kMoving ? shifted_lower(m.t1[i][k], shift) : m.t1[i][k];
        const double b_hi = frame == Frame::kMoving ? shifted_upper(m.t1[i][k], shift) : m.t1[i][k];
        lo[g][k] = std::min(lo[g][k], std::min(a, b_lo));
        hi[g][k] = std::max(hi[g][k], std::max(a, b_hi));
      }
    }
  }

  /// Whether the boxes, grown by `separation`, are disjoint.
  bool disjoint(double separation) const {
    bool apart = false;  // accumulated without branches: each axis is a coin flip
    if (separation == 0.0) {
      for (int k = 0; k < 3; ++k) apart |= (lo[1][k] > hi[0][k]) | (lo[0][k] > hi[1][k]);
    } else {
      for (int k = 0; k < 3; ++k) {
        apart |= std::max(lo[1][k] - hi[0][k], lo[0][k] - hi[1][k]) > separation * kBoxGapSlack;
      }
    }
    return apart;
  }

  double max_magnitude() const {
    double r = 0.0;
    for (int g = 0; g < 2; ++g) {
      for (int k = 0; k < 3; ++k) r = std::max({r, -lo[g][k], hi[g][k]});
    }
    return r;
  }
};

void check_finite(const FourPointMotion& m) {
  // std::isfinite, not arithmetic, so that no floating-point exception is raised.
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(m.t0[i][k]) || !std::isfinite(m.t1[i][k])) {
        throw std::invalid_argument(std::string(name_of(m.pair)) +
                                    ": non-finite coordinate (NaN or infinity) in the input");
      }
    }
  }
}

CcdResult decide(const FourPointMotion& motion, const CcdOptions& options) {
  check_options(motion.pair, options);
  check_finite(motion);
  const double tolerance = std::max(options.toi_tolerance, kMinToiTolerance);
  CcdResult result;
  const SweptBoxes boxes(motion, Frame::kFixed);
  if (boxes.disjoint(options.minimum_separation)) return result;
  // The moving frame's arithmetic stays far from overflow within the filters' range.
  if (boxes.max_magnitude() <= filter::kFilterMaxMagnitude &&
      SweptBoxes(motion, Frame::kMoving).disjoint(options.minimum_separation)) {
    return result;
  }
  if (options.minimum_separation > 0.0) {
#ifdef SSCC_MUTANT_SEPARATION_3D
    return separation_search(motion, 3.0 * options.minimum_separation, tolerance);
#endif
    return separation_search(motion, options.minimum_separation, tolerance);
  }
  if (boxes.max_magnitude() <= filter::kFilterMaxMagnitude) {
    const filter::FilterOutcome outcome = filter::run_coplanar_filter(motion, tolerance);
    if (outcome.verdict != filter::Verdict::kUndecided) {
      result.decided_by = outcome.stage;
      result.hit = outcome.verdict == filter::Verdict::kContact;
      result.toi = outcome.toi;
    }
    if (outcome.verdict == filter::Verdict::kNoContact) return result;
  }
  if (!result.hit) {
    result.decided_by = DecidedBy::kExact;
    const std::optional<double> first = exact_first_contact(motion, tolerance);
    if (!first) return result;
    result.hit = true;
    result.toi = *first;
  }
  contact_params_at(motion, result.toi, result.params);
  return result;
}

}  // namespace

CcdResult vertex_face_ccd(const Eigen::Vector3d& v_t0, const Eigen::Vector3d& f0_t0, const Eigen::Vector3d& f1_t0,
                          const Eigen::Vector3d& f2_t0, const Eigen::Vector3d& v_t1, const Eigen::Vector3d& f0_t1,
                          const Eigen::Vector3d& f1_t1, const Eigen::Vector3d& f2_t1, const CcdOptions& options) {
  return decide({PrimitivePair::kVertexFace, {f0_t0, f1_t0, f2_t0, v_t0}, {f0_t1, f1_t1, f2_t1, v_t1}}, options);
}

CcdResult edge_edge_ccd(const Eigen::Vector3d& ea0_t0, const Eigen::Vector3d& ea1_t0, const Eigen::Vector3d& eb0_t0,
                        const Eigen::Vector3d& eb1_t0, const Eigen::Vector3d& ea0_t1, const Eigen::Vector3d& ea1_t1,
                        const Eigen::Vector3d& eb0_t1, const Eigen::Vector3d& eb1_t1, const CcdOptions& options) {
  return decide({PrimitivePair::kEdgeEdge, {ea0_t0, ea1_t0, eb0_t0, eb1_t0}, {ea0_t1, ea1_t1, eb0_t1, eb1_t1}},
                options);
}

bool triangles_intersect(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1, const Eigen::Vector3d& a2,
                         const Eigen::Vector3d& b0, const Eigen::Vector3d& b1, const Eigen::Vector3d& b2) {
  // Two closed triangles meet iff an edge of one meets the other (the boundary of their
  // convex intersection lies on their edges). An edge [p, q] meets a still triangle iff a
  // vertex moving from p to q touches it: an exact vertex-face query.
  const Eigen::Vector3d* a[3] = {&a0, &a1, &a2};
  const Eigen::Vector3d* b[3] = {&b0, &b1, &b2};
  for (int side = 0; side < 2; ++side) {
    const Eigen::Vector3d* const* edge = side == 0 ? a : b;
    const Eigen::Vector3d* const* tri = side == 0 ? b : a;
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d& p = *edge[i];
      const Eigen::Vector3d& q = *edge[(i + 1) % 3];
      if (vertex_face_ccd(p, *tri[0], *tri[1], *tri[2], q, *tri[0], *tri[1], *tri[2]).hit) {
        return true;
      }
    }
  }
  return false;
}

}  // namespace sscc::ccd
