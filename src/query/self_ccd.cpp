#include "sscc/query/self_ccd.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <climits>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <tuple>

#include "sscc/ccd/kernels.hpp"

namespace sscc {

namespace {

SelfCcdReport sorted_report(std::vector<TrianglePairContact> pairs, std::vector<FeatureContact> features,
                            SelfCcdStats stats, std::chrono::steady_clock::time_point start) {
  SelfCcdReport report;
  report.pairs = std::move(pairs);
  std::sort(report.pairs.begin(), report.pairs.end(), [](const auto& x, const auto& y) {
    return std::make_pair(x.first, x.second) < std::make_pair(y.first, y.second);
  });
  report.features = std::move(features);
  std::sort(report.features.begin(), report.features.end(), [](const auto& x, const auto& y) {
    return std::make_tuple(x.kind, x.first, x.second) < std::make_tuple(y.kind, y.first, y.second);
  });
  for (const auto& p : report.pairs) report.earliest_toi = std::min(report.earliest_toi, p.toi);
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report.stats = stats;
  return report;
}

/// Box of triangle t at positions x.
Aabb box_at(const std::vector<Eigen::Vector3d>& x, const Triangle& t) {
  return {x[t[0]].cwiseMin(x[t[1]]).cwiseMin(x[t[2]]), x[t[0]].cwiseMax(x[t[1]]).cwiseMax(x[t[2]])};
}

/// Node boxes computed on first use (each at most once per query).
template <typename Box>
class LazyBoxes {
 public:
  explicit LazyBoxes(std::size_t nodes) : boxes_(nodes), known_(nodes, 0) {}
  template <typename Compute>
  const Box& get(int n, Compute compute) {
    if (!known_[n]) {
      boxes_[n] = compute(n);
      known_[n] = 1;
    }
    return boxes_[n];
  }

 private:
  std::vector<Box> boxes_;
  std::vector<char> known_;
};

Aabb hull(const Aabb& a, const Aabb& b) { return {a.lo.cwiseMin(b.lo), a.hi.cwiseMax(b.hi)}; }
Aabb shifted(const Aabb& a, const Eigen::Vector3d& by) { return {a.lo - by, a.hi - by}; }
Eigen::Vector3d centre(const Aabb& a) { return 0.5 * (a.lo + a.hi); }

/// Boxes of an object (triangle or node) at t = 0 and at t = 1.
using EndBoxes = std::array<Aabb, 2>;

/// Contact is unchanged when one translation, linear in t, moves both objects: with their
/// mean displacement taken out, neighbours that move alike sweep small boxes. Apart there
/// means apart.
bool apart_in_common_frame(const EndBoxes& a, const EndBoxes& b) {
  const Eigen::Vector3d common = 0.5 * ((centre(a[1]) - centre(a[0])) + (centre(b[1]) - centre(b[0])));
  return !hull(a[0], shifted(a[1], common)).overlaps(hull(b[0], shifted(b[1], common)));
}

/// What every query needs per call: the positions computed so far, the feature results,
/// the contacts and the statistics. Nothing here outlives the call.
class StepContext {
 public:
  /// s = max(||q_hat0||, ||q_hat1||).
  StepContext(const SubspaceBvh& bvh, const Eigen::VectorXd& q_hat0, const Eigen::VectorXd& q_hat1, double s,
              const SelfCcdOptions& options)
      : bvh_(bvh),
        mesh_(bvh.model().mesh()),
        options_(options),
        q_hat0_(q_hat0),
        q_hat1_(q_hat1),
        s_(s),
        x0_(mesh_.vertex_count()),
        x1_(mesh_.vertex_count()),
        computed_(mesh_.vertex_count(), 0),
        subspace_boxes_(bvh.nodes().size()),
        end_boxes_(bvh.nodes().size()) {}

  /// Whether two nodes may hold touching triangles. With refitted boxes the test is also
  /// made in the nodes' common moving frame: their mean displacement taken out of both
  /// (contact is unchanged by a translation, linear in t, applied to both).
  bool nodes_overlap(int a, int b) {
    ++stats_.box_tests;
    if (options_.bounds == NodeBounds::kSubspace) {
      const auto swept = [&](int n) { return bvh_.swept_box(n, q_hat0_, q_hat1_, s_); };
      return subspace_boxes_.get(a, swept).overlaps(subspace_boxes_.get(b, swept));
    }
    const EndBoxes& ea = node_end_boxes(a);
    const EndBoxes& eb = node_end_boxes(b);
    return hull(ea[0], ea[1]).overlaps(hull(eb[0], eb[1])) && !apart_in_common_frame(ea, eb);
  }
  bool stopped() const { return stop_; }
  SelfCcdStats& stats() { return stats_; }

  /// Kernels on the features of a non-adjacent triangle pair whose swept boxes meet. Each
  /// feature pair is tested in one triangle pair only, its owner: the smallest
  /// non-adjacent pair of triangles containing it. Whenever the feature's boxes overlap,
  /// every triangle and node box containing them overlaps too, so the owner is visited.
  void test_triangle_pair(int a, int b) {
    if (stop_) return;
    const EndBoxes ends_a = triangle_end_boxes(a);
    const EndBoxes ends_b = triangle_end_boxes(b);
    const Aabb box_a = hull(ends_a[0], ends_a[1]);
    const Aabb box_b = hull(ends_b[0], ends_b[1]);
    if (!box_a.overlaps(box_b) || mesh_.adjacent(a, b) || apart_in_common_frame(ends_a, ends_b)) return;
    ++stats_.triangle_pairs;
    const std::pair<int, int> pair{std::min(a, b), std::max(a, b)};
    const Triangle& ta = mesh_.triangles()[a];
    const Triangle& tb = mesh_.triangles()[b];
    for (int i = 0; i < 3; ++i) {
      if (point_box(ta[i]).overlaps(box_b) && owns_vertex_face(a, ta[i], b)) vertex_face(ta[i], b);
      if (point_box(tb[i]).overlaps(box_a) && owns_vertex_face(b, tb[i], a)) vertex_face(tb[i], a);
    }
    for (int i = 0; i < 3; ++i) {
      const int e = mesh_.triangle_edges(a)[i];
      const Aabb edge_a = edge_box(e);
      if (!edge_a.overlaps(box_b)) continue;
      for (int j = 0; j < 3; ++j) {
        const int g = mesh_.triangle_edges(b)[j];
        if (edge_a.overlaps(edge_box(g)) && edge_edge_owner(e, g) == pair) edge_edge(e, g);
      }
    }
  }

  SelfCcdReport finish(std::chrono::steady_clock::time_point start) {
    if (options_.mode == SelfCcdMode::kEarliest && !feature_hits_.empty()) {
      double earliest = 1.0;
      for (const FeatureContact& c : feature_hits_) earliest = std::min(earliest, c.toi);
      feature_hits_.erase(std::remove_if(feature_hits_.begin(), feature_hits_.end(),
                                         [&](const FeatureContact& c) { return c.toi != earliest; }),
                          feature_hits_.end());
    }
    std::vector<TrianglePairContact> pairs = pairs_from_features();  // before the move below
    return sorted_report(std::move(pairs), std::move(feature_hits_), stats_, start);
  }

 private:
  /// A node's boxes at both ends, refitted from its children's (or its triangles') on
  /// first use: only the nodes the traversal reaches, and the vertices under them.
  const EndBoxes& node_end_boxes(int n) {
    return end_boxes_.get(n, [&](int m) {
      const SubspaceBvh::Node& node = bvh_.nodes()[m];
      const Aabb empty{Eigen::Vector3d::Constant(INFINITY), Eigen::Vector3d::Constant(-INFINITY)};
      EndBoxes box{empty, empty};
      const auto add = [&](const EndBoxes& part) {
        box[0] = hull(box[0], part[0]);
        box[1] = hull(box[1], part[1]);
      };
      if (node.is_leaf()) {
        for (int i = node.triangle_begin; i < node.triangle_end; ++i) add(triangle_end_boxes(bvh_.triangle_order()[i]));
      } else {
        for (int c = node.first_child; c < node.first_child + node.child_count; ++c) add(node_end_boxes(c));
      }
      return box;
    });
  }

  void ensure_vertex(int v) {
    if (computed_[v]) return;
    x0_[v] = bvh_.model().position(v, q_hat0_);
    x1_[v] = bvh_.model().position(v, q_hat1_);
    computed_[v] = 1;
    ++stats_.vertices_computed;
  }

  Aabb point_box(int v) const { return {x0_[v].cwiseMin(x1_[v]), x0_[v].cwiseMax(x1_[v])}; }

  Aabb segment_box(const Edge& ends) const {
    const Aabb a = point_box(ends[0]);
    const Aabb b = point_box(ends[1]);
    return {a.lo.cwiseMin(b.lo), a.hi.cwiseMax(b.hi)};
  }

  Aabb edge_box(int e) const { return segment_box(mesh_.edges()[e]); }

  EndBoxes triangle_end_boxes(int t) {
    const Triangle& triangle = mesh_.triangles()[t];
    for (int v : triangle) ensure_vertex(v);
    return {box_at(x0_, triangle), box_at(x1_, triangle)};
  }

  /// Whether triangle t owns the vertex-face pair (v, f), v in t: the smallest non-adjacent
  /// pair containing it is (t', f) for the smallest t' around v not adjacent to f (pairs
  /// order by their smaller member, and f is fixed), so the first such t' decides.
  bool owns_vertex_face(int t, int v, int f) const {
    for (const int* u = mesh_.triangles_of_vertex_begin(v); u != mesh_.triangles_of_vertex_end(v); ++u) {
      if (!mesh_.adjacent(*u, f)) return *u == t;
    }
    return false;
  }

  /// The smallest non-adjacent triangle pair containing edges e and g.
  std::pair<int, int> edge_edge_owner(int e, int g) const {
    std::pair<int, int> owner{INT_MAX, INT_MAX};
    for (const int* t = mesh_.triangles_of_edge_begin(e); t != mesh_.triangles_of_edge_end(e); ++t) {
      for (const int* u = mesh_.triangles_of_edge_begin(g); u != mesh_.triangles_of_edge_end(g); ++u) {
        if (!mesh_.adjacent(*t, *u)) owner = std::min(owner, std::make_pair(std::min(*t, *u), std::max(*t, *u)));
      }
    }
    return owner;
  }

  void record(const ccd::CcdResult& r, FeatureKind kind, int first, int second) {
    ++stats_.kernel_calls;
    if (!r.hit) return;
    feature_hits_.push_back({kind, first, second, r.toi});
    if (options_.mode == SelfCcdMode::kAnyHit) stop_ = true;
  }

  void vertex_face(int v, int t) {
    if (stop_) return;
    const Triangle& f = mesh_.triangles()[t];
    record(ccd::vertex_face_ccd(x0_[v], x0_[f[0]], x0_[f[1]], x0_[f[2]], x1_[v], x1_[f[0]], x1_[f[1]],
                                x1_[f[2]], options_.kernel),
           FeatureKind::kVertexFace, v, t);
  }

  void edge_edge(int e, int g) {
    if (stop_) return;
    if (e > g) std::swap(e, g);
    const Edge& a = mesh_.edges()[e];
    const Edge& b = mesh_.edges()[g];
    record(ccd::edge_edge_ccd(x0_[a[0]], x0_[a[1]], x0_[b[0]], x0_[b[1]], x1_[a[0]], x1_[a[1]], x1_[b[0]],
                              x1_[b[1]], options_.kernel),
           FeatureKind::kEdgeEdge, e, g);
  }

  /// The colliding triangle pairs: every non-adjacent pair containing a feature that hit,
  /// at the earliest of its features' times.
  std::vector<TrianglePairContact> pairs_from_features() const {
    std::map<std::pair<int, int>, double> earliest;
    const auto add = [&](int t, int u, double toi) {
      if (mesh_.adjacent(t, u)) return;
      const auto key = std::make_pair(std::min(t, u), std::max(t, u));
      const auto [it, inserted] = earliest.emplace(key, toi);
      if (!inserted) it->second = std::min(it->second, toi);
    };
    for (const FeatureContact& c : feature_hits_) {
      if (c.kind == FeatureKind::kVertexFace) {
        for (const int* t = mesh_.triangles_of_vertex_begin(c.first); t != mesh_.triangles_of_vertex_end(c.first); ++t) {
          add(*t, c.second, c.toi);
        }
      } else {
        for (const int* t = mesh_.triangles_of_edge_begin(c.first); t != mesh_.triangles_of_edge_end(c.first); ++t) {
          for (const int* u = mesh_.triangles_of_edge_begin(c.second); u != mesh_.triangles_of_edge_end(c.second); ++u) {
            add(*t, *u, c.toi);
          }
        }
      }
    }
    std::vector<TrianglePairContact> pairs;
    for (const auto& [key, toi] : earliest) pairs.push_back({key.first, key.second, toi});
    return pairs;
  }

  const SubspaceBvh& bvh_;
  const TriangleMesh& mesh_;
  const SelfCcdOptions& options_;
  Eigen::VectorXd q_hat0_, q_hat1_;
  double s_;
  std::vector<Eigen::Vector3d> x0_, x1_;
  std::vector<char> computed_;
  LazyBoxes<Aabb> subspace_boxes_;
  LazyBoxes<EndBoxes> end_boxes_;
  std::vector<FeatureContact> feature_hits_;
  SelfCcdStats stats_;
  bool stop_ = false;
};

/// Self-traversal (SSCC paper, Algorithm 1): intra(n) tests the node against itself,
/// inter(a, b) two disjoint nodes whose boxes overlap; with certificates, a node or sibling
/// pair whose radius exceeds s is skipped.
template <typename Context>
class Traversal {
 public:
  /// certificates may be null (the traditional traversal).
  Traversal(const SubspaceBvh& bvh, Context& context, const Certificates* certificates, double s)
      : bvh_(bvh), context_(context), certificates_(certificates), s_(s) {}

  void intra(int n) {
    if (context_.stopped()) return;
    if (certificates_ && s_ < certificates_->node_radius(n)) {
      ++context_.stats().certified;
      return;
    }
    ++context_.stats().nodes_visited;
    const SubspaceBvh::Node& node = bvh_.nodes()[n];
    if (node.is_leaf()) {
      for (int i = node.triangle_begin; i < node.triangle_end; ++i) {
        for (int j = i + 1; j < node.triangle_end; ++j) pair(i, j);
      }
      return;
    }
    for (int c = node.first_child; c < node.first_child + node.child_count; ++c) intra(c);
    for (int c = node.first_child; c < node.first_child + node.child_count; ++c) {
      for (int d = c + 1; d < node.first_child + node.child_count; ++d) inter(c, d);
    }
  }

  void inter(int a, int b) {
    if (context_.stopped()) return;
    if (certificates_ && s_ < certificates_->sibling_radius(a, b)) {
      ++context_.stats().certified;
      return;
    }
    if (!context_.nodes_overlap(a, b)) return;
    ++context_.stats().nodes_visited;
    const SubspaceBvh::Node& na = bvh_.nodes()[a];
    const SubspaceBvh::Node& nb = bvh_.nodes()[b];
    if (na.is_leaf() && nb.is_leaf()) {
      for (int i = na.triangle_begin; i < na.triangle_end; ++i) {
        for (int j = nb.triangle_begin; j < nb.triangle_end; ++j) pair(i, j);
      }
      return;
    }
    // Descend the node with more triangles (a leaf never descends).
    const bool split_a = !na.is_leaf() && (nb.is_leaf() || na.triangle_end - na.triangle_begin >=
                                                                nb.triangle_end - nb.triangle_begin);
    const SubspaceBvh::Node& split = split_a ? na : nb;
    for (int c = split.first_child; c < split.first_child + split.child_count; ++c) {
      split_a ? inter(c, b) : inter(a, c);
    }
  }

 private:
  void pair(int i, int j) {
    const std::vector<int>& order = bvh_.triangle_order();
    context_.test_triangle_pair(order[i], order[j]);
  }

  const SubspaceBvh& bvh_;
  Context& context_;
  const Certificates* certificates_;
  double s_;
};

/// Discrete variant: boxes at one configuration, exact triangle-triangle tests.
class DiscreteContext {
 public:
  DiscreteContext(const SubspaceBvh& bvh, const Eigen::VectorXd& q_hat, double norm, const SelfCcdOptions& options)
      : bvh_(bvh), options_(options), q_hat_(q_hat), norm_(norm),
        x_(bvh.model().mesh().vertex_count()), computed_(x_.size(), 0), boxes_(bvh.nodes().size()) {}

  bool nodes_overlap(int a, int b) {
    ++stats_.box_tests;
    const auto at_q = [&](int n) { return bvh_.box(n, q_hat_, norm_); };
    return boxes_.get(a, at_q).overlaps(boxes_.get(b, at_q));
  }
  bool stopped() const { return stop_; }
  SelfCcdStats& stats() { return stats_; }

  void test_triangle_pair(int a, int b) {
    const TriangleMesh& mesh = bvh_.model().mesh();
    if (stop_ || mesh.adjacent(a, b)) return;
    const Triangle& ta = mesh.triangles()[a];
    const Triangle& tb = mesh.triangles()[b];
    for (int v : ta) ensure(v);
    for (int v : tb) ensure(v);
    if (!box_at(x_, ta).overlaps(box_at(x_, tb))) return;
    ++stats_.triangle_pairs;
    ++stats_.kernel_calls;
    if (ccd::triangles_intersect(x_[ta[0]], x_[ta[1]], x_[ta[2]], x_[tb[0]], x_[tb[1]], x_[tb[2]])) {
      pairs_.push_back({std::min(a, b), std::max(a, b), 0.0});
      if (options_.mode == SelfCcdMode::kAnyHit) stop_ = true;
    }
  }

  SelfCcdReport finish(std::chrono::steady_clock::time_point start) {
    return sorted_report(std::move(pairs_), {}, stats_, start);
  }

 private:
  void ensure(int v) {
    if (computed_[v]) return;
    x_[v] = bvh_.model().position(v, q_hat_);
    computed_[v] = 1;
    ++stats_.vertices_computed;
  }

  const SubspaceBvh& bvh_;
  const SelfCcdOptions& options_;
  Eigen::VectorXd q_hat_;
  double norm_;
  std::vector<Eigen::Vector3d> x_;
  std::vector<char> computed_;
  std::vector<TrianglePairContact> pairs_;
  LazyBoxes<Aabb> boxes_;
  SelfCcdStats stats_;
  bool stop_ = false;
};

}  // namespace

SelfCcd::SelfCcd(const SubspaceBvh& bvh, const Certificates& certificates)
    : bvh_(bvh), certificates_(&certificates) {
  certificates.check_belongs_to(bvh);
}

namespace {

/// The certificates a query may use (null for none); refuses a minimum separation, which
/// certificates of contact do not cover.
const Certificates* usable(const Certificates* certificates, const SelfCcdOptions& options) {
  if (!certificates || !options.use_certificates) return nullptr;
  if (options.kernel.minimum_separation > 0.0) {
    throw std::invalid_argument(
        "SelfCcd: certificates bound contact, not a minimum separation; set use_certificates = false");
  }
  return certificates;
}

/// The report of a step the root's certificate decides: nothing touches.
SelfCcdReport root_certified_report(std::chrono::steady_clock::time_point start) {
  SelfCcdStats stats;
  stats.certified = 1;
  stats.root_certified = true;
  return sorted_report({}, {}, stats, start);
}

}  // namespace

SelfCcdReport SelfCcd::query(const Eigen::VectorXd& q0, const Eigen::VectorXd& q1,
                             const SelfCcdOptions& options) const {
  const auto start = std::chrono::steady_clock::now();
  const Certificates* certificates = usable(certificates_, options);
  const Eigen::VectorXd q_hat0 = bvh_.model().scaled_coordinates(q0);
  const Eigen::VectorXd q_hat1 = bvh_.model().scaled_coordinates(q1);
  const double s = std::max(q_hat0.stableNorm(), q_hat1.stableNorm());
  if (certificates && s < certificates->node_radius(0)) return root_certified_report(start);
  StepContext context(bvh_, q_hat0, q_hat1, s, options);
  Traversal<StepContext>(bvh_, context, certificates, s).intra(0);
  return context.finish(start);
}

SelfCcdReport SelfCcd::query_discrete(const Eigen::VectorXd& q, const SelfCcdOptions& options) const {
  const auto start = std::chrono::steady_clock::now();
  const Certificates* certificates = usable(certificates_, options);
  const Eigen::VectorXd q_hat = bvh_.model().scaled_coordinates(q);
  const double s = q_hat.stableNorm();
  if (certificates && s < certificates->node_radius(0)) return root_certified_report(start);
  DiscreteContext context(bvh_, q_hat, s, options);
  Traversal<DiscreteContext>(bvh_, context, certificates, s).intra(0);
  return context.finish(start);
}

SelfCcdReport SelfCcd::query_exhaustive(const Eigen::VectorXd& q0, const Eigen::VectorXd& q1,
                                        const SelfCcdOptions& options) const {
  const auto start = std::chrono::steady_clock::now();
  const Eigen::VectorXd q_hat0 = bvh_.model().scaled_coordinates(q0);
  const Eigen::VectorXd q_hat1 = bvh_.model().scaled_coordinates(q1);
  StepContext context(bvh_, q_hat0, q_hat1, std::max(q_hat0.stableNorm(), q_hat1.stableNorm()), options);
  const int n = bvh_.model().mesh().triangle_count();
  for (int a = 0; a < n && !context.stopped(); ++a) {
    for (int b = a + 1; b < n && !context.stopped(); ++b) context.test_triangle_pair(a, b);
  }
  return context.finish(start);
}

}  // namespace sscc
