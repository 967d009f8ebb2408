// Axis-aligned boxes (closed: touching boxes overlap).
#pragma once

#include <Eigen/Core>

#include <cmath>

namespace sscc {

struct Aabb {
  Eigen::Vector3d lo;
  Eigen::Vector3d hi;
  /// The empty box: hull(empty(), b) == b.
  static Aabb empty() { return {Eigen::Vector3d::Constant(INFINITY), Eigen::Vector3d::Constant(-INFINITY)}; }
  bool overlaps(const Aabb& o) const {
    return (lo.array() <= o.hi.array()).all() && (o.lo.array() <= hi.array()).all();
  }
  bool contains(const Eigen::Vector3d& p) const {
    return (lo.array() <= p.array()).all() && (p.array() <= hi.array()).all();
  }
  void add(const Eigen::Vector3d& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
};

}  // namespace sscc
