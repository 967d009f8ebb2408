#include "sscc/query/self_ccd.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "common/finite.hpp"
#include "common/parallel_tasks.hpp"
#include "common/sorted_fraction.hpp"
#include "query/contour.hpp"
#include "query/descent.hpp"
#include "query/displacement_bound.hpp"
#include "query/feature_hits.hpp"
#include "query/hierarchy_vertices.hpp"
#include "query/moved_box.hpp"
#include "query/patch_cull.hpp"
#include "query/patch_radius.hpp"
#include "query/separating_plane.hpp"
#include "query/step_buffers.hpp"
#include "query/step_vertices.hpp"
#include "query/sweep.hpp"
#include "query/task_frontier.hpp"
#include "query/uncertified_work.hpp"
#include "query/unconsidered_leaf_pairs.hpp"
#include "sscc/ccd/kernels.hpp"

namespace sscc {

namespace {

using detail::box_at;
using detail::descend_larger;
using detail::EarliestPerKey;
using detail::FeatureHits;
using detail::for_each_triangle_pair_of;
using detail::hull;
using detail::LazyBoxes;
using detail::overlap;
using detail::Sweep;
using detail::sweeps_may_touch;

/// Past this multiple of the root's certificate radius (s > ratio R_0) the certificates of
/// its descendants rarely hold either (radii grow by about 1.6 per level on the meshes
/// measured): the query then computes every vertex up front and runs on every thread, as
/// without certificates. Lower: work that certificates would have saved; higher: steps far
/// outside the certificates cost more than without them (measured: the knot at amplitude 0.2,
/// 19.1 ms with certificates against 18.0 without, before this rule; 17.3 against 17.5 with
/// it).
constexpr double kFarPastCertificateRatio = 2.0;

/// Past kFarPastCertificateRatio, a step is still taken lazily (vertices and sweeps on demand,
/// one thread) while the certificates' open ends it fails weigh at most this fraction of the
/// triangle count (uncertified_work.hpp): the pair certificates below the sibling pairs then
/// still cull nearly all of the hierarchy. Measured, one thread, traversed steps: the dragon
/// scene's (every one past the ratio, estimates at most 0.05), 0.68 ms per step computing every
/// vertex against 0.044 ms lazily (same culls, 5441 vertices against 357); the hard spring's
/// (estimates at most 0.15) 0.322 against 0.320 ms. A step that fails every certificate
/// estimates at least 1 (every leaf). Lower: lazy steps that reach most vertices anyway;
/// higher: every vertex computed for a step that reaches few.
constexpr double kLargestUncertifiedWorkForLazySteps = 0.5;

/// With certificates, a step whose norm leaves more than this fraction of the nodes of at
/// least kSmallestCountedNode triangles (displacement_bound.hpp) certified (s below their
/// radius) uses no normal cones: the certificates cull most of the hierarchy, and a cone
/// costs every normal under its node, most of them under certified subtrees. Leaves do not
/// count: far past the root's radius most of them stay certified while their pairs with
/// neighbours, which they do not cover, make the traversal's work. Measured, one thread,
/// median step, before the per-mesh rule (patch_cull.hpp, kSmallestMeanRestPatch) kept the
/// cones off the dragon: the dragon at amplitude 0.01 (nine in ten such nodes certified),
/// 4.02 ms with cones against 2.97 ms without before this rule, 3.11 against 3.08 with it;
/// the lion at 0.2 (none certified), 15.5 against 16.9 ms. Lower: fewer steps with cones;
/// higher: cones where they cost.
constexpr double kLargestCertifiedFractionForCones = 0.5;

/// Without certificates, a step whose displacement bounds cull more than this fraction of a
/// sample of nodes (DisplacementBounds::sample) uses no normal cones: a cone costs every normal
/// under its node, where the bounds cull nodes for O(r) each. Measured, one thread, median
/// step, the bounds with and without cones: before this rule, the lion at amplitude 0.01
/// 3.00 against 1.86 ms, the dragon 9.94 against 8.20 ms; with it at most 1% apart, except the
/// lion at 0.2 (none culled), 16.9 against 18.2 ms, and the bunny at 0.2, 67.0 against 66.0.
/// A half instead: the lion at 0.05, 7.02 against 6.56 ms.
constexpr double kLargestApartFractionForCones = 0.1;

/// A step whose displacement bounds cull less than this fraction of the same sample tests
/// them nowhere: each test costs O(r) on every node and node pair visited, for culls that
/// do not come. Measured, one thread, 5 steps, the cones and the bounds together at
/// amplitude 0.2 (the sample's fraction 0 on every mesh of ../shared/data/meshes, 0.016 on one
/// elephant step; 0.13 to 0.89 at 0.01 and 0.05): 0.95x (the knot, the elephant) to 1.06x
/// (the lion) the traditional query's speed before this rule, 1.01x to 1.10x with it.
/// Lower: tests that cull nothing; higher: culls lost on steps where a few nodes are apart.
constexpr double kSmallestApartFractionForBounds = 0.05;

/// A step whose norm leaves fewer than this fraction of the node radii of the cones bounded
/// from the norm (patch_radius.hpp) above it does not test them: its few culls save less than
/// the tests cost on every node visited. Measured, one thread, 5 steps, the cones query
/// against the traditional one: the dragon at amplitude 0.05 (0.3% of the radii above the
/// step's norm), 0.97x with the radii tested; the elephant at 0.05 (6.4%), 1.00x. Lower:
/// tests that do not pay; higher: culls lost. The node pairs' radii are tested with them
/// (before, only when half of those exceeded the norm; Valgrind, the cones query, 5 steps:
/// the knot at amplitude 0.05, 40% to 54% above it, 131.9M instructions against 152.0M, the
/// dragon 322.8M against 364.0M; the lion at 0.1, 13% above it, 373.0M against 376.9M).
constexpr double kSmallestRadiusFractionForCones = 0.02;

/// A step that computes every vertex up front refits every node's sweep at once (a tight pass
/// over the triangles and the nodes) unless the radii cull patches of more than
/// kRefitTriangleLimit triangles holding more than this fraction of the mesh: those keep their
/// O(r) subspace boxes (NodeBounds::kHybrid), never refitted below. Otherwise the traversal
/// refits most nodes anyway, on demand, one lazy lookup and call at a time. Measured, one
/// thread, 20 steps, the cones query, on demand against at once: the dragon at amplitude 0.01
/// 4.22 / 4.55 ms against 3.88 / 4.25 ms (two runs), at 0.05 12.69 / 12.78 against 11.99 /
/// 12.33; the knot 0.87 / 0.88 against 0.77 / 0.79 and 5.10 / 5.27 against 4.89 / 4.85; the
/// elephant 1.00 / 1.09 against 0.96 / 1.01 and 1.94 / 1.68 against 1.60 / 1.62; the 75k bunny
/// at 0.05 9.53 / 9.59 against 7.85 / 7.46 (its large patches' subspace boxes are loose: node
/// tests 85k against 60k), but at 0.01, where the radii cull nine tenths of it in large
/// patches, 23% more instructions at once (Valgrind, 5 steps: 203M against 166M). Lower:
/// steps like the bunny's at 0.05 kept on demand; higher: refits the radii would spare.
constexpr double kLargestCoverageForLazyRefit = 0.5;

/// A step whose norm leaves more than this fraction of the patches' radii (the largest proven
/// nodes: patch_radius.hpp) above it forms no cones from the positions (patch_cull.hpp): the
/// radii then cull most of what these would, at the top, while formed cones cost every
/// normal under the nodes they test. Counted over all the node radii instead (the rule
/// before, at a half), a step far past the certificates whose patches mostly fail but whose
/// small nodes mostly pass lost its formed cones, which cull whole patches. Measured, one
/// thread: the default demo's 234 traversed steps, 459 and 461 ms with this rule against 482
/// and 483 ms with the one before (their patches' fraction about 0.1, the nodes' 0.6); the
/// 75k bunny at amplitude 0.05, cones query, 20.3 ms at a fifth against 23.5 ms at 0.3 and
/// 24.7 at a half (formed cones there cost more than they save); at amplitude 0.01 (the
/// patches mostly above the norm) the same node and triangle-pair tests with either rule on
/// every mesh of ../shared/data/meshes. Lower: formed cones lost where the patches fail; higher: formed cones that
/// cost. A step whose norm leaves none of the patches' radii above it (far past every proven
/// patch) forms none either: its normals spread so far that the formed cones mostly fail after
/// their normals are paid. Measured, one thread, 5 steps, cones query at amplitude 0.2 (no
/// patch radius above the norm): Valgrind, the lion 417M instructions without them against
/// 545M with them; the 75k bunny 54-62 ms against 83-98 ms (traditional query 83-85 ms in the
/// same runs); the default demo's steps (a tenth of their patches above) the same
/// instructions and culls. Without radii (positions queries, no coordinates) the rule does not
/// apply.
constexpr double kLargestPatchFractionForFormedCones = 0.2;

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

/// The static data of the culls a query uses (CullData), each null when it does not.
struct StepCulls {
  const detail::NodeBoundaries* boundaries = nullptr;  // the normal cones formed per step
  const detail::PatchRadii* radii = nullptr;           // the normal cones bounded from the norm
  const detail::DisplacementBounds* displacement = nullptr;
  const detail::UnconsideredLeafPairs* unconsidered = nullptr;  // leaf pairs skipped with the cones
};

/// What a query's traversal needs on one thread: the positions (shared by the query's
/// contexts), its box and cone caches, the feature results, the contacts and the statistics.
/// Only the node boxes it records for the next step (step_vertices.hpp) outlive the call.
class StepContext {
 public:
  /// s = max(||q_hat0||, ||q_hat1||); empty coordinates for a query on given positions.
  /// The positions come from `vertices` (shared by the query's contexts, computed up front or
  /// on demand), the context's caches from `pool`, back to it with the context.
  StepContext(const SubspaceBvh& bvh, const Eigen::VectorXd& q_hat0, const Eigen::VectorXd& q_hat1, double s,
              const SelfCcdOptions& options, const StepCulls& culls, detail::BufferPool<detail::BoxBuffers>& pool,
              detail::StepVertices& vertices)
      : bvh_(bvh),
        mesh_(bvh.model().mesh()),
        options_(options),
        q_hat0_(q_hat0),
        q_hat1_(q_hat1),
        s_(s),
        separation_(options.kernel.minimum_separation),
        norm0_(q_hat0.stableNorm()),
        norm1_(q_hat1.stableNorm()),
        buffers_(pool.lend()),
        vertices_(vertices),
        x0_(vertices.x0()),
        x1_(vertices.x1()),
        subspace_boxes_(buffers_->subspace_boxes),
        node_sweeps_(buffers_->node_sweeps),
        coherent_sweeps_(buffers_->coherent_sweeps),
        triangle_sweeps_(buffers_->triangle_sweeps),
        triangle_normals_(buffers_->triangle_normals),
        hits_(options.mode, &stats_.kernel_calls),
        unconsidered_(culls.unconsidered) {
    subspace_boxes_.reset(bvh.nodes().size());
    node_sweeps_.reset(bvh.nodes().size());
    triangle_sweeps_.reset(mesh_.triangle_count());
    // On demand, the node boxes go from step to step (coherent_sweep): recorded by every such
    // step, moved by a step that continues the last one. Only then is every vertex computed
    // on this context's thread (plan_step), so the records need no lock.
    coherent_ = !vertices.every_vertex_known() && options.bounds != NodeBounds::kSubspace;
    move_boxes_ = coherent_ && vertices.continues_previous();
    if (coherent_) {
      vertices.track_node_boxes(static_cast<int>(bvh.nodes().size()));
      coherent_sweeps_.reset(bvh.nodes().size());
      delta_ = q_hat1 - q_hat0;
      delta_norm_ = delta_.stableNorm();
    }
    if (culls.displacement && options.use_displacement_bounds && q_hat0.size() > 0) {
      displacement_ = std::make_unique<detail::StepDisplacement>(*culls.displacement, bvh, q_hat0, q_hat1, separation_);
      if (displacement_->apart_fraction() < kSmallestApartFractionForBounds) displacement_.reset();
    }
    const auto cones_pay = [&] {
      return !displacement_ || displacement_->apart_fraction() <= kLargestApartFractionForCones;
    };
    const bool cones = options.use_normal_cones && separation_ == 0.0;
    separating_planes_ = cones;
    if (separating_planes_) triangle_normals_.reset(mesh_.triangle_count());
    // With coordinates, the cones bounded from the norm; the fraction of their radii above
    // it says how much they cull.
    const bool radii_from_norm = cones && culls.radii && q_hat0.size() > 0;
    const double radius_fraction = radii_from_norm ? culls.radii->fraction_above(s) : 0.0;
    if (radius_fraction >= kSmallestRadiusFractionForCones) radii_ = culls.radii;
    rest_patches_ = cones ? culls.radii : nullptr;
    const double patch_fraction = radii_from_norm ? culls.radii->patch_fraction_above(s) : 0.0;
    const bool formed_cones_pay =
        !radii_from_norm || (patch_fraction > 0.0 && patch_fraction <= kLargestPatchFractionForFormedCones);
    // Every sweep at once, in one pass, unless the step leaves most of the mesh under large
    // patches the radii cull, whose subspace boxes spare refitting below them.
    const bool large_patches_culled = options.bounds == NodeBounds::kHybrid && radii_from_norm &&
                                      culls.radii->large_patch_coverage_above(s) > kLargestCoverageForLazyRefit;
    if (vertices.every_vertex_known() && q_hat0.size() > 0 && options.bounds != NodeBounds::kSubspace &&
        !large_patches_culled) {
      refit_every_sweep();
    }
    if (culls.boundaries && cones && cones_pay() && formed_cones_pay) {
      patch_cull_ = std::make_unique<detail::PatchCull>(
          bvh, *culls.boundaries, vertices.x0_vector(), vertices.x1_vector(),
          [this](int i) {
            for (int v : mesh_.triangles()[bvh_.triangle_order()[i]]) ensure_vertex(v);
          },
          buffers_->patch_cull);
    }
  }

  /// Whether two nodes may hold touching triangles: with refitted boxes, their boxes at both
  /// ends of the step, interpolated (sweep.hpp); with subspace boxes, the boxes of the step.
  bool nodes_overlap(int a, int b) {
    ++stats_.box_tests;
    if (options_.bounds == NodeBounds::kSubspace) {
      const auto swept = [&](int n) { return bvh_.swept_box(n, q_hat0_, q_hat1_, s_); };
      return overlap(subspace_boxes_.get(a, swept), subspace_boxes_.get(b, swept), separation_);
    }
    // The sweeps from the last step's end boxes first: no vertex computed when they part.
    if (move_boxes_ && !(node_sweeps_.known(a) && node_sweeps_.known(b))) {
      const Sweep& sweep_a = coherent_sweep(a);
      const Sweep& sweep_b = coherent_sweep(b);
      if (!sweeps_may_touch(sweep_a, sweep_b, separation_)) {
        // Counted when a moved box decided it (coherent_sweep computes the sweep it cannot move).
        if (!(node_sweeps_.known(a) && node_sweeps_.known(b))) ++stats_.moved_box_culled;
        return false;
      }
    }
    return sweeps_may_touch(node_sweep(a), node_sweep(b), separation_);
  }
  bool stopped() const { return hits_.stopped() || (cancel_ && cancel_->cancels(task_)); }
  SelfCcdStats& stats() { return stats_; }
  /// The normal-cone cull of a node, and of the union of two nodes: bounded from the step's
  /// norm (patch_radius.hpp), else formed from the positions (patch_cull.hpp).
  bool node_cannot_self_touch(int n) {
    if (radii_ && s_ < radii_->node_radius(n)) return ++stats_.cone_radius_culled, true;
    // The cones formed per step only on nodes proven at rest along their mean normal, the
    // direction those cones take: the others' normals rarely fit in a half-space about it
    // during a step either, and their cones cost every normal below them.
    return patch_cull_ && (!rest_patches_ || rest_patches_->proven_along_mean(n)) && patch_cull_->cannot_self_touch(n);
  }
  bool nodes_cannot_touch(int a, int b) {
    if (radii_ && radii_->pair_below(a, b, s_)) {
      return ++stats_.cone_radius_culled, true;
    }
    return patch_cull_ && patch_cull_->cannot_touch(a, b);
  }
  /// Whether a and b are leaves holding no considered triangle pair (unconsidered_leaf_pairs.hpp).
  bool leaves_hold_no_considered_pair(int a, int b) const { return unconsidered_ && unconsidered_->contains(a, b); }
  /// The displacement cull (displacement_bound.hpp) of a node, and of two nodes.
  bool node_held_apart(int n) { return displacement_ && displacement_->node_apart(n); }
  bool nodes_held_apart(int a, int b) { return displacement_ && displacement_->nodes_apart(a, b); }

  /// The parallel layer: the next task this context runs (its hits are taken with
  /// take_hits before the next one); `cancel`, in the modes that stop at a hit, tells when
  /// an earlier task's hit makes this one useless.
  void begin_task(int task, const detail::FirstHitTask* cancel) {
    task_ = task;
    cancel_ = cancel;
  }
  std::vector<FeatureContact> take_hits() { return hits_.take(); }
  /// The merged hits of every task, in task order, and the counters of every context.
  void absorb(std::vector<FeatureContact> hits, const SelfCcdStats& stats) {
    hits_.replace(std::move(hits));
    stats_ = stats;
  }

  /// Whether the triangle at position i of the BVH's order can touch anything in node n:
  /// the cheap test that prunes a leaf pair's triangle loops.
  bool triangle_meets_node(int i, int n) {
    if (options_.bounds == NodeBounds::kSubspace) return true;
    return sweeps_may_touch(triangle_sweep(i), node_sweep(n), separation_);
  }

  /// Kernels on the features of a considered triangle pair (neither adjacent nor excluded)
  /// whose sweeps may touch (sweep.hpp). Each feature pair is tested in one triangle pair
  /// only, its owner: the smallest considered pair of triangles containing it. Whenever the
  /// features come within the separation at some t, so do the interpolated boxes of every
  /// triangle and node containing them, so the owner is visited. A pair its planes separate
  /// skips the features it owns: they are parts of its two triangles, which never touch.
  /// The triangles at positions i and j of the BVH's order.
  void test_triangle_pair(int i, int j) {
    if (stopped()) return;
    const int a = bvh_.triangle_order()[i];
    const int b = bvh_.triangle_order()[j];
    if (!considers(a, b) || !sweeps_may_touch(triangle_sweep(i), triangle_sweep(j), separation_)) return;
    ++stats_.triangle_pairs;
    if (separating_planes_ && plane_separates(i, j)) {
      ++stats_.plane_culled;
      return;
    }
    const Aabb box_a = hull(triangle_sweep(i).start, triangle_sweep(i).end);
    const Aabb box_b = hull(triangle_sweep(j).start, triangle_sweep(j).end);
    const Triangle& ta = mesh_.triangles()[a];
    const Triangle& tb = mesh_.triangles()[b];
    for (int k = 0; k < 3; ++k) {
      if (overlap(point_box(ta[k]), box_b, separation_) && owns_vertex_face(a, ta[k], b)) vertex_face(ta[k], b);
      if (overlap(point_box(tb[k]), box_a, separation_) && owns_vertex_face(b, tb[k], a)) vertex_face(tb[k], a);
    }
    std::array<Aabb, 3> edges_b;
    for (int l = 0; l < 3; ++l) edges_b[l] = edge_box(mesh_.triangle_edges(b)[l]);
    const std::pair<int, int> pair{std::min(a, b), std::max(a, b)};
    for (int k = 0; k < 3; ++k) {
      const int e = mesh_.triangle_edges(a)[k];
      const Aabb edge_a = edge_box(e);
      if (!overlap(edge_a, box_b, separation_)) continue;
      for (int l = 0; l < 3; ++l) {
        const int g = mesh_.triangle_edges(b)[l];
        if (overlap(edge_a, edges_b[l], separation_) && owns_edge_edge(pair, e, g)) edge_edge(e, g);
      }
    }
  }

  SelfCcdReport finish(std::chrono::steady_clock::time_point start) {
    std::vector<FeatureContact>& hits = hits_.hits();
    if (options_.mode == SelfCcdMode::kEarliest && !hits.empty()) {
      double earliest = 1.0;
      for (const FeatureContact& c : hits) earliest = std::min(earliest, c.toi);
      hits.erase(std::remove_if(hits.begin(), hits.end(), [&](const FeatureContact& c) { return c.toi != earliest; }),
                 hits.end());
    }
    std::vector<TrianglePairContact> pairs = pairs_from_features();  // before the move below
    return sorted_report(std::move(pairs), std::move(hits), stats_, start);
  }

 private:
  /// A node's sweep, refitted from its children's (or its triangles') on first use: only
  /// the nodes the traversal reaches, and the vertices under them.
  const Sweep& node_sweep(int n) {
    return node_sweeps_.get(n, [&](int m) {
      const SubspaceBvh::Node& node = bvh_.nodes()[m];
      const Sweep sweep =
          options_.bounds == NodeBounds::kHybrid && node.triangle_end - node.triangle_begin > kRefitTriangleLimit
              ? Sweep{bvh_.box(m, q_hat0_, norm0_), bvh_.box(m, q_hat1_, norm1_)}
              : refitted_sweep(node);
      if (coherent_) vertices_.record_end_box(m, sweep.end);
      return sweep;
    });
  }

  /// Node n's sweep when known, else bounded from the box the previous step recorded for its
  /// end, which holds this step's start positions (step_vertices.hpp): the vertices move by
  /// at most their deviation from the node's mean modes (SubspaceBvh::SubspaceBound) applied
  /// to q_hat1 - q_hat0, past the node's mean shift, plus the rounding of the positions at
  /// both ends; else the node's sweep. A sweep bounded so is recorded as the node's end box.
  const Sweep& coherent_sweep(int n) {
    if (node_sweeps_.known(n)) return node_sweeps_.value(n);
    return coherent_sweeps_.get(n, [&](int m) {
      const Aabb* start = vertices_.previous_end_box(m);
      if (!start) return node_sweep(m);
      const Sweep sweep{*start, detail::moved_box(*start, bvh_.subspace_bound(m), delta_, delta_norm_, s_,
                                                  bvh_.model().mode_count())};
      vertices_.record_end_box(m, sweep.end);
      return sweep;
    });
  }

  /// A node's sweep merged from its triangles' or its children's. On a step that moves the
  /// last one's boxes, from the children's moved boxes where they have them: any boxes that
  /// hold the children's positions at both ends hold the node's (sweep.hpp interpolates
  /// them), and a refit down to the triangles would compute every vertex under the node when
  /// the traversal goes on into a few of its children. Measured on the hard spring (`sscc demo
  /// --scene spring --strike-speed 7 --steps 17640 --fcl-steps 0 --threads 1`, SSCC alone):
  /// 0.048 ms per step against 0.067 to 0.085 ms refitting from the triangles.
  Sweep refitted_sweep(const SubspaceBvh::Node& node) {
    Sweep sweep = Sweep::empty();
    if (node.is_leaf()) {
      for (int i = node.triangle_begin; i < node.triangle_end; ++i) sweep.merge(triangle_sweep(i));
    } else {
      for (int c = node.first_child; c < node.first_child + node.child_count; ++c) {
        sweep.merge(move_boxes_ ? coherent_sweep(c) : node_sweep(c));
      }
    }
    return sweep;
  }

  /// Every triangle's and node's sweep, bottom-up in one pass (children follow their parent
  /// in the node array), once every vertex is known (no box moved then): the same boxes as
  /// node_sweep's refits, and under NodeBounds::kHybrid refits of the large nodes too, tighter than their subspace
  /// boxes.
  void refit_every_sweep() {
    const std::vector<SubspaceBvh::Node>& nodes = bvh_.nodes();
    for (int n = static_cast<int>(nodes.size()) - 1; n >= 0; --n) node_sweeps_.set(n, refitted_sweep(nodes[n]));
  }

  /// Whether either triangle's plane (positions i and j of the BVH's order) separates the
  /// two over the step (separating_plane.hpp).
  bool plane_separates(int i, int j) {
    const Triangle& a = mesh_.triangles()[bvh_.triangle_order()[i]];
    const Triangle& b = mesh_.triangles()[bvh_.triangle_order()[j]];
    if (!detail::within_plane_range(x0_, x1_, a, b)) return false;
    return detail::plane_separates(x0_, x1_, a, triangle_normals(i), b) ||
           detail::plane_separates(x0_, x1_, b, triangle_normals(j), a);
  }

  /// The normal's Bernstein coefficients of the triangle at position i of the BVH's order
  /// (its vertices known: its sweep was formed first).
  const detail::BernsteinNormals& triangle_normals(int i) {
    return triangle_normals_.get(i, [&](int k) {
      const Triangle& t = mesh_.triangles()[bvh_.triangle_order()[k]];
      return detail::bernstein_normals(x0_[t[0]], x0_[t[1]], x0_[t[2]], x1_[t[0]], x1_[t[1]], x1_[t[2]]);
    });
  }

  /// The sweep of the triangle at position i of the BVH's order.
  const Sweep& triangle_sweep(int i) {
    return triangle_sweeps_.get(i, [&](int k) {
      const Triangle& triangle = mesh_.triangles()[bvh_.triangle_order()[k]];
      for (int v : triangle) ensure_vertex(v);
      return Sweep{box_at(x0_, triangle), box_at(x1_, triangle)};
    });
  }

  void ensure_vertex(int v) { vertices_.ensure(v, stats_); }

  /// Neither adjacent nor excluded (excluded_pairs.hpp): the pairs a query considers. The
  /// exclusion lookup only for non-adjacent pairs, and an empty set answers at once.
  bool considers(int a, int b) const { return !mesh_.adjacent(a, b) && !bvh_.model().excluded_pairs().contains(a, b); }

  Aabb point_box(int v) const { return {x0_[v].cwiseMin(x1_[v]), x0_[v].cwiseMax(x1_[v])}; }

  Aabb edge_box(int e) const {
    const Edge& ends = mesh_.edges()[e];
    return hull(point_box(ends[0]), point_box(ends[1]));
  }

  /// Whether triangle t owns the vertex-face pair (v, f), v in t: the smallest considered
  /// pair containing it is (t', f) for the smallest t' around v considered with f (pairs
  /// order by their smaller member, and f is fixed), so the first such t' decides.
  bool owns_vertex_face(int t, int v, int f) const {
#ifdef SSCC_MUTANT_OWNS_ALWAYS_TRUE
    return true;
#endif
    for (const int* u = mesh_.triangles_of_vertex_begin(v); u != mesh_.triangles_of_vertex_end(v); ++u) {
      if (considers(*u, f)) return *u == t;
    }
    return false;
  }

  /// Whether `pair` (ordered, considered, its triangles containing edges e and g) is the
  /// smallest considered triangle pair containing them: no smaller pair of their triangles
  /// is considered (the cheap order test first).
  bool owns_edge_edge(const std::pair<int, int>& pair, int e, int g) const {
#ifdef SSCC_MUTANT_OWNS_ALWAYS_TRUE
    return true;
#endif
    for (const int* t = mesh_.triangles_of_edge_begin(e); t != mesh_.triangles_of_edge_end(e); ++t) {
      for (const int* u = mesh_.triangles_of_edge_begin(g); u != mesh_.triangles_of_edge_end(g); ++u) {
        if (std::make_pair(std::min(*t, *u), std::max(*t, *u)) < pair && considers(*t, *u)) return false;
      }
    }
    return true;
  }

  void vertex_face(int v, int t) {
    if (stopped()) return;
    const Triangle& f = mesh_.triangles()[t];
    hits_.record(ccd::vertex_face_ccd(x0_[v], x0_[f[0]], x0_[f[1]], x0_[f[2]], x1_[v], x1_[f[0]], x1_[f[1]], x1_[f[2]],
                                      options_.kernel),
                 {FeatureKind::kVertexFace, v, t, 1.0});
  }

  void edge_edge(int e, int g) {
    if (stopped()) return;
    if (e > g) std::swap(e, g);
    const Edge& a = mesh_.edges()[e];
    const Edge& b = mesh_.edges()[g];
    hits_.record(ccd::edge_edge_ccd(x0_[a[0]], x0_[a[1]], x0_[b[0]], x0_[b[1]], x1_[a[0]], x1_[a[1]], x1_[b[0]],
                                    x1_[b[1]], options_.kernel),
                 {FeatureKind::kEdgeEdge, e, g, 1.0});
  }

  /// The colliding triangle pairs: every considered pair containing a feature that hit,
  /// at the earliest of its features' times.
  std::vector<TrianglePairContact> pairs_from_features() const {
    EarliestPerKey<std::pair<int, int>> earliest;
    for (const FeatureContact& c : hits_.hits()) {
      for_each_triangle_pair_of(c.kind, mesh_, c.first, mesh_, c.second, [&](int t, int u) {
        if (considers(t, u)) earliest.add({std::min(t, u), std::max(t, u)}, c.toi);
      });
    }
    std::vector<TrianglePairContact> pairs;
    for (const auto& [key, toi] : earliest.earliest()) pairs.push_back({key.first, key.second, toi});
    return pairs;
  }

  const SubspaceBvh& bvh_;
  const TriangleMesh& mesh_;
  const SelfCcdOptions& options_;
  Eigen::VectorXd q_hat0_, q_hat1_;
  double s_;
  double separation_;  // every cull widened by the kernels' minimum separation
  double norm0_, norm1_;
  detail::BufferPool<detail::BoxBuffers>::Lease buffers_;  // what the caches below refer to
  detail::StepVertices& vertices_;
  // The positions (raw pointers: the hot loops read them without an indirection).
  Eigen::Vector3d* x0_;
  Eigen::Vector3d* x1_;
  LazyBoxes<Aabb>& subspace_boxes_;
  LazyBoxes<Sweep>& node_sweeps_;
  LazyBoxes<Sweep>& coherent_sweeps_;  // coherent_sweep's bounds
  bool coherent_ = false;              // node boxes go from step to step
  bool move_boxes_ = false;            // and this step moves the last one's
  Eigen::VectorXd delta_;              // q_hat1 - q_hat0, when coherent_
  double delta_norm_ = 0.0;
  LazyBoxes<Sweep>& triangle_sweeps_;                      // by position in the BVH's triangle order
  LazyBoxes<detail::BernsteinNormals>& triangle_normals_;  // likewise
  SelfCcdStats stats_;                                     // before hits_, which keeps a pointer into it
  FeatureHits<FeatureContact> hits_;
  const detail::PatchRadii* radii_ = nullptr;               // null: no cones bounded from the norm
  const detail::PatchRadii* rest_patches_ = nullptr;        // the nodes proven at rest (null: unknown)
  bool separating_planes_ = false;                          // the triangle pairs' plane cull
  std::unique_ptr<detail::PatchCull> patch_cull_;           // null: no cones formed per step
  std::unique_ptr<detail::StepDisplacement> displacement_;  // null: no displacement cull
  const detail::UnconsideredLeafPairs* unconsidered_;       // null: no leaf pairs skipped
  const detail::FirstHitTask* cancel_ = nullptr;
  int task_ = 0;
};

/// The certificates a traversal tests (none when null), with or without the pair certificates
/// below the sibling pairs.
struct TraversalCertificates {
  const Certificates* certificates = nullptr;
  bool pairs = true;
};

/// Self-traversal (SSCC paper, Algorithm 1): intra(n) tests the node against itself,
/// inter(a, b) two disjoint nodes whose boxes overlap; with certificates, a node or sibling
/// pair whose radius exceeds s is skipped; with normal cones, a node or node pair proven free
/// of self-contact (patch_cull.hpp).
template <typename Context>
class Traversal {
 public:
  /// certificates.certificates may be null (the traditional traversal), certificates.pairs
  /// false leaves the pair certificates out; with a frontier, node pairs it takes become tasks
  /// instead of being descended (task_frontier.hpp).
  Traversal(const SubspaceBvh& bvh, Context& context, TraversalCertificates certificates, double s,
            detail::TaskFrontier* frontier = nullptr)
      : bvh_(bvh),
        context_(context),
        certificates_(certificates.certificates),
        pair_certificates_(certificates.pairs),
        s_(s),
        frontier_(frontier) {}

  void run(const detail::TraversalTask& task) { task.a == task.b ? intra(task.a) : inter(task.a, task.b, task.pair); }

  void intra(int n) {
    if (context_.stopped()) return;
    if (certificates_ && s_ < certificates_->node_radius(n)) {
      ++context_.stats().certified;
      return;
    }
    if (frontier_ && frontier_->take(n, n)) return;
    if (context_.node_held_apart(n)) {
      ++context_.stats().displacement_culled;
      return;
    }
    if (context_.node_cannot_self_touch(n)) {
      ++context_.stats().cone_culled;
      return;
    }
    ++context_.stats().nodes_visited;
    const SubspaceBvh::Node& node = bvh_.nodes()[n];
    if (node.is_leaf()) {
      for (int i = node.triangle_begin; i < node.triangle_end; ++i) {
        for (int j = i + 1; j < node.triangle_end; ++j) context_.test_triangle_pair(i, j);
      }
      return;
    }
    for (int c = node.first_child; c < node.first_child + node.child_count; ++c) intra(c);
    for (int c = node.first_child; c < node.first_child + node.child_count; ++c) {
      for (int d = c + 1; d < node.first_child + node.child_count; ++d) {
        if (context_.stopped()) return;
        // Sibling pairs have certificates, and pair certificates below them (-1: none).
        if (!certificates_) {
          inter(c, d, -1);
          continue;
        }
        if (s_ < certificates_->sibling_radius(c, d)) {
          ++context_.stats().certified;
          continue;
        }
        inter(c, d, pair_certificates_ ? certificates_->sibling_pair_certificate(c, d) : -1);
      }
    }
  }

  /// `pair`: the pair certificate of (a, b) (certificates.hpp), -1 when it has none.
  void inter(int a, int b, int pair) {
    if (context_.stopped()) return;
    int children = -1;  // the pair certificates of (a, b)'s child pairs, in descent order
    if (pair >= 0) {
      const PairCertificate& certificate = certificates_->pair_certificate(pair);
      if (s_ < certificate.radius) {
        ++context_.stats().certified;
        ++context_.stats().pair_certified;
        return;
      }
      children = certificate.first_child;
    }
    if (frontier_ && frontier_->take(a, b, pair)) return;
    if (context_.leaves_hold_no_considered_pair(a, b)) return;
    if (!context_.nodes_overlap(a, b)) return;
    if (context_.nodes_held_apart(a, b)) {
      ++context_.stats().displacement_culled;
      return;
    }
    if (context_.nodes_cannot_touch(a, b)) {
      ++context_.stats().cone_culled;
      return;
    }
    ++context_.stats().nodes_visited;
    const SubspaceBvh::Node& na = bvh_.nodes()[a];
    const SubspaceBvh::Node& nb = bvh_.nodes()[b];
    if (na.is_leaf() && nb.is_leaf()) {
      detail::for_each_pruned_leaf_pair(
          na, nb, [&](int i) { return context_.triangle_meets_node(i, b); },
          [&](int j) { return context_.triangle_meets_node(j, a); },
          [&](int i, int j) { context_.test_triangle_pair(i, j); });
      return;
    }
    descend_larger(bvh_, a, bvh_, b, [&](int x, int y) { inter(x, y, children < 0 ? -1 : children++); });
  }

 private:
  const SubspaceBvh& bvh_;
  Context& context_;
  const Certificates* certificates_;
  bool pair_certificates_;
  double s_;
  detail::TaskFrontier* frontier_;
};

/// The traversal from the root on `threads` > 1 threads: the top expanded into tasks
/// (task_frontier.hpp), the tasks run on one context per thread (make_context() makes
/// one; the expansion's own is reused by the first thread), their hits merged in task
/// order; in the any-hit mode only the first task's that hit. The counters are summed over
/// the contexts: boxes computed by several threads count once per thread (the vertices are
/// computed once, up front: step_vertices.hpp). The tasks carry their pair certificate; the
/// steps query() runs on several threads compute every vertex and walk none, so there it is -1.
template <typename MakeContext>
SelfCcdReport parallel_traversal(const SubspaceBvh& bvh, TraversalCertificates certificates, double s,
                                 const SelfCcdOptions& options, int threads, MakeContext make_context,
                                 std::chrono::steady_clock::time_point start) {
  std::vector<std::unique_ptr<StepContext>> contexts(threads);
  contexts[0] = make_context();
  detail::TaskFrontier frontier(bvh, threads);
  Traversal<StepContext>(bvh, *contexts[0], certificates, s, &frontier).intra(0);
  const std::vector<detail::TraversalTask>& tasks = frontier.tasks();
  const int count = static_cast<int>(tasks.size());
  const bool any_hit = options.mode == SelfCcdMode::kAnyHit;
  std::vector<std::vector<FeatureContact>> hits(count);
  detail::FirstHitTask first_hit;
  detail::run_tasks(count, std::max(1, std::min(threads, count)), [&](int task, int thread) {
    if (any_hit && first_hit.cancels(task)) return;
    if (!contexts[thread]) contexts[thread] = make_context();
    StepContext& context = *contexts[thread];
    context.begin_task(task, any_hit ? &first_hit : nullptr);
    Traversal<StepContext>(bvh, context, certificates, s).run(tasks[task]);
    hits[task] = context.take_hits();
    if (any_hit && !hits[task].empty()) first_hit.hit(task);
  });
  std::vector<FeatureContact> merged;
  for (std::vector<FeatureContact>& h : hits) {
    merged.insert(merged.end(), h.begin(), h.end());
    if (any_hit && !merged.empty()) break;
  }
  SelfCcdStats stats;
  for (const auto& context : contexts) {
    if (context) detail::add_counts(stats, context->stats());
  }
  contexts[0]->absorb(std::move(merged), stats);
  return contexts[0]->finish(start);
}

/// Discrete variant: boxes at one configuration, exact triangle-triangle tests.
class DiscreteContext {
 public:
  DiscreteContext(const SubspaceBvh& bvh, const Eigen::VectorXd& q_hat, double norm, const SelfCcdOptions& options)
      : bvh_(bvh),
        options_(options),
        q_hat_(q_hat),
        norm_(norm),
        x_(bvh.model().mesh().vertex_count()),
        computed_(x_.size(), 0),
        boxes_(bvh.nodes().size()) {}

  bool nodes_overlap(int a, int b) {
    ++stats_.box_tests;
    const auto at_q = [&](int n) { return bvh_.box(n, q_hat_, norm_); };
    return boxes_.get(a, at_q).overlaps(boxes_.get(b, at_q));
  }
  bool stopped() const { return stop_; }
  SelfCcdStats& stats() { return stats_; }
  bool node_cannot_self_touch(int) const { return false; }  // the cones are a continuous cull
  bool nodes_cannot_touch(int, int) const { return false; }
  bool node_held_apart(int) const { return false; }  // bounds over a step; the discrete query has certificates
  bool nodes_held_apart(int, int) const { return false; }
  bool leaves_hold_no_considered_pair(int, int) const { return false; }
  bool triangle_meets_node(int, int) const { return true; }

  /// The triangles at positions i and j of the BVH's order.
  void test_triangle_pair(int i, int j) {
    const TriangleMesh& mesh = bvh_.model().mesh();
    const int a = bvh_.triangle_order()[i];
    const int b = bvh_.triangle_order()[j];
    if (stop_ || !bvh_.model().considers(a, b)) return;
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

SelfCcd::SelfCcd(const SubspaceBvh& bvh) : SelfCcd(std::make_shared<const SubspaceBvh>(bvh)) {}

SelfCcd::SelfCcd(const SubspaceBvh& bvh, const Certificates& certificates)
    : SelfCcd(std::make_shared<const SubspaceBvh>(bvh), std::make_shared<const Certificates>(certificates)) {}

namespace detail {

/// The culls' static data of one hierarchy, each part built once, when a query first needs
/// it (0.3 s for the boundary chains of a 75k-triangle mesh: not worth paying for detectors
/// that never use the cones).
class CullData {
 public:
  CullData(std::shared_ptr<const SubspaceBvh> bvh, std::shared_ptr<const Certificates> certificates)
      : bvh_(std::move(bvh)), certificates_(std::move(certificates)) {}
  /// For a query with these options: null when it does not use the cones, or when they do
  /// not pay on this mesh (patch_cull.hpp, kSmallestMeanRestPatch).
  const NodeBoundaries* boundaries(const SelfCcdOptions& options) {
    if (!options.use_normal_cones) return nullptr;
    build_boundaries();
    return cones_pay_ ? boundaries_.get() : nullptr;
  }
  /// The parts built so far.
  SelfCcdBuiltParts built() const {
    SelfCcdBuiltParts parts;
    parts.cone_boundaries = built_[kBoundaries].load();
    parts.cone_radii = built_[kPatchRadii].load();
    parts.unconsidered_leaf_pairs = built_[kUnconsidered].load();
    parts.certified_radii = built_[kCertifiedRadii].load();
    parts.displacement_bounds = built_[kDisplacement].load();
    return parts;
  }
  /// The fraction of the nodes of at least kSmallestCountedNode triangles whose certificates
  /// hold at norm s (s below their radius); 0 when there are none.
  double certified_fraction(double s) {
    std::call_once(radii_once_, [&] {
      for (int n = 0; n < static_cast<int>(bvh_->nodes().size()); ++n) {
        const SubspaceBvh::Node& node = bvh_->nodes()[n];
        if (node.triangle_end - node.triangle_begin >= detail::kSmallestCountedNode)
          radii_.push_back(certificates_->node_radius(n));
      }
      std::sort(radii_.begin(), radii_.end());
      built_[kCertifiedRadii] = true;
    });
    return fraction_above(radii_, s);
  }
  /// The certificates' estimate of the traversal's uncertified work at norm s, over the
  /// triangle count (uncertified_work.hpp).
  double uncertified_work(double s) {
    std::call_once(work_once_, [&] { work_ = std::make_unique<const UncertifiedWork>(*bvh_, *certificates_); });
    return work_->fraction(s);
  }
  /// Null when the query does not use the cones. Built on any mesh: they cost O(1) per node
  /// per query, so kSmallestMeanRestPatch does not apply.
  const PatchRadii* radii(const SelfCcdOptions& options) {
    if (!options.use_normal_cones) return nullptr;
    std::call_once(patch_radii_once_, [&] {
      build_boundaries();
      patch_radii_ = std::make_unique<const PatchRadii>(*bvh_, *boundaries_);
      built_[kPatchRadii] = true;
    });
    return patch_radii_.get();
  }
  /// Null when the query does not use the displacement bounds (they are not used with
  /// certificates: self_ccd.cpp, SelfCcd::query).
  const DisplacementBounds* displacement(const SelfCcdOptions& options, bool with_certificates) {
    if (!options.use_displacement_bounds || with_certificates) return nullptr;
    std::call_once(displacement_once_, [&] {
      displacement_ = std::make_unique<const DisplacementBounds>(*bvh_);
      built_[kDisplacement] = true;
    });
    return displacement_.get();
  }
  /// Null when the query does not use the cones (the leaf pairs are skipped with them, so
  /// that the traditional query stays the paper's).
  const UnconsideredLeafPairs* unconsidered_leaf_pairs(const SelfCcdOptions& options) {
    if (!options.use_normal_cones) return nullptr;
    std::call_once(unconsidered_once_, [&] {
      unconsidered_ = std::make_unique<const UnconsideredLeafPairs>(*bvh_);
      built_[kUnconsidered] = true;
    });
    return unconsidered_.get();
  }
  /// The basis in the hierarchy's order, for steps that compute vertices on demand.
  const HierarchyVertices* hierarchy_vertices() {
    std::call_once(vertices_once_, [&] { vertices_ = std::make_unique<const HierarchyVertices>(*bvh_); });
    return vertices_.get();
  }
  /// The buffers the queries lend (step_buffers.hpp): a query's positions, and each of its
  /// contexts' caches.
  BufferPool<VertexBuffers>& vertex_buffers() { return vertex_buffers_; }
  BufferPool<BoxBuffers>& box_buffers() { return box_buffers_; }

 private:
  void build_boundaries() {
    std::call_once(boundaries_once_, [&] {
      boundaries_ = std::make_unique<const NodeBoundaries>(*bvh_);
      cones_pay_ = mean_patch_at_rest(*bvh_, *boundaries_) >= kSmallestMeanRestPatch;
      built_[kBoundaries] = true;
    });
  }

  enum Part { kBoundaries, kPatchRadii, kUnconsidered, kCertifiedRadii, kDisplacement, kPartCount };

  std::shared_ptr<const SubspaceBvh> bvh_;
  std::shared_ptr<const Certificates> certificates_;
  std::once_flag boundaries_once_, displacement_once_, radii_once_, patch_radii_once_, unconsidered_once_, work_once_,
      vertices_once_;
  std::vector<double> radii_;  // sorted
  std::unique_ptr<const NodeBoundaries> boundaries_;
  bool cones_pay_ = false;
  std::unique_ptr<const DisplacementBounds> displacement_;
  std::unique_ptr<const PatchRadii> patch_radii_;
  std::unique_ptr<const UnconsideredLeafPairs> unconsidered_;
  std::unique_ptr<const UncertifiedWork> work_;
  std::unique_ptr<const HierarchyVertices> vertices_;
  std::atomic<bool> built_[kPartCount] = {};
  BufferPool<VertexBuffers> vertex_buffers_;
  BufferPool<BoxBuffers> box_buffers_;
};

}  // namespace detail

SelfCcd::SelfCcd(std::shared_ptr<const SubspaceBvh> bvh, std::shared_ptr<const Certificates> certificates)
    : bvh_(std::move(bvh)), certificates_(std::move(certificates)) {
  if (!bvh_) throw std::invalid_argument("SelfCcd: no hierarchy");
  if (certificates_) certificates_->check_belongs_to(*bvh_);
  culls_ = std::make_shared<detail::CullData>(bvh_, certificates_);
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

/// Whether a step of norm s is far past the root's certificate, or there are none.
bool far_past_root(const Certificates* certificates, double s) {
  return !certificates || s > kFarPastCertificateRatio * certificates->node_radius(0);
}

/// How a query past the root's certificate computes its vertices, on how many threads.
struct StepPlan {
  bool every_vertex;  // up front, else on demand
  int threads;
};

StepPlan plan_step(detail::CullData& culls, const Certificates* certificates, double s, const SelfCcdOptions& options) {
  // Without certificates, or far past the root's while they leave most of the hierarchy to
  // the traversal, it reaches nearly every vertex (neighbouring leaves' boxes always meet):
  // computed up front, a share per thread, and the traversal's work repays the threads.
  // Closer to the root's radius, certificates cull most of what the threads would share:
  // one thread. Measured on the hard spring (`sscc demo --scene spring --strike-speed 7
  // --steps 17640 --fcl-steps 0 --threads 2`), its lazy steps on both threads, the vertices
  // shared between them: SSCC 0.146 ms per step against 0.115 on one thread, slower on
  // every size of step.
  const bool every_vertex = far_past_root(certificates, s) &&
                            (!certificates || culls.uncertified_work(s) > kLargestUncertifiedWorkForLazySteps);
  return {every_vertex, every_vertex ? detail::resolve_threads(options.threads) : 1};
}

/// The traversal from the root on the calling thread.
template <typename MakeContext>
SelfCcdReport serial_traversal(const SubspaceBvh& bvh, TraversalCertificates certificates, double s,
                               MakeContext make_context, std::chrono::steady_clock::time_point start) {
  const std::unique_ptr<StepContext> context = make_context();
  Traversal<StepContext>(bvh, *context, certificates, s).intra(0);
  return context->finish(start);
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
  const Certificates* certificates = usable(certificates_.get(), options);
  const Eigen::VectorXd q_hat0 = bvh_->model().scaled_coordinates(q0);
  const Eigen::VectorXd q_hat1 = bvh_->model().scaled_coordinates(q1);
  const double s = std::max(q_hat0.stableNorm(), q_hat1.stableNorm());
  if (certificates && s < certificates->node_radius(0)) return root_certified_report(start);
  const StepPlan plan = plan_step(*culls_, certificates, s, options);
  // The displacement cull only without certificates: with them it culls what they cull, a
  // little later, at O(r) per node (measured on the default demo's traversed steps, 2.13 ms
  // per step with it against 2.02 ms without; without certificates 6.0 ms against 9.1 ms).
  // The normal cones only where the certificates leave most of the hierarchy to the
  // traversal: a cone costs every normal under its node, which is wasted under certified
  // subtrees.
  StepCulls culls;
  culls.displacement = culls_->displacement(options, certificates != nullptr);
  culls.boundaries =
      !options.use_normal_cones || (certificates && culls_->certified_fraction(s) > kLargestCertifiedFractionForCones)
          ? nullptr
          : culls_->boundaries(options);
  culls.radii = culls_->radii(options);
  culls.unconsidered = culls_->unconsidered_leaf_pairs(options);
  // The buffers the last query ended in, when this step starts there (a simulator's next step).
  const auto positions = culls_->vertex_buffers().lend(
      [&](const detail::VertexBuffers& b) { return detail::StepVertices::same_bits(b.end_coordinates, q_hat0); });
  detail::StepVertices vertices(*positions, bvh_->model(), plan.every_vertex ? nullptr : culls_->hierarchy_vertices(),
                                q_hat0, q_hat1);
  if (plan.every_vertex) vertices.compute_every_vertex(plan.threads);
  const auto make_context = [&] {
    return std::make_unique<StepContext>(*bvh_, q_hat0, q_hat1, s, options, culls, culls_->box_buffers(), vertices);
  };
  // Steps that compute every vertex are those whose open ends fail for most of the mesh: there
  // the pair certificates hold for few pairs, and walking them costs a load per node pair (the
  // dragon at amplitude 0.2 in the self-CCD table: 18.4 ms per step with them, 17.9 ms without).
  const TraversalCertificates tested{certificates, !plan.every_vertex};
  SelfCcdReport report = plan.threads > 1
                             ? parallel_traversal(*bvh_, tested, s, options, plan.threads, make_context, start)
                             : serial_traversal(*bvh_, tested, s, make_context, start);
  detail::add_counts(report.stats, vertices.up_front());
  return report;
}

void SelfCcd::prepare(const SelfCcdOptions& options) const {
  const Certificates* certificates = usable(certificates_.get(), options);
  culls_->boundaries(options);
  culls_->radii(options);
  culls_->displacement(options, certificates != nullptr);
  culls_->unconsidered_leaf_pairs(options);
  if (certificates && options.use_normal_cones) culls_->certified_fraction(0.0);  // query() asks for it then
  if (certificates) {
    culls_->uncertified_work(0.0);
    culls_->hierarchy_vertices();  // the steps near the root's radius compute vertices on demand
  }
}

SelfCcdBuiltParts SelfCcd::built_parts() const { return culls_->built(); }

double SelfCcd::step_norm(const Eigen::VectorXd& q0, const Eigen::VectorXd& q1) const {
  const SubspaceModel& model = bvh_->model();
  return std::max(model.scaled_coordinates(q0).stableNorm(), model.scaled_coordinates(q1).stableNorm());
}

bool SelfCcd::root_certifies(const Eigen::VectorXd& q0, const Eigen::VectorXd& q1,
                             const SelfCcdOptions& options) const {
  const Certificates* certificates = usable(certificates_.get(), options);
  return certificates && step_norm(q0, q1) < certificates->node_radius(0);
}

int SelfCcd::query_threads(const Eigen::VectorXd& q0, const Eigen::VectorXd& q1, const SelfCcdOptions& options) const {
  const Certificates* certificates = usable(certificates_.get(), options);
  const double s = step_norm(q0, q1);
  if (certificates && s < certificates->node_radius(0)) return 1;
  return plan_step(*culls_, certificates, s, options).threads;
}

SelfCcdReport SelfCcd::query_positions(const std::vector<Eigen::Vector3d>& x0, const std::vector<Eigen::Vector3d>& x1,
                                       const SelfCcdOptions& options) const {
  const auto start = std::chrono::steady_clock::now();
  const int vertices = bvh_->model().mesh().vertex_count();
  for (const auto* x : {&x0, &x1}) {
    if (static_cast<int>(x->size()) != vertices) {
      throw std::invalid_argument("SelfCcd::query_positions: " + std::to_string(x->size()) +
                                  " positions given for a mesh of " + std::to_string(vertices) + " vertices");
    }
    for (std::size_t v = 0; v < x->size(); ++v) {
      if (!all_finite((*x)[v])) {
        throw std::invalid_argument("SelfCcd::query_positions: vertex " + std::to_string(v) +
                                    " has a NaN or infinite coordinate");
      }
    }
  }
  SelfCcdOptions refit = options;
  refit.bounds = NodeBounds::kRefit;
  StepCulls culls;
  culls.boundaries = culls_->boundaries(options);
  culls.unconsidered = culls_->unconsidered_leaf_pairs(options);
  const int threads = detail::resolve_threads(options.threads);
  const auto positions = culls_->vertex_buffers().lend();
  detail::StepVertices given(*positions, x0, x1);
  const Eigen::VectorXd none;  // no coordinates
  const auto make_context = [&] {
    return std::make_unique<StepContext>(*bvh_, none, none, 0.0, refit, culls, culls_->box_buffers(), given);
  };
  return threads > 1 ? parallel_traversal(*bvh_, {}, 0.0, refit, threads, make_context, start)
                     : serial_traversal(*bvh_, {}, 0.0, make_context, start);
}

SelfCcdReport SelfCcd::query_discrete(const Eigen::VectorXd& q, const SelfCcdOptions& options) const {
  const auto start = std::chrono::steady_clock::now();
  const Certificates* certificates = usable(certificates_.get(), options);
  const Eigen::VectorXd q_hat = bvh_->model().scaled_coordinates(q);
  const double s = q_hat.stableNorm();
  if (certificates && s < certificates->node_radius(0)) return root_certified_report(start);
  DiscreteContext context(*bvh_, q_hat, s, options);
  Traversal<DiscreteContext>(*bvh_, context, {certificates, true}, s).intra(0);
  return context.finish(start);
}

SelfCcdReport SelfCcd::query_exhaustive(const Eigen::VectorXd& q0, const Eigen::VectorXd& q1,
                                        const SelfCcdOptions& options) const {
  const auto start = std::chrono::steady_clock::now();
  const Eigen::VectorXd q_hat0 = bvh_->model().scaled_coordinates(q0);
  const Eigen::VectorXd q_hat1 = bvh_->model().scaled_coordinates(q1);
  SelfCcdOptions reference = options;  // no cull: nor the triangle pairs' separating planes
  reference.use_normal_cones = false;
  const auto positions = culls_->vertex_buffers().lend();
  detail::StepVertices vertices(*positions, bvh_->model(), nullptr, q_hat0, q_hat1);
  vertices.compute_every_vertex(1);
  StepContext context(*bvh_, q_hat0, q_hat1, std::max(q_hat0.stableNorm(), q_hat1.stableNorm()), reference, StepCulls{},
                      culls_->box_buffers(), vertices);
  const int n = bvh_->model().mesh().triangle_count();
  for (int i = 0; i < n && !context.stopped(); ++i) {  // positions in the BVH's order: every pair
    for (int j = i + 1; j < n && !context.stopped(); ++j) context.test_triangle_pair(i, j);
  }
  SelfCcdReport report = context.finish(start);
  detail::add_counts(report.stats, vertices.up_front());
  return report;
}

}  // namespace sscc
