// The parallel layer of the self traversal: its top is expanded serially (certificates and
// node boxes tested as usual) until node pairs are small, and those pairs, in the order the
// serial traversal would reach them, become independent tasks. Each task is the serial
// traversal below its pair, so the tasks' hits concatenated in task order are the serial
// traversal's hits in its order: merging them gives the serial report for any thread count
// (and the serial first hit, in the modes that stop there). Private to the library.
#pragma once

#include <algorithm>
#include <vector>

#include "sscc/bvh/subspace_bvh.hpp"
#include "sscc/query/self_ccd.hpp"

namespace sscc::detail {

/// Tasks per thread the frontier aims at, from the triangle count alone (certificates and
/// culls remove some, node pairs between siblings add many): enough for dynamic scheduling
/// to even out tasks of unequal cost. Lower: a few large tasks decide the run time; higher:
/// more serial expansion and per-task overhead.
inline constexpr int kTasksPerThread = 16;

/// intra(n) when a == b, inter(a, b) otherwise.
struct TraversalTask {
  int a, b;
  int pair = -1;  ///< the pair certificate of (a, b) (certificates.hpp), -1 for none
};

/// The traversal hands each node pair here before descending into it; a pair small enough
/// (both nodes leaves or at most triangle_limit triangles) becomes a task instead.
class TaskFrontier {
 public:
  TaskFrontier(const SubspaceBvh& bvh, int threads)
      : bvh_(bvh), triangle_limit_(std::max(1, bvh.model().mesh().triangle_count() / (kTasksPerThread * threads))) {}

  /// Whether the pair became a task (the traversal then leaves it to the task).
  bool take(int a, int b, int pair = -1) {
    if (!small(a) || !small(b)) return false;
    tasks_.push_back({a, b, pair});
    return true;
  }
  const std::vector<TraversalTask>& tasks() const { return tasks_; }

 private:
  bool small(int n) const {
    const SubspaceBvh::Node& node = bvh_.nodes()[n];
    return node.is_leaf() || node.triangle_end - node.triangle_begin <= triangle_limit_;
  }

  const SubspaceBvh& bvh_;
  int triangle_limit_;
  std::vector<TraversalTask> tasks_;
};

/// Adds b's counters to a's (root_certified and seconds are the merged query's own).
inline void add_counts(SelfCcdStats& a, const SelfCcdStats& b) {
  a.nodes_visited += b.nodes_visited;
  a.box_tests += b.box_tests;
  a.triangle_pairs += b.triangle_pairs;
  a.kernel_calls += b.kernel_calls;
  a.vertices_computed += b.vertices_computed;
  a.vertex_starts_reused += b.vertex_starts_reused;
  a.certified += b.certified;
  a.pair_certified += b.pair_certified;
  a.cone_culled += b.cone_culled;
  a.cone_radius_culled += b.cone_radius_culled;
  a.plane_culled += b.plane_culled;
  a.displacement_culled += b.displacement_culled;
  a.moved_box_culled += b.moved_box_culled;
}

}  // namespace sscc::detail
