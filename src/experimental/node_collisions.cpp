#include "sscc/experimental/node_collisions.hpp"

namespace sscc::experimental {

std::vector<char> nodes_holding_pairs(const SubspaceBvh& bvh, const std::vector<TrianglePairContact>& pairs) {
  const std::vector<SubspaceBvh::Node>& nodes = bvh.nodes();
  std::vector<int> position(bvh.triangle_order().size());
  for (std::size_t i = 0; i < position.size(); ++i) position[bvh.triangle_order()[i]] = static_cast<int>(i);
  std::vector<char> holds(nodes.size(), 0);
  for (const TrianglePairContact& pair : pairs) {
    const int a = position[pair.first];
    const int b = position[pair.second];
    // From the root down while one node holds both: children partition their parent's range.
    int n = 0;
    while (true) {
      holds[n] = 1;
      const SubspaceBvh::Node& node = nodes[n];
      if (node.is_leaf()) break;
      int next = -1;
      for (int c = node.first_child; c < node.first_child + node.child_count; ++c) {
        if (nodes[c].triangle_begin <= a && a < nodes[c].triangle_end) next = c;
      }
      if (!(nodes[next].triangle_begin <= b && b < nodes[next].triangle_end)) break;
      n = next;
    }
  }
  return holds;
}

std::vector<char> colliding_nodes(const SubspaceBvh& bvh, const Eigen::VectorXd& q) {
  SelfCcdOptions exact;
  exact.use_certificates = false;
  exact.mode = SelfCcdMode::kAllContacts;
  return nodes_holding_pairs(bvh, SelfCcd(bvh).query_discrete(q, exact).pairs);
}

}  // namespace sscc::experimental
