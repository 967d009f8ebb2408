#include "query.hpp"

#include <algorithm>
#include <cmath>

#include "sscc/ccd/kernels.hpp"

namespace sscc::validation {

const char* to_string(Kind kind) { return kind == Kind::kVertexFace ? "vertex-face" : "edge-edge"; }

ccd::CcdResult run_kernel(const Query& q, const ccd::CcdOptions& options) {
  const auto& p = q.points;
  if (q.kind == Kind::kVertexFace) {
    return ccd::vertex_face_ccd(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], options);
  }
  return ccd::edge_edge_ccd(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], options);
}

exact::ContactTime run_reference(const Query& q) {
  std::array<exact::Vec3q, 8> r;
  for (int i = 0; i < 8; ++i) r[i] = exact::to_rational(q.points[i][0], q.points[i][1], q.points[i][2]);
  if (q.kind == Kind::kVertexFace) {
    return exact::reference_vertex_face(r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7]);
  }
  return exact::reference_edge_edge(r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7]);
}

double sampled_min_distance(const Query& q, int steps) {
  double best = INFINITY;
  for (int it = 0; it <= steps; ++it) {
    const double t = double(it) / steps;
    Eigen::Vector3d x[4];
    for (int i = 0; i < 4; ++i) x[i] = (1.0 - t) * q.points[i] + t * q.points[i + 4];
    for (int iu = 0; iu <= steps; ++iu) {
      for (int iv = 0; iv <= steps; ++iv) {
        const double u = double(iu) / steps;
        const double v = double(iv) / steps;
        Eigen::Vector3d d;
        if (q.kind == Kind::kVertexFace) {
          if (u + v > 1.0) continue;
          d = x[0] - ((1 - u - v) * x[1] + u * x[2] + v * x[3]);
        } else {
          d = (x[0] + u * (x[1] - x[0])) - (x[2] + v * (x[3] - x[2]));
        }
        best = std::min(best, d.norm());
      }
    }
  }
  return best;
}

}  // namespace sscc::validation
