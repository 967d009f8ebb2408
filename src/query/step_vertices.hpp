// The positions of one query's vertices at both ends of its step, in buffers the detector
// keeps between queries: one copy for every thread of the query. Either every vertex is
// computed up front (a share per thread, before the traversal's threads start; they only
// read), or each on demand, with the rest of its chunk in the hierarchy's order
// (hierarchy_vertices.hpp), by a query on one thread (self_ccd.cpp, plan_step, says why the
// on-demand steps take one). A query that starts where the buffers' last one ended (q_hat0
// equal to its q_hat1, bit for bit: a simulator's next step) takes the end positions that
// query computed as its starts, and computes only the ends. Private to the library.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "query/hierarchy_vertices.hpp"
#include "sscc/geometry/aabb.hpp"
#include "sscc/model/subspace_model.hpp"
#include "sscc/query/self_ccd.hpp"

namespace sscc::detail {

/// What StepVertices keeps between queries (step_buffers.hpp lends them).
struct VertexBuffers {
  std::vector<Eigen::Vector3d> x0, x1;
  /// Per vertex, the number of the last query on these buffers that knew both its positions
  /// (queries numbered from 1 by `queries`; 0: none). Numbers, not flags, so that a query
  /// starts without touching every vertex.
  std::vector<std::uint64_t> known_in;
  std::uint64_t queries = 0;
  /// The q_hat1 of the last query, when it computed its positions from coordinates (empty
  /// otherwise): where a next query may start.
  Eigen::VectorXd end_coordinates;
  /// Per node, a box holding its vertices' end positions, and the number of the query that
  /// recorded it (StepVertices::record_end_box).
  std::vector<Aabb> end_boxes;
  std::vector<std::uint64_t> end_box_in;
};

class StepVertices {
 public:
  /// From coordinates. With `order`, vertices are computed on demand (ensure); without it,
  /// compute_every_vertex must run before the positions are read.
  StepVertices(VertexBuffers& buffers, const SubspaceModel& model, const HierarchyVertices* order,
               const Eigen::VectorXd& q_hat0, const Eigen::VectorXd& q_hat1);
  /// Given positions (one per vertex at each end): every vertex known.
  StepVertices(VertexBuffers& buffers, const std::vector<Eigen::Vector3d>& x0, const std::vector<Eigen::Vector3d>& x1);

  /// Every vertex, in vertex order (one stream through the basis), a share per thread. Not
  /// thread-safe: before the query's threads start.
  void compute_every_vertex(int threads);
  bool every_vertex_known() const { return every_vertex_known_; }
  /// Whether this query starts where the buffers' last one ended.
  bool continues_previous() const { return continues_previous_; }

  /// Computes vertex v unless known (with its chunk), counting in `stats`. On demand, the
  /// query's one thread only.
  void ensure(int v, SelfCcdStats& stats) {
    if (every_vertex_known_ || known_in_[v] == query_) return;
    compute_chunk_of(v, stats);
  }

  /// The positions (vertex v's once ensure(v) returned).
  Eigen::Vector3d* x0() const { return x0_; }
  Eigen::Vector3d* x1() const { return x1_; }
  std::vector<Eigen::Vector3d>& x0_vector() const { return buffers_.x0; }
  std::vector<Eigen::Vector3d>& x1_vector() const { return buffers_.x1; }
  /// Node boxes handed from step to step, for `node_count` nodes: from then on the query may
  /// record boxes of its end positions (on one thread), and read those the previous query
  /// recorded, which hold this query's start positions when it continues that query.
  void track_node_boxes(int node_count);
  /// Node n's box recorded by the previous query, when this query starts at its end; null
  /// otherwise (and once this query recorded n's).
  const Aabb* previous_end_box(int n) const {
    return continues_previous_ && buffers_.end_box_in[n] == query_ - 1 ? &buffers_.end_boxes[n] : nullptr;
  }
  /// Records a box holding node n's end positions in this query.
  void record_end_box(int n, const Aabb& box) {
    buffers_.end_boxes[n] = box;
    buffers_.end_box_in[n] = query_;
  }

  /// What compute_every_vertex counted.
  const SelfCcdStats& up_front() const { return up_front_; }

  /// Whether two coordinate vectors are equal bit for bit (a pool prefers buffers whose
  /// end_coordinates equal a query's q_hat0).
  static bool same_bits(const Eigen::VectorXd& a, const Eigen::VectorXd& b);

 private:
  void size_buffers(int vertex_count);
  [[gnu::noinline]] void compute_chunk_of(int v, SelfCcdStats& stats);
  /// Vertex v's positions from its basis block `rows` (the end only when its start is the
  /// previous query's end).
  void compute(int v, const double* rows, SelfCcdStats& stats);

  VertexBuffers& buffers_;
  // The buffers' arrays (the checks read them without the vectors' indirection).
  Eigen::Vector3d* x0_ = nullptr;
  Eigen::Vector3d* x1_ = nullptr;
  std::uint64_t* known_in_ = nullptr;
  const SubspaceModel* model_ = nullptr;  // null for given positions
  const HierarchyVertices* order_ = nullptr;
  const Eigen::VectorXd* q_hat0_ = nullptr;
  const Eigen::VectorXd* q_hat1_ = nullptr;
  std::uint64_t query_ = 0;
  bool continues_previous_ = false;
  bool every_vertex_known_ = false;
  SelfCcdStats up_front_;
};

}  // namespace sscc::detail
