#include "query/contour.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "query/normal_cone.hpp"

namespace sscc::detail {

std::vector<DirectedEdge> boundary_chain(std::vector<DirectedEdge> edges) {
  // Key each edge by its ordered vertices; the sign says which way it runs.
  std::vector<std::pair<DirectedEdge, int>> signed_edges;
  signed_edges.reserve(edges.size());
  for (const DirectedEdge& e : edges) {
    if (e[0] < e[1])
      signed_edges.push_back({e, 1});
    else
      signed_edges.push_back({{e[1], e[0]}, -1});
  }
  std::sort(signed_edges.begin(), signed_edges.end());
  std::vector<DirectedEdge> chain;
  for (std::size_t i = 0; i < signed_edges.size();) {
    std::size_t j = i;
    int net = 0;
    for (; j < signed_edges.size() && signed_edges[j].first == signed_edges[i].first; ++j)
      net += signed_edges[j].second;
    const DirectedEdge& key = signed_edges[i].first;
    for (int k = 0; k < std::abs(net); ++k) chain.push_back(net > 0 ? key : DirectedEdge{key[1], key[0]});
    i = j;
  }
  std::sort(chain.begin(), chain.end());
  return chain;
}

bool is_simple_cycle(const std::vector<DirectedEdge>& chain) {
  if (chain.empty()) return false;
  std::vector<DirectedEdge> by_from = chain;
  std::sort(by_from.begin(), by_from.end());
  std::vector<int> targets;
  targets.reserve(chain.size());
  for (std::size_t i = 0; i < by_from.size(); ++i) {
    if (i > 0 && by_from[i][0] == by_from[i - 1][0]) return false;  // two edges leave one vertex
    targets.push_back(by_from[i][1]);
  }
  std::sort(targets.begin(), targets.end());
  if (std::adjacent_find(targets.begin(), targets.end()) != targets.end()) return false;  // two enter one
  // Every vertex left once and entered once: the chain is disjoint cycles. One cycle when the
  // walk from the first edge takes every edge before it returns.
  const auto successor = [&](int v) {
    const auto it = std::lower_bound(by_from.begin(), by_from.end(), DirectedEdge{v, -1});
    return (it != by_from.end() && (*it)[0] == v) ? (*it)[1] : -1;
  };
  const int start = by_from[0][0];
  int v = by_from[0][1];
  std::size_t steps = 1;
  while (v != start) {
    v = successor(v);
    if (v < 0) return false;  // a vertex entered but never left: not a cycle
    if (++steps > by_from.size()) return false;
  }
  return steps == by_from.size();
}

bool union_is_simple_cycle(const std::vector<DirectedEdge>& a, const std::vector<DirectedEdge>& b,
                           std::vector<DirectedEdge>& sum) {
  sum.clear();
  const auto add_uncancelled = [&](const std::vector<DirectedEdge>& chain, const std::vector<DirectedEdge>& other) {
    for (const DirectedEdge& e : chain) {
      if (!std::binary_search(other.begin(), other.end(), DirectedEdge{e[1], e[0]})) sum.push_back(e);
    }
  };
  add_uncancelled(a, b);
  const std::size_t cancelled = a.size() - sum.size();
  if (cancelled == 0) return false;
  // Sorted by (from, to), a simple cycle lists each of its vertices once as `from`, in
  // increasing order: a merge counts the shared ones.
  std::size_t shared = 0;
  for (std::size_t i = 0, j = 0; i < a.size() && j < b.size();) {
    if (a[i][0] < b[j][0]) {
      ++i;
    } else if (b[j][0] < a[i][0]) {
      ++j;
    } else {
      ++shared, ++i, ++j;
    }
  }
  if (shared != cancelled + 1) return false;
  add_uncancelled(b, a);
  return true;
}

NodeBoundaries::NodeBoundaries(const SubspaceBvh& bvh)
    : chains_(bvh.nodes().size()), simple_cycle_(bvh.nodes().size(), 0), parents_(bvh.nodes().size(), -1) {
  const TriangleMesh& mesh = bvh.model().mesh();
  for (std::size_t n = 0; n < bvh.nodes().size(); ++n) {
    const SubspaceBvh::Node& node = bvh.nodes()[n];
    for (int c = node.first_child; c < node.first_child + node.child_count; ++c) parents_[c] = static_cast<int>(n);
  }
  // Children follow their parent in the node array: fill from the back.
  for (int n = static_cast<int>(bvh.nodes().size()) - 1; n >= 0; --n) {
    const SubspaceBvh::Node& node = bvh.nodes()[n];
    std::vector<DirectedEdge> edges;
    if (node.is_leaf()) {
      for (int i = node.triangle_begin; i < node.triangle_end; ++i) {
        const Triangle& t = mesh.triangles()[bvh.triangle_order()[i]];
        for (int k = 0; k < 3; ++k) edges.push_back({t[k], t[(k + 1) % 3]});
      }
    } else {
      for (int c = node.first_child; c < node.first_child + node.child_count; ++c) {
        edges.insert(edges.end(), chains_[c].begin(), chains_[c].end());
      }
    }
    chains_[n] = boundary_chain(std::move(edges));
    simple_cycle_[n] = is_simple_cycle(chains_[n]);
  }
}

namespace {

/// A vector not parallel to the unit vector d: the cross product with the axis d leans on least.
Eigen::Vector3d across(const Eigen::Vector3d& d) {
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(d[k]) < std::abs(d[axis])) axis = k;
  }
  return d.cross(Eigen::Vector3d::Unit(axis));
}

}  // namespace

bool winds_once_star_shaped(const Eigen::Vector3d& d, const std::vector<DirectedEdge>& chain,
                            const std::vector<Eigen::Vector3d>& x0, const std::vector<Eigen::Vector3d>& x1) {
  if (chain.empty()) return false;  // a closed surface: winds zero times
  Eigen::Vector3d c0 = Eigen::Vector3d::Zero();
  Eigen::Vector3d c1 = Eigen::Vector3d::Zero();
  for (const DirectedEdge& e : chain) {
    c0 += x0[e[0]];
    c1 += x1[e[0]];
  }
  c0 /= static_cast<double>(chain.size());
  c1 /= static_cast<double>(chain.size());
  for (const DirectedEdge& e : chain) {
    if (!certainly_positive(d, bernstein_normals(c0, x0[e[0]], x0[e[1]], c1, x1[e[0]], x1[e[1]]))) return false;
  }
  // Every edge turns counter-clockwise about c by less than pi, so an edge from the ray's
  // negative side to its positive side crosses the ray itself, and the crossings count the
  // turns.
  const Eigen::Vector3d ray = across(d);
  int crossings = 0;
  for (const DirectedEdge& e : chain) {
    const int from = certified_sign_of_triple(d, ray, x0[e[0]], c0);
    const int to = certified_sign_of_triple(d, ray, x0[e[1]], c0);
    if (from == 0 || to == 0) return false;
    crossings += from < 0 && to > 0;
  }
#ifdef SSCC_MUTANT_CONTOUR_ANY_WINDING
  return crossings >= 1;
#endif
  return crossings == 1;
}

}  // namespace sscc::detail
