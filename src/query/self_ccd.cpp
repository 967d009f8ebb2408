#include "sscc/query/self_ccd.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <tuple>
#include <unordered_map>

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

Aabb box_of(const std::vector<Eigen::Vector3d>& x0, const std::vector<Eigen::Vector3d>& x1,
            const Triangle& t) {
  Aabb box{Eigen::Vector3d::Constant(INFINITY), Eigen::Vector3d::Constant(-INFINITY)};
  for (int v : t) {
    box.lo = box.lo.cwiseMin(x0[v]).cwiseMin(x1[v]);
    box.hi = box.hi.cwiseMax(x0[v]).cwiseMax(x1[v]);
  }
  return box;
}

/// What every query needs per call: the positions computed so far, the feature results,
/// the contacts and the statistics. Nothing here outlives the call.
class StepContext {
 public:
  StepContext(const SubspaceBvh& bvh, const Eigen::VectorXd& q0, const Eigen::VectorXd& q1,
              const SelfCcdOptions& options)
      : bvh_(bvh),
        mesh_(bvh.model().mesh()),
        options_(options),
        q_hat0_(bvh.model().scaled_coordinates(q0)),
        q_hat1_(bvh.model().scaled_coordinates(q1)),
        s_(std::max(q_hat0_.norm(), q_hat1_.norm())),
        x0_(mesh_.vertex_count()),
        x1_(mesh_.vertex_count()),
        computed_(mesh_.vertex_count(), 0) {}

  Aabb node_box(int n) {
    ++stats_.box_tests;
    return bvh_.swept_box(n, q_hat0_, q_hat1_, s_);
  }
  bool stopped() const { return stop_; }
  SelfCcdStats& stats() { return stats_; }

  /// Kernels on the features of a non-adjacent triangle pair whose swept boxes meet.
  void test_triangle_pair(int a, int b) {
    if (stop_ || mesh_.adjacent(a, b)) return;
    if (!triangle_box(a).overlaps(triangle_box(b))) return;
    ++stats_.triangle_pairs;
    double earliest = 2.0;
    const Triangle& ta = mesh_.triangles()[a];
    const Triangle& tb = mesh_.triangles()[b];
    for (int i = 0; i < 3; ++i) {
      earliest = std::min(earliest, vertex_face(ta[i], b));
      earliest = std::min(earliest, vertex_face(tb[i], a));
      for (int j = 0; j < 3; ++j) {
        earliest = std::min(earliest, edge_edge(mesh_.triangle_edges(a)[i], mesh_.triangle_edges(b)[j]));
      }
    }
    if (earliest <= 1.0) {
      pairs_.push_back({std::min(a, b), std::max(a, b), earliest});
      if (options_.mode == SelfCcdMode::kAnyHit) stop_ = true;
    }
  }

  SelfCcdReport finish(std::chrono::steady_clock::time_point start) {
    return sorted_report(std::move(pairs_), std::move(feature_hits_), stats_, start);
  }

 private:
  void ensure_vertex(int v) {
    if (computed_[v]) return;
    x0_[v] = bvh_.model().position(v, q_hat0_);
    x1_[v] = bvh_.model().position(v, q_hat1_);
    computed_[v] = 1;
    ++stats_.vertices_computed;
  }

  Aabb triangle_box(int t) {
    for (int v : mesh_.triangles()[t]) ensure_vertex(v);
    return box_of(x0_, x1_, mesh_.triangles()[t]);
  }

  /// Time of impact of a feature pair (2 for none), computed once per query.
  template <typename Kernel>
  double feature(FeatureKind kind, int first, int second, Kernel kernel) {
    const std::uint64_t key = (static_cast<std::uint64_t>(kind) << 63) |
                              (static_cast<std::uint64_t>(first) << 31) | static_cast<std::uint64_t>(second);
    const auto [it, inserted] = results_.emplace(key, 2.0);
    if (inserted) {
      ++stats_.kernel_calls;
      const ccd::CcdResult r = kernel();
      if (r.hit) {
        it->second = r.toi;
        feature_hits_.push_back({kind, first, second, r.toi});
      }
    }
    return it->second;
  }

  double vertex_face(int v, int t) {
    return feature(FeatureKind::kVertexFace, v, t, [&] {
      const Triangle& f = mesh_.triangles()[t];
      return ccd::vertex_face_ccd(x0_[v], x0_[f[0]], x0_[f[1]], x0_[f[2]], x1_[v], x1_[f[0]],
                                  x1_[f[1]], x1_[f[2]], options_.kernel);
    });
  }

  double edge_edge(int e, int g) {
    if (e > g) std::swap(e, g);
    return feature(FeatureKind::kEdgeEdge, e, g, [&] {
      const Edge& a = mesh_.edges()[e];
      const Edge& b = mesh_.edges()[g];
      return ccd::edge_edge_ccd(x0_[a[0]], x0_[a[1]], x0_[b[0]], x0_[b[1]], x1_[a[0]], x1_[a[1]],
                                x1_[b[0]], x1_[b[1]], options_.kernel);
    });
  }

  const SubspaceBvh& bvh_;
  const TriangleMesh& mesh_;
  const SelfCcdOptions& options_;
  Eigen::VectorXd q_hat0_, q_hat1_;
  double s_;
  std::vector<Eigen::Vector3d> x0_, x1_;
  std::vector<char> computed_;
  std::unordered_map<std::uint64_t, double> results_;
  std::vector<TrianglePairContact> pairs_;
  std::vector<FeatureContact> feature_hits_;
  SelfCcdStats stats_;
  bool stop_ = false;
};

/// Self-traversal (SSCC paper, Algorithm 1 without the certificates): intra(n) tests the
/// node against itself, inter(a, b) two disjoint nodes whose boxes overlap.
template <typename Context>
class Traversal {
 public:
  Traversal(const SubspaceBvh& bvh, Context& context) : bvh_(bvh), context_(context) {
    boxes_.resize(bvh.nodes().size());
    known_.assign(bvh.nodes().size(), 0);
  }

  void intra(int n) {
    if (context_.stopped()) return;
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
    if (context_.stopped() || !box(a).overlaps(box(b))) return;
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
  const Aabb& box(int n) {
    if (!known_[n]) {
      boxes_[n] = context_.node_box(n);
      known_[n] = 1;
    }
    return boxes_[n];
  }
  void pair(int i, int j) {
    const std::vector<int>& order = bvh_.triangle_order();
    context_.test_triangle_pair(order[i], order[j]);
  }

  const SubspaceBvh& bvh_;
  Context& context_;
  std::vector<Aabb> boxes_;
  std::vector<char> known_;
};

/// Discrete variant: boxes at one configuration, exact triangle-triangle tests.
class DiscreteContext {
 public:
  DiscreteContext(const SubspaceBvh& bvh, const Eigen::VectorXd& q, const SelfCcdOptions& options)
      : bvh_(bvh), options_(options), q_hat_(bvh.model().scaled_coordinates(q)), norm_(q_hat_.norm()),
        x_(bvh.model().mesh().vertex_count()), computed_(x_.size(), 0) {}

  Aabb node_box(int n) {
    ++stats_.box_tests;
    return bvh_.box(n, q_hat_, norm_);
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
    if (!box_of(x_, x_, ta).overlaps(box_of(x_, x_, tb))) return;
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
  SelfCcdStats stats_;
  bool stop_ = false;
};

}  // namespace

SelfCcdReport SelfCcd::query(const Eigen::VectorXd& q0, const Eigen::VectorXd& q1,
                             const SelfCcdOptions& options) const {
  const auto start = std::chrono::steady_clock::now();
  StepContext context(bvh_, q0, q1, options);
  Traversal<StepContext>(bvh_, context).intra(0);
  return context.finish(start);
}

SelfCcdReport SelfCcd::query_discrete(const Eigen::VectorXd& q, const SelfCcdOptions& options) const {
  const auto start = std::chrono::steady_clock::now();
  DiscreteContext context(bvh_, q, options);
  Traversal<DiscreteContext>(bvh_, context).intra(0);
  return context.finish(start);
}

SelfCcdReport SelfCcd::query_exhaustive(const Eigen::VectorXd& q0, const Eigen::VectorXd& q1,
                                        const SelfCcdOptions& options) const {
  const auto start = std::chrono::steady_clock::now();
  StepContext context(bvh_, q0, q1, options);
  const int n = bvh_.model().mesh().triangle_count();
  for (int a = 0; a < n && !context.stopped(); ++a) {
    for (int b = a + 1; b < n && !context.stopped(); ++b) context.test_triangle_pair(a, b);
  }
  return context.finish(start);
}

}  // namespace sscc
