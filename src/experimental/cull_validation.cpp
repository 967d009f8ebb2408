#include "sscc/experimental/cull_validation.hpp"

#include <stdexcept>
#include <string>

namespace sscc::experimental {

namespace {

void count(const std::vector<char>& free, const std::vector<char>& colliding, CullCounts& counts) {
  for (std::size_t n = 0; n < free.size(); ++n) {
    counts.culled += free[n];
    counts.false_culls += free[n] && colliding[n];
  }
  counts.poses_declared_free += free[0];
  counts.poses_falsely_free += free[0] && colliding[0];
}

}  // namespace

CullValidation validate_culling(const SubspaceBvh& bvh, const Certificates& certificates,
                                const CullingPredictor& predictor, const std::vector<Eigen::VectorXd>& q,
                                const std::vector<std::vector<char>>& collisions) {
  certificates.check_belongs_to(bvh);
  const int nodes = static_cast<int>(bvh.nodes().size());
  if (predictor.node_count() != nodes) {
    throw std::invalid_argument("validate_culling: the predictor has " + std::to_string(predictor.node_count()) +
                                " nodes, the hierarchy " + std::to_string(nodes));
  }
  if (collisions.size() != q.size()) {
    throw std::invalid_argument("validate_culling: " + std::to_string(q.size()) + " poses but " +
                                std::to_string(collisions.size()) + " ground truths");
  }
  CullValidation result;
  result.poses = static_cast<int>(q.size());
  result.nodes = nodes;
  for (std::size_t p = 0; p < q.size(); ++p) {
    const std::vector<char>& colliding = collisions[p];
    if (static_cast<int>(colliding.size()) != nodes) {
      throw std::invalid_argument("validate_culling: the ground truth of pose " + std::to_string(p) +
                                  " is not one flag per node");
    }
    for (char c : colliding) result.colliding += c;
    result.colliding_poses += colliding[0];
    const double norm = bvh.model().weighted_norm(q[p]);
    std::vector<char> certified(colliding.size());
    for (int n = 0; n < nodes; ++n) certified[n] = norm < certificates.node_radius(n);
    count(certified, colliding, result.sound);
    count(predictor.predicted_free(q[p]), colliding, result.predicted);
  }
  return result;
}

}  // namespace sscc::experimental
