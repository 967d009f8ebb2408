// An estimate, from the certificates alone, of how much of the hierarchy a step of norm s
// leaves to a lazy traversal (which walks the pair certificates): the query computes every
// vertex up front and runs on every thread only when that is most of the mesh. Private to
// the library.
#pragma once

#include <vector>

#include "sscc/bvh/subspace_bvh.hpp"
#include "sscc/certificates/certificates.hpp"

namespace sscc::detail {

/// The open ends of the certificates: the pairs (and leaves) below which the traversal
/// continues uncertified once the norm passes their radius (leaves, sibling pairs without
/// pair certificates, pair certificates without children). Each weighs the triangles under
/// it when its nodes are near at rest (near_pair.hpp), else 1 (one box test, which mostly
/// culls it). Radii below a failing open end are not looked at: the estimate ignores that
/// an ancestor's certificate may still hold, so it can only overstate the work.
class UncertifiedWork {
 public:
  UncertifiedWork(const SubspaceBvh& bvh, const Certificates& certificates);
  /// The weight of the open ends whose radius is at most s, over the triangle count.
  double fraction(double s) const;

 private:
  void add_pair(const SubspaceBvh& bvh, const Certificates& certificates, int x, int y, double radius, int pair);
  void add(const SubspaceBvh& bvh, int x, int y, double radius);

  std::vector<std::pair<double, double>> ends_;  // (radius, weight), by radius
  std::vector<double> weight_below_;             // weight_below_[k]: the weight of ends_[0..k)
  double triangles_ = 1.0;
};

}  // namespace sscc::detail
