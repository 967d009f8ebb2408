#include "query/simple_contour.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/scaled_norm.hpp"
#include "query/normal_cone.hpp"

namespace sscc::detail {

namespace {

using Eigen::Vector3d;

/// Margin on the bound of a rounding error made of a few roundings (each within u of the
/// result): a projected box's bound, value - error - pad (and value + error + pad), carries the
/// three roundings of the 3-term dot product and one per subtraction, the second of which can
/// lose up to u |value - error| of the pad (all of it when the pad is below half an ulp), so
/// it needs at least 5u plus terms of order u^2 times sum |axis_i| |p_i|: 4u was short by a
/// first-order term (found by a review); 8u covers it with room. Smaller could leave a box
/// short of the exact projection; larger only pads the boxes more.
constexpr double kDotRounding = 8.0 * kUnitRoundoff;

/// A vertex's or an edge's projected sweep: a box in the (u, w) frame over both ends of the
/// step, padded so that it contains the exact projection.
struct ProjectedBox {
  std::array<double, 2> lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
  void merge(const ProjectedBox& other) {
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], other.lo[k]), hi[k] = std::max(hi[k], other.hi[k]);
  }
  bool meets(const ProjectedBox& other) const {
    return !(hi[0] < other.lo[0] || other.hi[0] < lo[0] || hi[1] < other.lo[1] || other.hi[1] < lo[1]);
  }
};

/// The projection frame and the padding that makes its boxes sound for projection along d.
class ProjectionFrame {
 public:
  /// `extent` bounds the distance between any two points of the cycle during the step.
  ProjectionFrame(const Vector3d& d, double extent) {
    axes_[0] = d.unitOrthogonal();
    axes_[1] = d.cross(axes_[0]);
    for (int k = 0; k < 2; ++k) {
      // |exact (axis . d)|, times the largest distance along d between a vertex and an edge.
      const double leak = std::abs(axes_[k].dot(d)) + kDotRounding * axes_[k].cwiseAbs().dot(d.cwiseAbs());
      leak_pad_[k] = 2.0 * leak * extent;
    }
  }
  ProjectedBox box(const Vector3d& p0, const Vector3d& p1) const {
    ProjectedBox box;
    for (const Vector3d* p : {&p0, &p1}) {
      for (int k = 0; k < 2; ++k) {
        const double value = axes_[k].dot(*p);
        const double error = kDotRounding * axes_[k].cwiseAbs().dot(p->cwiseAbs()) + kUnderflowAllowance;
        box.lo[k] = std::min(box.lo[k], value - error - leak_pad_[k]);
        box.hi[k] = std::max(box.hi[k], value + error + leak_pad_[k]);
      }
    }
    return box;
  }

 private:
  std::array<Vector3d, 2> axes_;
  std::array<double, 2> leak_pad_;
};

/// +1 or -1 when d . ((a - p) x (b - p))(t) certainly keeps that sign over [0, 1], else 0.
int constant_sign(const Vector3d& d, const std::vector<Vector3d>& x0, const std::vector<Vector3d>& x1, int p, int a,
                  int b) {
  const BernsteinNormals n = bernstein_normals(x0[p], x0[a], x0[b], x1[p], x1[a], x1[b]);
  if (certainly_positive(d, n)) return 1;
  if (certainly_positive(-d, n)) return -1;
  return 0;
}

}  // namespace

bool stays_simple_in_projection(const Vector3d& d, const std::vector<DirectedEdge>& chain,
                                const std::vector<Vector3d>& x0, const std::vector<Vector3d>& x1) {
  if (chain.size() < 3) return false;
  Vector3d lo = x0[chain[0][0]], hi = lo;
  for (const DirectedEdge& e : chain) {
    lo = lo.cwiseMin(x0[e[0]]).cwiseMin(x1[e[0]]);
    hi = hi.cwiseMax(x0[e[0]]).cwiseMax(x1[e[0]]);
  }
  // The diagonal, rounded up by a margin far above its few roundings (without the underflow of
  // a plain sum of squares: at coordinates near 1e-160 it would vanish, and the pads with it).
  const Vector3d diagonal = hi - lo;
  const double extent = length3(diagonal.x(), diagonal.y(), diagonal.z()) * (1.0 + 1e-12);
  if (!std::isfinite(extent)) return false;
  const ProjectionFrame frame(d, extent);

  // Each vertex is the start of exactly one edge of a simple cycle: boxes by edge.
  struct EdgeSweep {
    ProjectedBox from, edge;  // the start vertex's box, the edge's
    int index;
  };
  std::vector<EdgeSweep> sweeps(chain.size());
  for (std::size_t i = 0; i < chain.size(); ++i) {
    sweeps[i].from = frame.box(x0[chain[i][0]], x1[chain[i][0]]);
    sweeps[i].edge = sweeps[i].from;
    sweeps[i].edge.merge(frame.box(x0[chain[i][1]], x1[chain[i][1]]));
    sweeps[i].index = static_cast<int>(i);
  }
  std::sort(sweeps.begin(), sweeps.end(),
            [](const EdgeSweep& x, const EdgeSweep& y) { return x.edge.lo[0] < y.edge.lo[0]; });

  // Condition (b) for the start vertex of g against edge f, when their sweeps can meet.
  const auto start_stays_off = [&](const EdgeSweep& g, const EdgeSweep& f) {
    const DirectedEdge& e = chain[f.index];
    const int p = chain[g.index][0];
    if (p == e[0] || p == e[1] || !g.from.meets(f.edge)) return true;
    return constant_sign(d, x0, x1, p, e[0], e[1]) != 0;
  };
  // Condition (a) for two edges without a shared vertex: certified sides at t = 0, no crossing.
  const auto apart_at_start = [&](const DirectedEdge& e, const DirectedEdge& f) {
    const auto side = [&](int p, const DirectedEdge& g) { return certified_orientation(d, x0[p], x0[g[0]], x0[g[1]]); };
    const int f0 = side(f[0], e), f1 = side(f[1], e), e0 = side(e[0], f), e1 = side(e[1], f);
    if (f0 == 0 || f1 == 0 || e0 == 0 || e1 == 0) return false;
#ifdef SSCC_MUTANT_CONTOUR_CROSSING_AT_START
    return true;
#endif
    return f0 == f1 || e0 == e1;
  };

  for (std::size_t i = 0; i < sweeps.size(); ++i) {
    for (std::size_t j = i + 1; j < sweeps.size() && sweeps[j].edge.lo[0] <= sweeps[i].edge.hi[0]; ++j) {
      if (!sweeps[i].edge.meets(sweeps[j].edge)) continue;
      if (!start_stays_off(sweeps[i], sweeps[j]) || !start_stays_off(sweeps[j], sweeps[i])) return false;
      const DirectedEdge& e = chain[sweeps[i].index];
      const DirectedEdge& f = chain[sweeps[j].index];
      const bool share = e[0] == f[0] || e[0] == f[1] || e[1] == f[0] || e[1] == f[1];
      if (!share && !apart_at_start(e, f)) return false;
    }
  }
  return true;
}

}  // namespace sscc::detail
