#include "fcl_settle.hpp"

#include <algorithm>
#include <iterator>

#include "brute_force.hpp"

namespace sscc::validation {

SettledDisagreements settle_with_exact_kernels(const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& x0,
                                               const std::vector<Eigen::Vector3d>& x1, const PairList& fcl,
                                               const PairList& ours) {
  const auto touches = [&](const std::pair<int, int>& p) {
    return triangle_pair_first_contact(x0, x1, mesh.triangles()[p.first], mesh.triangles()[p.second]) <= 1.0;
  };
  PairList only_fcl, only_ours;
  std::set_difference(fcl.begin(), fcl.end(), ours.begin(), ours.end(), std::back_inserter(only_fcl));
  std::set_difference(ours.begin(), ours.end(), fcl.begin(), fcl.end(), std::back_inserter(only_ours));
  SettledDisagreements s;
  for (const auto& p : only_fcl) (touches(p) ? s.unexplained : s.fcl_false_positives)++;
  for (const auto& p : only_ours) (touches(p) ? s.fcl_false_negatives : s.unexplained)++;
  return s;
}

}  // namespace sscc::validation
