#include "contact_params.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace sscc::ccd {

namespace {

using Eigen::Vector3d;

double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }

/// Parameter of the point of segment [a, b] closest to p.
double closest_on_segment(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
  const Vector3d d = b - a;
  const double dd = d.squaredNorm();
  return dd > 0.0 ? clamp01((p - a).dot(d) / dd) : 0.0;
}

void triangle_params(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                     const Vector3d& c, double params[2]) {
  // Candidates: the projection into the face (ill-conditioned when the triangle is nearly
  // degenerate) and the closest point on each edge; the nearest one wins.
  double best[2] = {0.0, 0.0};
  double best_distance = INFINITY;
  const auto consider = [&](double u, double v) {
    const double d = (a + u * (b - a) + v * (c - a) - p).squaredNorm();
    if (d < best_distance) {
      best_distance = d;
      best[0] = u;
      best[1] = v;
    }
  };
  const Vector3d n = (b - a).cross(c - a);
  const double nn = n.squaredNorm();
  if (nn > 0.0) {
    const double u = (p - a).cross(c - a).dot(n) / nn;  // weight of b
    const double v = (b - a).cross(p - a).dot(n) / nn;  // weight of c
    if (u >= 0.0 && v >= 0.0 && u + v <= 1.0) consider(u, v);
  }
  const double s_ab = closest_on_segment(p, a, b);
  const double s_bc = closest_on_segment(p, b, c);
  const double s_ca = closest_on_segment(p, c, a);
  consider(s_ab, 0.0);
  consider(1.0 - s_bc, s_bc);
  consider(0.0, 1.0 - s_ca);
  params[0] = best[0];
  params[1] = best[1];
}

void segment_params(const Vector3d& a0, const Vector3d& a1, const Vector3d& b0,
                    const Vector3d& b1, double params[2]) {
  const Vector3d da = a1 - a0;
  const Vector3d db = b1 - b0;
  const Vector3d w = a0 - b0;
  const double aa = da.squaredNorm();
  const double bb = db.squaredNorm();
  const double ab = da.dot(db);
  if (aa == 0.0 && bb == 0.0) {
    params[0] = params[1] = 0.0;
    return;
  }
  if (aa == 0.0) {  // edge a is a point
    params[0] = 0.0;
    params[1] = clamp01(db.dot(w) / bb);
    return;
  }
  if (bb == 0.0) {  // edge b is a point
    params[0] = clamp01(-da.dot(w) / aa);
    params[1] = 0.0;
    return;
  }
  const double denom = aa * bb - ab * ab;
  double s = denom > 0.0 ? clamp01((ab * db.dot(w) - bb * da.dot(w)) / denom) : 0.0;
  double u = (ab * s + db.dot(w)) / bb;
  if (u < 0.0 || u > 1.0) {
    u = clamp01(u);
    s = clamp01((ab * u - da.dot(w)) / aa);
  }
  params[0] = s;
  params[1] = u;
}

}  // namespace

void contact_params_at(const FourPointMotion& motion, double t, double params[2]) {
  Vector3d x[4];
  for (int i = 0; i < 4; ++i) x[i] = (1.0 - t) * motion.t0[i] + t * motion.t1[i];
  // The parameters do not depend on position or scale: centre on x[0] and scale by a power
  // of two to magnitude about 1, so squared cross products can neither overflow nor vanish.
  double magnitude = 0.0;
  for (int i = 1; i < 4; ++i) {
    x[i] -= x[0];
    magnitude = std::max(magnitude, x[i].cwiseAbs().maxCoeff());
  }
  x[0].setZero();
  if (magnitude > 0.0) {
    int exponent = 0;
    std::frexp(magnitude, &exponent);
    const double scale = std::ldexp(1.0, -exponent);
    for (int i = 1; i < 4; ++i) x[i] *= scale;
  }
  if (motion.pair == PrimitivePair::kVertexFace) {
    triangle_params(x[3], x[0], x[1], x[2], params);
  } else {
    segment_params(x[0], x[1], x[2], x[3], params);
  }
}

}  // namespace sscc::ccd
