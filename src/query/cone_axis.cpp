#include "query/cone_axis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sscc::detail {

namespace {

/// Centres shorter than this are no axis: their normals spread over most of the sphere, and
/// normalizing a short vector would amplify its rounding.
constexpr double kShortestCentre = 1e-2;

/// The directions of the finite nonzero normals, scaled before they are normalized (normals
/// of tiny triangles have subnormal squares, whose plain norm errs).
std::vector<Eigen::Vector3d> unit_directions(const std::vector<Eigen::Vector3d>& normals) {
  std::vector<Eigen::Vector3d> units;
  units.reserve(normals.size());
  for (const Eigen::Vector3d& n : normals) {
    const double largest = n.cwiseAbs().maxCoeff();
    if (largest > 0.0 && std::isfinite(largest)) units.push_back((n / largest).normalized());
  }
  return units;
}

double smallest_cosine(const Eigen::Vector3d& d, const std::vector<Eigen::Vector3d>& units) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& n : units) smallest = std::min(smallest, d.dot(n));
  return smallest;
}

}  // namespace

Eigen::Vector3d cone_axis(const std::vector<Eigen::Vector3d>& normals) {
  std::vector<Eigen::Vector3d> units = unit_directions(normals);
  if (units.empty()) return Eigen::Vector3d::Zero();
  std::sort(units.begin(), units.end(), [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& n : units) centre += n;
  centre /= static_cast<double>(units.size());
  for (int k = 1; k <= kConeAxisIterations; ++k) {
    if (!(centre.norm() >= kShortestCentre)) return Eigen::Vector3d::Zero();
    const Eigen::Vector3d axis = centre.normalized();
    // The normal farthest from the axis (the first of equals, in the sorted order).
    const Eigen::Vector3d* farthest = &units.front();
    double smallest = farthest->dot(axis);
    for (const Eigen::Vector3d& n : units) {
      const double cosine = n.dot(axis);
      if (cosine < smallest) {
        farthest = &n;
        smallest = cosine;
      }
    }
    centre += (*farthest - centre) / (k + 1.0);
  }
  if (!(centre.norm() >= kShortestCentre)) return Eigen::Vector3d::Zero();
  return centre.normalized();
}

Eigen::Vector3d axis_to_try(const Eigen::Vector3d& mean, const std::vector<Eigen::Vector3d>& normals) {
  const std::vector<Eigen::Vector3d> units = unit_directions(normals);
  const double along_mean = smallest_cosine(mean, units);
  if (along_mean >= kLargestCosineForAxis) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d axis = cone_axis(normals);
  if (axis.isZero() || !(smallest_cosine(axis, units) > along_mean + kSmallestAxisGain)) return Eigen::Vector3d::Zero();
  return axis;
}

}  // namespace sscc::detail
