#include "query/step_vertices.hpp"

#include <algorithm>
#include <cstring>

#include "common/parallel_tasks.hpp"
#include "query/task_frontier.hpp"

namespace sscc::detail {

namespace {

/// Fewer vertices per thread than this are computed up front on fewer threads: opening a
/// parallel region costs about as much as a thousand vertices of a 30-mode basis.
constexpr int kVerticesPerBlock = 1024;

}  // namespace

bool StepVertices::same_bits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() && (a.size() == 0 || std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0);
}

StepVertices::StepVertices(VertexBuffers& buffers, const SubspaceModel& model, const HierarchyVertices* order,
                           const Eigen::VectorXd& q_hat0, const Eigen::VectorXd& q_hat1)
    : buffers_(buffers), model_(&model), order_(order), q_hat0_(&q_hat0), q_hat1_(&q_hat1) {
  size_buffers(model.mesh().vertex_count());
  query_ = ++buffers_.queries;
  continues_previous_ = q_hat0.size() > 0 && same_bits(buffers_.end_coordinates, q_hat0);
  buffers_.end_coordinates = q_hat1;
}

StepVertices::StepVertices(VertexBuffers& buffers, const std::vector<Eigen::Vector3d>& x0,
                           const std::vector<Eigen::Vector3d>& x1)
    : buffers_(buffers) {
  size_buffers(static_cast<int>(x0.size()));
  query_ = ++buffers_.queries;
  buffers_.end_coordinates.resize(0);
  std::copy(x0.begin(), x0.end(), x0_);  // into the buffers' storage
  std::copy(x1.begin(), x1.end(), x1_);
  every_vertex_known_ = true;
}

void StepVertices::size_buffers(int vertex_count) {
  if (static_cast<int>(buffers_.known_in.size()) != vertex_count) {
    buffers_.x0.resize(vertex_count);
    buffers_.x1.resize(vertex_count);
    buffers_.known_in.assign(vertex_count, 0);
    buffers_.end_coordinates.resize(0);  // no position is a previous end any more
  }
  x0_ = buffers_.x0.data();
  x1_ = buffers_.x1.data();
  known_in_ = buffers_.known_in.data();
}

void StepVertices::track_node_boxes(int node_count) {
  if (static_cast<int>(buffers_.end_box_in.size()) == node_count) return;
  buffers_.end_boxes.assign(node_count, Aabb::empty());
  buffers_.end_box_in.assign(node_count, 0);
}

void StepVertices::compute_every_vertex(int threads) {
  if (every_vertex_known_) return;
  const int count = static_cast<int>(buffers_.known_in.size());
  const int blocks = std::max(1, std::min(threads, count / kVerticesPerBlock));
  std::vector<SelfCcdStats> counted(blocks);
  run_tasks(blocks, blocks, [&](int block, int) {
    const int end = static_cast<int>(static_cast<long>(count) * (block + 1) / blocks);
    for (int v = static_cast<int>(static_cast<long>(count) * block / blocks); v < end; ++v) {
      compute(v, model_->vertex_block(v), counted[block]);
    }
  });
  for (const SelfCcdStats& c : counted) add_counts(up_front_, c);
  every_vertex_known_ = true;
}

/// A chunk is computed whole, so no vertex of it is known when v is not.
void StepVertices::compute_chunk_of(int v, SelfCcdStats& stats) {
  const HierarchyVertices& order = *order_;
  const int begin = order.rank(v) / HierarchyVertices::kChunk * HierarchyVertices::kChunk;
  const int end = std::min(begin + HierarchyVertices::kChunk, order.count());
  for (int i = begin; i < end; ++i) compute(order.vertex(i), order.rows(i), stats);
}

void StepVertices::compute(int v, const double* rows, SelfCcdStats& stats) {
  const Eigen::Vector3d& rest = model_->mesh().vertices()[v];
  if (continues_previous_ && known_in_[v] == query_ - 1) {
    x0_[v] = x1_[v];
    x1_[v] = SubspaceModel::position(rest, rows, *q_hat1_);
    ++stats.vertex_starts_reused;
  } else {
    SubspaceModel::position_pair(rest, rows, *q_hat0_, *q_hat1_, x0_[v], x1_[v]);
  }
  known_in_[v] = query_;
  ++stats.vertices_computed;
}

}  // namespace sscc::detail
