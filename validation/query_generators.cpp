#include "query_generators.hpp"

#include <cmath>

namespace sscc::validation {

namespace {

using Eigen::Vector3d;

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
int integer(std::mt19937_64& rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
Vector3d grid_point(std::mt19937_64& rng, int range) {
  return Vector3d(integer(rng, -range, range), integer(rng, -range, range), integer(rng, -range, range));
}
double quarter(std::mt19937_64& rng) { return integer(rng, 0, 4) / 4.0; }

/// Positions at t* and velocities -> the query's t = 0 and t = 1 points (exact for dyadics).
Query from_contact(Kind kind, const std::array<Vector3d, 4>& at, const std::array<Vector3d, 4>& velocity,
                   double t_star) {
  Query q{kind, {}};
  for (int i = 0; i < 4; ++i) {
    q.points[i] = at[i] - t_star * velocity[i];
    q.points[i + 4] = at[i] + (1.0 - t_star) * velocity[i];
  }
  return q;
}

Query built_contact(Kind kind, std::mt19937_64& rng) {
  std::array<Vector3d, 4> at;
  std::array<Vector3d, 4> velocity;
  for (auto& v : velocity) v = integer(rng, 0, 3) == 0 ? Vector3d::Zero() : grid_point(rng, 2);
  if (kind == Kind::kVertexFace) {
    // at[0] = vertex; at[1..3] = triangle; the vertex on the face at dyadic barycentrics.
    for (int i = 1; i < 4; ++i) at[i] = grid_point(rng, 4);
    const double u = quarter(rng);
    const double v = quarter(rng) * (1.0 - u);
    at[0] = (1.0 - u - v) * at[1] + u * at[2] + v * at[3];
  } else {
    at[0] = grid_point(rng, 4);
    at[1] = grid_point(rng, 4);
    const Vector3d x = at[0] + quarter(rng) * (at[1] - at[0]);
    const Vector3d d = integer(rng, 0, 3) == 0 ? Vector3d(integer(rng, -2, 2) * (at[1] - at[0])) : grid_point(rng, 3);
    at[2] = x - quarter(rng) * d;
    at[3] = at[2] + d;
  }
  const double t_star = integer(rng, 0, 8) / 8.0;
  return from_contact(kind, at, velocity, t_star);
}

Query grid_query(Kind kind, std::mt19937_64& rng, bool planar) {
  Query q{kind, {}};
  const int flat_axis = integer(rng, 0, 2);
  for (auto& p : q.points) {
    p = grid_point(rng, 2);
    if (planar) p[flat_axis] = 0.0;
  }
  if (integer(rng, 0, 3) == 0) {  // some points do not move
    for (int i = 0; i < 4; ++i) {
      if (integer(rng, 0, 1) == 0) q.points[i + 4] = q.points[i];
    }
  }
  return q;
}

void perturb(Query& q, std::mt19937_64& rng) {
  const int count = integer(rng, 1, 3);
  for (int n = 0; n < count; ++n) {
    double& x = q.points[integer(rng, 0, 7)][integer(rng, 0, 2)];
    if (integer(rng, 0, 1) == 0) {
      const int ulps = integer(rng, 1, 4);
      for (int i = 0; i < ulps; ++i) x = std::nextafter(x, integer(rng, 0, 1) ? INFINITY : -INFINITY);
    } else {
      x += (integer(rng, 0, 1) ? 1.0 : -1.0) * std::ldexp(1.0, -integer(rng, 20, 52));
    }
  }
}

void rescale(Query& q, std::mt19937_64& rng) {
  const int choice = integer(rng, 0, 3);
  const double scale = choice == 0   ? std::ldexp(1.0, integer(rng, -20, 20))
                       : choice == 1 ? std::pow(10.0, integer(rng, -6, 6))
                                     : 1.0;
  for (auto& p : q.points) p *= scale;
}

}  // namespace

Query random_query(Kind kind, std::mt19937_64& rng) {
  Query q{kind, {}};
  for (int i = 0; i < 4; ++i) {
    q.points[i] = Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    q.points[i + 4] = q.points[i] + Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
  }
  return q;
}

Query integer_grid_query(Kind kind, std::mt19937_64& rng, int range) {
  Query q{kind, {}};
  for (auto& p : q.points) p = grid_point(rng, range);
  return q;
}

Query resting_contact_query(Kind kind, std::mt19937_64& rng) {
  Query q{kind, {}};
  for (auto& p : q.points) p = Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), 0.0);
  return q;
}

Query near_degenerate_query(Kind kind, std::mt19937_64& rng) {
  const int family = integer(rng, 0, 2);
  Query q = family == 0 ? built_contact(kind, rng) : grid_query(kind, rng, family == 2);
  if (integer(rng, 0, 1) == 0) perturb(q, rng);
  rescale(q, rng);
  return q;
}

}  // namespace sscc::validation
