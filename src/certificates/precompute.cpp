#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "certificates/box_box_bound.hpp"
#include "certificates/near_pair.hpp"
#include "certificates/precompute_driver.hpp"
#include "query/descent.hpp"
#include "sscc/ccd/kernels.hpp"
#include "sscc/certificates/certificates.hpp"
#include "sscc/certificates/triangle_pair_bound.hpp"
#include "sscc/common/timing.hpp"
#include "sscc/threads.hpp"

namespace sscc {

namespace {

using detail::box_box_radius;

// A sibling pair's radius is resolved up to this multiple of the smallest radius known in
// its parent at the time (and R_global), on its own rather than lowered to the parent's
// minimum: a step a little above the parent's radius is then still certified for most of
// its sibling pairs. Larger: more precomputation for pairs that rarely matter; 1 gives the
// paper's running minimum (sibling radii close to the parent's).
constexpr double kSiblingReach = 2.0;

/// The minimum radius over the pairs seen so far, as a lower bound and as the smallest
/// contact configuration found (an upper bound). Lower bounds accurate to epsilon relative
/// to `contact` keep the minimum accurate to epsilon without resolving every pair to it.
struct RunningMinimum {
  double lower;
  double contact;
  void add(double pair_lower, double pair_contact) {
    lower = std::min(lower, pair_lower);
    contact = std::min(contact, pair_contact);
  }
};

struct Counters {
  long node_pairs_visited = 0, node_pairs_culled = 0, triangle_pairs_culled = 0, triangle_pairs_bounded = 0,
       evaluations = 0, pair_tree_tasks = 0;
  void add(const Counters& o) {
    node_pairs_visited += o.node_pairs_visited;
    node_pairs_culled += o.node_pairs_culled;
    triangle_pairs_culled += o.triangle_pairs_culled;
    triangle_pairs_bounded += o.triangle_pairs_bounded;
    evaluations += o.evaluations;
    pair_tree_tasks += o.pair_tree_tasks;
  }
};

/// How finely the triangle pairs are resolved: the node radii's accuracy, or the pair
/// certificates' looser one.
struct Accuracy {
  double epsilon;
  int max_depth;
  int max_evaluations;
};

class Precomputation {
 public:
  /// `global`: R_global, the largest radius kept.
  Precomputation(const SubspaceBvh& bvh, const CertificateParameters& parameters, double global)
      : bvh_(bvh),
        mesh_(bvh.model().mesh()),
        parameters_(parameters),
        global_(global),
        slot_(mesh_.triangle_count()),
        triangles_(mesh_.triangle_count()),
        summaries_(mesh_.triangle_count()),
        groups_(bvh.nodes().size()) {
    // Stored (and allocated) in the hierarchy's order: a node pair's triangles then lie
    // together in memory, which on large meshes (the bunny's 75k triangles hold about 360 MB of
    // modes and summaries, the summaries' row-major copies of the modes included) saves cache
    // misses in the descents that visit every pair.
    const RowMajorMatrix& basis = bvh.model().scaled_basis();
    const std::vector<int>& order = bvh.triangle_order();
    for (int slot = 0; slot < mesh_.triangle_count(); ++slot) {
      const int t = order[slot];
      slot_[t] = slot;
      for (int i = 0; i < 3; ++i) {
        const int v = mesh_.triangles()[t][i];
        triangles_[slot].rest[i] = mesh_.vertices()[v];
        triangles_[slot].modes[i] = basis.middleRows<3>(3 * v);
      }
      summaries_[slot] = summarize(triangles_[slot]);
    }
    for (int n = 0; n < static_cast<int>(bvh.nodes().size()); ++n) {
      const SubspaceBvh::Node& node = bvh.nodes()[n];
      groups_[n] = summarize_group(&triangles_[node.triangle_begin], &summaries_[node.triangle_begin],
                                   node.triangle_end - node.triangle_begin, bvh.subspace_bound(n).mean_modes);
    }
  }

  /// Folds the considered pairs (neither adjacent nor excluded) among `pairs` into the
  /// running minimum, in order of their 1D bound; pairs whose bound reaches the minimum's
  /// lower bound cannot lower it. The minimum's lower bound only falls, so a pair whose 1D
  /// bound (or its floor) reaches it on entry would be cut there after sorting: it is cut
  /// before sorting, and the pairs bounded, their order and the minimum stay the same.
  void add_triangle_pairs(const std::vector<std::pair<int, int>>& pairs, RunningMinimum& minimum, Counters& counters,
                          const Accuracy& accuracy) const {
    // Reused by each thread's calls (millions of them), as the pairs' lists below.
    thread_local std::vector<std::pair<double, std::pair<int, int>>> ordered;
    ordered.clear();
    long culled = 0;
    for (const auto& [s, t] : pairs) {
      if (!bvh_.model().considers(s, t)) continue;
      const double estimate = one_dimensional_radius(triangle(s), triangle(t), summary(s), summary(t), minimum.lower);
      if (estimate >= minimum.lower) {
        ++culled;
        continue;
      }
      ordered.push_back({estimate, {s, t}});
    }
    counters.triangle_pairs_culled += culled;
    std::sort(ordered.begin(), ordered.end());
    for (std::size_t i = 0; i < ordered.size(); ++i) {
      const auto& [estimate, pair] = ordered[i];
      if (estimate >= minimum.lower) {
        counters.triangle_pairs_culled += static_cast<long>(ordered.size() - i);
        return;
      }
      const ModalTriangle& a = triangle(pair.first);
      const ModalTriangle& b = triangle(pair.second);
      // Projections apart means disjoint; otherwise triangles meeting at rest have radius 0.
      if (estimate == 0.0 &&
          ccd::triangles_intersect(a.rest[0], a.rest[1], a.rest[2], b.rest[0], b.rest[1], b.rest[2])) {
        minimum.lower = minimum.contact = 0.0;
        return;
      }
      TrianglePairRadiusOptions options;
      options.epsilon = accuracy.epsilon;
      options.target = minimum.contact;
      options.ceiling = minimum.lower;
      options.max_depth = accuracy.max_depth;
      options.max_evaluations = accuracy.max_evaluations;
      const TrianglePairRadius r = triangle_pair_radius(a, b, options);
      ++counters.triangle_pairs_bounded;
      counters.evaluations += r.evaluations;
      minimum.add(r.lower, r.upper);
    }
  }

  /// Folds the pairs of triangles of two disjoint nodes into the running minimum: children
  /// pairs in order of their box bound.
  void add_node_pair(int a, int b, RunningMinimum& minimum, Counters& counters) const {
    add_node_pair(a, b, minimum, counters, node_accuracy());
  }

  void add_node_pair(int a, int b, RunningMinimum& minimum, Counters& counters, const Accuracy& accuracy) const {
    ++counters.node_pairs_visited;
    // Every triangle pair of the two nodes would be left out by its own screening.
    if (group_pair_floor(groups_[a], groups_[b], bvh_.subspace_bound(a).mean_modes,
                         bvh_.subspace_bound(b).mean_modes) >= minimum.lower) {
      ++counters.node_pairs_culled;
      return;
    }
    const SubspaceBvh::Node& na = bvh_.nodes()[a];
    const SubspaceBvh::Node& nb = bvh_.nodes()[b];
    if (na.is_leaf() && nb.is_leaf()) {
      add_triangle_pairs(leaf_pair_triangles(na, nb), minimum, counters, accuracy);
      return;
    }
    const bool split_a = detail::splits_first(na, nb);
    const SubspaceBvh::Node& split = split_a ? na : nb;
    const int other = split_a ? b : a;
    std::array<std::pair<double, int>, kBranchingFactor> children;
    for (int i = 0; i < split.child_count; ++i) {
      const int c = split.first_child + i;
      children[i] = {box_box_radius(bvh_, c, other), c};
    }
    // In order of their box bound (an insertion sort: at most kBranchingFactor of them).
    for (int i = 1; i < split.child_count; ++i) {
      for (int j = i; j > 0 && children[j] < children[j - 1]; --j) std::swap(children[j], children[j - 1]);
    }
    for (int i = 0; i < split.child_count; ++i) {
      const auto& [estimate, c] = children[i];
      if (estimate >= minimum.lower) {
        ++counters.node_pairs_culled;
        continue;
      }
      add_node_pair(c, other, minimum, counters, accuracy);
    }
  }

  /// The pair certificates below sibling pair (a, b), resolved up to `reach`: entry 0 is the
  /// pair itself (its radius set by the caller), then the children blocks, depth first. The
  /// pairs are laid out first; the radii of the far and leaf pairs (independent descents, each
  /// from `reach`) are computed next, the large ones as OpenMP tasks that idle threads take up;
  /// then the near pairs' radii and the blocks kept. The result does not depend on the order.
  std::vector<PairCertificate> pair_tree(int a, int b, double reach, Counters& counters) const {
    std::vector<PairShape> shape(1, PairShape{a, b});
    lay_out_pair_children(0, reach, shape, counters);
    std::vector<Counters> job_counters(shape.size());
    for (std::size_t i = 0; i < shape.size(); ++i) {
      if (shape[i].job == PairJob::kNone) continue;
      if (triangle_pairs_below(shape[i]) < kSmallestPairTask) {
        run_pair_job(shape[i], reach, job_counters[i]);
        continue;
      }
      ++counters.pair_tree_tasks;
#pragma omp task default(none) firstprivate(i, reach) shared(shape, job_counters)
      run_pair_job(shape[i], reach, job_counters[i]);
    }
#pragma omp taskwait
    for (const Counters& c : job_counters) counters.add(c);
    resolve_near_radius(0, reach, shape);
    std::vector<PairCertificate> tree(1);
    emit_pair_children(shape, 0, reach, tree, 0);
    return tree;
  }

  /// Folds a leaf's own non-adjacent pairs into the running minimum.
  void add_leaf(int n, RunningMinimum& minimum, Counters& counters) const {
    const SubspaceBvh::Node& node = bvh_.nodes()[n];
    std::vector<std::pair<int, int>> pairs;
    const std::vector<int>& order = bvh_.triangle_order();
    for (int i = node.triangle_begin; i < node.triangle_end; ++i) {
      for (int j = i + 1; j < node.triangle_end; ++j) pairs.push_back({order[i], order[j]});
    }
    add_triangle_pairs(pairs, minimum, counters, node_accuracy());
  }

 private:
  const ModalTriangle& triangle(int t) const { return triangles_[slot_[t]]; }
  const TriangleSummary& summary(int t) const { return summaries_[slot_[t]]; }

  Accuracy node_accuracy() const {
    return {parameters_.epsilon, parameters_.max_subdivision_depth, parameters_.max_evaluations_per_pair};
  }
  Accuracy pair_accuracy() const {
    return {std::max(parameters_.epsilon, kPairEpsilon), parameters_.max_subdivision_depth,
            std::min(parameters_.max_evaluations_per_pair, kPairEvaluations)};
  }

  /// The pairs of triangles of leaves na and nb, in a list each thread reuses (valid until
  /// its next call).
  const std::vector<std::pair<int, int>>& leaf_pair_triangles(const SubspaceBvh::Node& na,
                                                              const SubspaceBvh::Node& nb) const {
    thread_local std::vector<std::pair<int, int>> pairs;
    pairs.clear();
    const std::vector<int>& order = bvh_.triangle_order();
    for (int i = na.triangle_begin; i < na.triangle_end; ++i) {
      for (int j = nb.triangle_begin; j < nb.triangle_end; ++j) pairs.push_back({order[i], order[j]});
    }
    return pairs;
  }

  /// How a pair tree's entry gets its radius: from its children (near pairs), its box bound
  /// (far pairs the bound puts at the reach or beyond), or a descent of its own from the reach.
  enum class PairJob { kNone, kLeafPairs, kNodePair };
  struct PairShape {
    int x, y;
    int first_child = -1, child_count = 0;  // a near inner pair's block in the shape
    PairJob job = PairJob::kNone;
    // The box bound (a far pair's, when at the reach or beyond), the descent's (below it), or
    // the least of the reach and the children's (a near pair's).
    double radius = 0.0;
  };
  // Pair tree descents below this many triangle pairs run where they are met. A task costs
  // about a microsecond to hand over, 512 screened pairs 50-100 us: larger, fewer tasks to
  // even out the end of a level; smaller, more overhead for work that is already spread.
  static constexpr long kSmallestPairTask = 512;

  long triangle_pairs_below(const PairShape& entry) const {
    const SubspaceBvh::Node& nx = bvh_.nodes()[entry.x];
    const SubspaceBvh::Node& ny = bvh_.nodes()[entry.y];
    return static_cast<long>(nx.triangle_end - nx.triangle_begin) * (ny.triangle_end - ny.triangle_begin);
  }

  /// Lays out entry `self`, the pair (x, y): its block of child pairs (the larger node split,
  /// as the traversal does), near children recursively; far ones get their box bound, and a
  /// descent when it lies below `reach`; a leaf pair its triangle pairs.
  void lay_out_pair_children(std::size_t self, double reach, std::vector<PairShape>& shape, Counters& counters) const {
    ++counters.node_pairs_visited;
    const int x = shape[self].x, y = shape[self].y;
    const SubspaceBvh::Node& nx = bvh_.nodes()[x];
    const SubspaceBvh::Node& ny = bvh_.nodes()[y];
    if (nx.is_leaf() && ny.is_leaf()) {
      shape[self].job = PairJob::kLeafPairs;
      return;
    }
    const bool split_x = detail::splits_first(nx, ny);
    const SubspaceBvh::Node& split = split_x ? nx : ny;
    const std::size_t block = shape.size();
    shape[self].first_child = static_cast<int>(block);
    shape[self].child_count = split.child_count;
    for (int i = 0; i < split.child_count; ++i) {
      const int c = split.first_child + i;
      shape.push_back(PairShape{split_x ? c : x, split_x ? y : c});
    }
    for (std::size_t entry = block; entry < block + static_cast<std::size_t>(split.child_count); ++entry) {
      const int a = shape[entry].x, b = shape[entry].y;
      if (detail::near_at_rest(bvh_, a, b)) {
        lay_out_pair_children(entry, reach, shape, counters);
      } else {
        shape[entry].radius = box_box_radius(bvh_, a, b);
        if (shape[entry].radius < reach) shape[entry].job = PairJob::kNodePair;
      }
    }
  }

  /// The radius of a far or leaf pair up to `reach`: its pairs folded into a minimum from it.
  void run_pair_job(PairShape& entry, double reach, Counters& counters) const {
    RunningMinimum minimum{reach, reach};
    if (entry.job == PairJob::kLeafPairs) {
      add_triangle_pairs(leaf_pair_triangles(bvh_.nodes()[entry.x], bvh_.nodes()[entry.y]), minimum, counters,
                         pair_accuracy());
    } else {
      add_node_pair(entry.x, entry.y, minimum, counters, pair_accuracy());
    }
    entry.radius = minimum.lower;
  }

  /// A near inner pair's radius up to `reach`: the least of its children's (theirs first).
  double resolve_near_radius(std::size_t self, double reach, std::vector<PairShape>& shape) const {
    PairShape& entry = shape[self];
    if (entry.child_count == 0) return entry.radius;
    double radius = reach;
    for (int i = 0; i < entry.child_count; ++i) {
      radius = std::min(radius, resolve_near_radius(static_cast<std::size_t>(entry.first_child + i), reach, shape));
    }
    return entry.radius = radius;
  }

  /// Gives entry `self` of `tree` the block of shape entry `from`'s children, with their radii,
  /// depth first; a near child's block is dropped when it is certified up to the reach (its
  /// children would never be tested).
  void emit_pair_children(const std::vector<PairShape>& shape, std::size_t from, double reach,
                          std::vector<PairCertificate>& tree, std::size_t self) const {
    const PairShape& entry = shape[from];
    if (entry.child_count == 0) return;
    const std::size_t block = tree.size();
    tree.resize(block + static_cast<std::size_t>(entry.child_count));
    tree[self].first_child = static_cast<std::int32_t>(block);
    for (int i = 0; i < entry.child_count; ++i) {
      const std::size_t child = static_cast<std::size_t>(entry.first_child + i);
      tree[block + static_cast<std::size_t>(i)].radius = std::min(shape[child].radius, global_);
      if (shape[child].radius < reach)
        emit_pair_children(shape, child, reach, tree, block + static_cast<std::size_t>(i));
    }
  }

  const SubspaceBvh& bvh_;
  const TriangleMesh& mesh_;
  const CertificateParameters& parameters_;
  double global_;
  std::vector<int> slot_;  // mesh triangle -> its position in triangles_ and summaries_
  std::vector<ModalTriangle> triangles_;
  std::vector<TriangleSummary> summaries_;
  std::vector<TriangleGroupSummary> groups_;  // per node, against its mean modes
};

/// The norm at which the floppiest mode moves some vertex by half the bounding-box
/// diagonal (SSCC paper, section 5.2), times the scale.
double global_radius_of(const SubspaceModel& model, double scale) {
  const RowMajorMatrix& basis = model.scaled_basis();
  double largest = 0.0;
  for (int j = 0; j < model.mode_count(); ++j) {
    for (int v = 0; v < model.mesh().vertex_count(); ++v)
      largest = std::max(largest, basis.middleRows<3>(3 * v).col(j).norm());
  }
  const double radius = 0.5 * model.mesh().bounding_box_diagonal();
  return largest > 0.0 ? scale * radius / largest : INFINITY;
}

}  // namespace

Certificates::Certificates(const SubspaceBvh& bvh, const CertificateParameters& parameters)
    : parameters_(parameters),
      key_(key_of(bvh, parameters)),
      node_radius_(bvh.nodes().size(), 0.0),
      first_sibling_(bvh.nodes().size(), 0),
      sibling_radius_(bvh.nodes().size()),
      sibling_tree_(bvh.nodes().size()) {
  for (const SubspaceBvh::Node& node : bvh.nodes()) {
    for (int c = node.first_child; c < node.first_child + node.child_count; ++c) first_sibling_[c] = node.first_child;
  }
  for (auto& radii : sibling_radius_) radii.fill(0.0);
  for (auto& tree : sibling_tree_) tree.fill(-1);
}

void Certificates::assemble_pair_certificates(
    std::vector<std::array<std::vector<PairCertificate>, kBranchingFactor>>& trees) {
  pairs_.clear();
  for (std::size_t a = 0; a < trees.size(); ++a) {
    for (std::size_t position = 0; position < kBranchingFactor; ++position) {
      std::vector<PairCertificate>& tree = trees[a][position];
      if (tree.empty()) continue;
      const auto base = static_cast<std::int32_t>(pairs_.size());
      const int b = first_sibling_[a] + static_cast<int>(position);
      sibling_tree_[a][position] = sibling_tree_[b][a - first_sibling_[a]] = base;
      for (PairCertificate entry : tree) {
        if (entry.first_child >= 0) entry.first_child += base;
        pairs_.push_back(entry);
      }
      tree = {};
    }
  }
}

std::string problem_with(const CertificateParameters& parameters) {
  if (!std::isfinite(parameters.epsilon) || parameters.epsilon <= 0.0 || parameters.epsilon >= 1.0) {
    return "epsilon must lie in (0, 1), got " + std::to_string(parameters.epsilon);
  }
  if (!std::isfinite(parameters.global_radius_scale) || parameters.global_radius_scale <= 0.0) {
    return "the global radius scale must be positive and finite, got " + std::to_string(parameters.global_radius_scale);
  }
  if (!std::isfinite(parameters.pair_reach) || (parameters.pair_reach != 0.0 && parameters.pair_reach < 1.0)) {
    return "the pair reach must be 0 or at least 1, got " + std::to_string(parameters.pair_reach);
  }
  if (parameters.max_subdivision_depth < 0 || parameters.max_evaluations_per_pair < 1) {
    return "subdivision limits must be non-negative (depth " + std::to_string(parameters.max_subdivision_depth) +
           ") and allow an evaluation (evaluations " + std::to_string(parameters.max_evaluations_per_pair) + ")";
  }
  return "";
}

std::string basis_scale_problem(const SubspaceModel& model) {
  const RowMajorMatrix& basis = model.scaled_basis();
  const double largest = basis.size() > 0 ? basis.cwiseAbs().maxCoeff() : 0.0;
  if (largest == 0.0 || std::abs(std::ilogb(largest)) <= kLargestCertifiedModeExponent) return "";
  std::ostringstream message;
  message << "the scaled basis's largest entry is " << largest << ", outside 2^-" << kLargestCertifiedModeExponent
          << "..2^" << kLargestCertifiedModeExponent
          << ": the products of its entries underflow or overflow and certificates would not be valid; express the "
             "model in other units, or query without certificates (SelfCcdOptions::use_certificates = false)";
  return message.str();
}

namespace detail {

namespace {

// A work item's cost model (PrecomputeStatus): each of its triangle pairs is screened by the
// 1D bound (nearly every pair, once by the sibling pair's descent and once more below its pair
// certificates), and the pairs bounded lie along the nodes' borders, counted per triangle of
// the item (a triangle is in three sibling pairs per level). The constant is fitted to the
// lion (27 polynomial modes), where a screened pair costs about 0.2 us: the estimate of time
// left there was 21 s at 43% for 16 s and 9 s at 71% for 9 s (with the triangles alone, 4 s
// at 85% for 9 s); on sscc scale's 20k sphere, where screening is nearly all, 10 s at 66% for
// 15 s. Only the progress estimate and the order of the work items depend on it.
constexpr long kUnitsPerTriangle = 1024;

long item_units(long pairs, long triangles) { return pairs + kUnitsPerTriangle * triangles; }

long triangles_of(const SubspaceBvh::Node& node) { return node.triangle_end - node.triangle_begin; }

/// The units of a leaf's own pairs, and of sibling pair (a, b).
long leaf_units(const SubspaceBvh::Node& leaf) {
  const long t = triangles_of(leaf);
  return item_units(t * (t - 1) / 2, t);
}
long sibling_units(const SubspaceBvh::Node& a, const SubspaceBvh::Node& b) {
  return item_units(triangles_of(a) * triangles_of(b), triangles_of(a) + triangles_of(b));
}

/// The units of node n's work items.
long work_units(const std::vector<SubspaceBvh::Node>& nodes, int n) {
  const SubspaceBvh::Node& node = nodes[n];
  if (node.is_leaf()) return leaf_units(node);
  long units = 0;
  for (int a = node.first_child; a < node.first_child + node.child_count; ++a) {
    for (int b = a + 1; b < node.first_child + node.child_count; ++b) units += sibling_units(nodes[a], nodes[b]);
  }
  return units;
}

/// Reports the progress as work items finish, from any thread, one call at a time. An
/// exception the callback throws is kept, the remaining items are skipped (stopped()), and
/// rethrow() passes it on outside the parallel region.
class ProgressReport {
 public:
  ProgressReport(const PrecomputeProgress& progress, int levels, long work) : progress_(progress) {
    status_.levels = levels;
    status_.work = work;
  }
  bool stopped() const { return stopped_.load(std::memory_order_relaxed); }
  void work_done(long units) {
    if (!progress_) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    status_.work_done += units;
    call();
  }
  void level_done() {
    if (!progress_) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    ++status_.levels_done;
    call();
  }
  void rethrow() const {
    if (failure_) std::rethrow_exception(failure_);
  }

 private:
  void call() {
    if (failure_) return;
    try {
      progress_(status_);
    } catch (...) {
      failure_ = std::current_exception();
      stopped_.store(true, std::memory_order_relaxed);
    }
  }

  const PrecomputeProgress& progress_;
  std::mutex mutex_;
  PrecomputeStatus status_;
  std::exception_ptr failure_;
  std::atomic<bool> stopped_{false};
};

}  // namespace

PrecomputeState PrecomputeDriver::start(const SubspaceBvh& bvh, const CertificateParameters& parameters) {
  const std::string problem = problem_with(parameters);
  if (!problem.empty()) throw std::invalid_argument("certificates: " + problem);
  const std::string scale_problem = basis_scale_problem(bvh.model());
  if (!scale_problem.empty()) throw std::invalid_argument("certificates: " + scale_problem);
  PrecomputeState state{Certificates(bvh, parameters), {}, {}};
  state.trees.resize(bvh.nodes().size());
  state.certificates.global_radius_ = global_radius_of(bvh.model(), parameters.global_radius_scale);
  state.contact.assign(bvh.nodes().size(), state.certificates.global_radius_);
  return state;
}

void PrecomputeDriver::run(const SubspaceBvh& bvh, const std::vector<char>& selected, PrecomputeState& state,
                           const PrecomputeProgress& progress) {
  Certificates& certificates = state.certificates;
  std::vector<double>& contact = state.contact;
  const double global = certificates.global_radius_;
  const auto& nodes = bvh.nodes();
  const std::vector<int> depth = bvh.node_depths();
  int deepest = -1, shallowest = static_cast<int>(nodes.size());
  long work = 0;
  for (int n = 0; n < static_cast<int>(nodes.size()); ++n) {
    if (!selected[n]) continue;
    deepest = std::max(deepest, depth[n]);
    shallowest = std::min(shallowest, depth[n]);
    work += work_units(nodes, n);
  }
  if (deepest < 0) return;
  const Precomputation precomputation(bvh, certificates.parameters_, global);
  ProgressReport report(progress, deepest - shallowest + 1, work);

  // Levels, deepest first: a node's radius needs its children's.
  Counters totals;
  for (int level = deepest; level >= shallowest; --level) {
    // Work items of the level, largest first: each leaf's own pairs, and each sibling pair
    // of each inner node. A sibling pair is resolved on its own up to kSiblingReach times
    // the smallest radius among its parent's children (and R_global).
    struct Task {
      int node;
      int a = -1, b = -1;  // -1: a leaf's own pairs
      long units = 0;
      RunningMinimum minimum{0.0, 0.0};
      std::vector<PairCertificate> tree;  // below a sibling pair: its pair certificates
    };
    std::vector<Task> tasks;
    for (int n = 0; n < static_cast<int>(nodes.size()); ++n) {
      if (depth[n] != level || !selected[n]) continue;
      const SubspaceBvh::Node& node = nodes[n];
      if (node.is_leaf()) {
        tasks.push_back({n, -1, -1, leaf_units(node), {global, global}, {}});
        continue;
      }
      double children = global;
      for (int a = node.first_child; a < node.first_child + node.child_count; ++a) {
        children = std::min(children, certificates.node_radius_[a]);
      }
      const double reach = std::min(global, kSiblingReach * children);
      for (int a = node.first_child; a < node.first_child + node.child_count; ++a) {
        for (int b = a + 1; b < node.first_child + node.child_count; ++b) {
          tasks.push_back({n, a, b, sibling_units(nodes[a], nodes[b]), {reach, reach}, {}});
        }
      }
    }
    std::stable_sort(tasks.begin(), tasks.end(), [](const Task& x, const Task& y) { return x.units > y.units; });
#pragma omp parallel num_threads(default_threads())
    {
      Counters counters;
#pragma omp for schedule(dynamic, 1)
      for (long i = 0; i < static_cast<long>(tasks.size()); ++i) {
        if (report.stopped()) continue;
        Task& task = tasks[i];
        if (task.a < 0) {
          precomputation.add_leaf(task.node, task.minimum, counters);
        } else {
          if (box_box_radius(bvh, task.a, task.b) < task.minimum.lower) {
            precomputation.add_node_pair(task.a, task.b, task.minimum, counters);
          }
          const double radius = task.minimum.lower;
          const double tree_reach = std::min(global, certificates.parameters_.pair_reach * radius);
          if (radius > 0.0 && radius < tree_reach) {
            task.tree = precomputation.pair_tree(task.a, task.b, tree_reach, counters);
            task.tree[0].radius = radius;
          }
        }
        report.work_done(task.units);
      }
#pragma omp critical
      totals.add(counters);
    }
    report.rethrow();
    // A node's radius: the minimum over its children and its sibling pairs.
    std::vector<RunningMinimum> minimum(nodes.size(), RunningMinimum{global, global});
    for (int n = 0; n < static_cast<int>(nodes.size()); ++n) {
      if (depth[n] != level || !selected[n]) continue;
      for (int a = nodes[n].first_child; a < nodes[n].first_child + nodes[n].child_count; ++a) {
        minimum[n].add(certificates.node_radius_[a], contact[a]);
      }
    }
    for (Task& task : tasks) {
      minimum[task.node].add(task.minimum.lower, task.minimum.contact);
      if (task.a < 0) continue;
      const int first = nodes[task.node].first_child;
      certificates.sibling_radius_[task.a][task.b - first] = task.minimum.lower;
      certificates.sibling_radius_[task.b][task.a - first] = task.minimum.lower;
      state.trees[task.a][task.b - first] = std::move(task.tree);
    }
    for (int n = 0; n < static_cast<int>(nodes.size()); ++n) {
      if (depth[n] != level || !selected[n]) continue;
      certificates.node_radius_[n] = minimum[n].lower;
      contact[n] = minimum[n].contact;
    }
    report.level_done();
    report.rethrow();
  }
  PrecomputeStats& stats = certificates.stats_;
  stats.node_pairs_visited += totals.node_pairs_visited;
  stats.node_pairs_culled += totals.node_pairs_culled;
  stats.triangle_pairs_culled += totals.triangle_pairs_culled;
  stats.triangle_pairs_bounded += totals.triangle_pairs_bounded;
  stats.constant_mode_evaluations += totals.evaluations;
  stats.pair_tree_tasks += totals.pair_tree_tasks;
}

void PrecomputeDriver::copy_node(const SubspaceBvh& bvh, int n, const Certificates& from, PrecomputeState& to) {
  to.certificates.node_radius_[n] = from.node_radius_[n];
  const SubspaceBvh::Node& node = bvh.nodes()[n];
  for (int c = node.first_child; c < node.first_child + node.child_count; ++c) {
    to.certificates.sibling_radius_[c] = from.sibling_radius_[c];
    for (int d = c + 1; d < node.first_child + node.child_count; ++d) {
      to.trees[c][d - node.first_child] = from.pair_tree(bvh, c, d);
    }
  }
}

void PrecomputeDriver::finish(PrecomputeState& state, double seconds) {
  state.certificates.assemble_pair_certificates(state.trees);
#ifdef SSCC_MUTANT_INFLATE_PAIR_RADII
  for (PairCertificate& pair : state.certificates.pairs_) pair.radius *= 1.5;
#endif
  state.certificates.stats_.pair_certificates = static_cast<long>(state.certificates.pairs_.size());
  state.certificates.stats_.threads = default_threads();
  state.certificates.stats_.seconds = seconds;
}

}  // namespace detail

Certificates Certificates::precompute(const SubspaceBvh& bvh, const CertificateParameters& parameters,
                                      const PrecomputeProgress& progress) {
  const auto start = std::chrono::steady_clock::now();
  detail::PrecomputeState state = detail::PrecomputeDriver::start(bvh, parameters);
  detail::PrecomputeDriver::run(bvh, std::vector<char>(bvh.nodes().size(), 1), state, progress);
#ifdef SSCC_MUTANT_INFLATE_RADII
  Certificates& certificates = state.certificates;
  for (int n = 1; n < static_cast<int>(bvh.nodes().size()); ++n) certificates.node_radius_[n] *= 1.1;
  for (auto& radii : certificates.sibling_radius_)
    for (double& r : radii) r *= 1.1;
#endif
  detail::PrecomputeDriver::finish(state, seconds_since(start));
  return std::move(state.certificates);
}

void Certificates::check_belongs_to(const SubspaceBvh& bvh) const {
  const std::string scale_problem = basis_scale_problem(bvh.model());
  if (!scale_problem.empty()) throw std::invalid_argument("certificates: " + scale_problem);
  if (static_cast<int>(bvh.nodes().size()) != node_count() || key_of(bvh, parameters_) != key_) {
    throw std::invalid_argument(
        "certificates: computed for another mesh, basis, weights or hierarchy, or another set of excluded pairs (key "
        "mismatch)");
  }
}

}  // namespace sscc
