#include "query/uncertified_work.hpp"

#include <algorithm>
#include <limits>

#include "certificates/near_pair.hpp"
#include "query/descent.hpp"

namespace sscc::detail {

UncertifiedWork::UncertifiedWork(const SubspaceBvh& bvh, const Certificates& certificates)
    : triangles_(std::max(1, bvh.model().mesh().triangle_count())) {
  const auto& nodes = bvh.nodes();
  for (int n = 0; n < static_cast<int>(nodes.size()); ++n) {
    const SubspaceBvh::Node& node = nodes[n];
    if (node.is_leaf()) {
      ends_.emplace_back(certificates.node_radius(n), node.triangle_end - node.triangle_begin);
      continue;
    }
    for (int c = node.first_child; c < node.first_child + node.child_count; ++c) {
      for (int d = c + 1; d < node.first_child + node.child_count; ++d) {
        add_pair(bvh, certificates, c, d, certificates.sibling_radius(c, d),
                 certificates.sibling_pair_certificate(c, d));
      }
    }
  }
  std::sort(ends_.begin(), ends_.end());
  weight_below_.assign(ends_.size() + 1, 0.0);
  for (std::size_t k = 0; k < ends_.size(); ++k) weight_below_[k + 1] = weight_below_[k] + ends_[k].second;
}

void UncertifiedWork::add_pair(const SubspaceBvh& bvh, const Certificates& certificates, int x, int y, double radius,
                               int pair) {
  const int children = pair < 0 ? -1 : certificates.pair_certificate(pair).first_child;
  if (children < 0) {
    add(bvh, x, y, radius);
    return;
  }
  int child = children;
  descend_larger(bvh, x, bvh, y, [&](int a, int b) {
    add_pair(bvh, certificates, a, b, certificates.pair_certificate(child).radius, child);
    ++child;
  });
}

void UncertifiedWork::add(const SubspaceBvh& bvh, int x, int y, double radius) {
  const auto triangles = [&](int n) { return bvh.nodes()[n].triangle_end - bvh.nodes()[n].triangle_begin; };
  ends_.emplace_back(radius, near_at_rest(bvh, x, y) ? triangles(x) + triangles(y) : 1);
}

double UncertifiedWork::fraction(double s) const {
  const auto end = std::upper_bound(ends_.begin(), ends_.end(), std::make_pair(s, std::numeric_limits<double>::max()));
  return weight_below_[static_cast<std::size_t>(end - ends_.begin())] / triangles_;
}

}  // namespace sscc::detail
