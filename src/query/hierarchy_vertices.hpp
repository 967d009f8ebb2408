// The mesh's vertices in the order the hierarchy's triangles first use them, with a copy of
// their basis blocks in that order. A query that computes vertices on demand (self_ccd.cpp)
// computes them a chunk of consecutive ones at a time: the traversal reaches triangles of
// the same subtree together, so their vertices are mostly in the same chunks, and a chunk's
// blocks are read in one stream where single vertices wait for the memory one by one.
// Positions computed from the copy are the model's to the bit (the same rows, the same
// operations: SubspaceModel::position_pair). Private to the library.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "sscc/bvh/subspace_bvh.hpp"

namespace sscc::detail {

class HierarchyVertices {
 public:
  /// Vertices computed together, consecutive in the hierarchy's order. Measured, one
  /// thread, SSCC's speedup over the traditional query in two runs each (`sscc demo --scene
  /// spring --strike-speed 7 --steps 17640 --fcl-steps 0`, 20 modes, steps reaching most of
  /// the spring; `sscc demo --scene dragon --exclude-rest-contacts --fcl-steps 0`, steps
  /// reaching a few hundred of its vertices): chunks of 1 vertex, spring 23.1x and 23.0x,
  /// dragon 147.0x and 136.3x; 4: 24.8x and 25.1x, 127.0x and 147.3x; 16: 25.4x and 25.3x,
  /// 118.9x and 126.2x. Larger: vertices computed that a step never reaches; smaller: more
  /// waits for the memory.
  static constexpr int kChunk = 4;

  /// O(V r) time and memory (a copy of the basis).
  explicit HierarchyVertices(const SubspaceBvh& bvh);

  /// Position of vertex v in the order.
  int rank(int v) const { return rank_[v]; }
  /// The vertex at position i of the order.
  int vertex(int i) const { return order_[i]; }
  int count() const { return static_cast<int>(order_.size()); }
  /// The 3 x r block (row-major) of the vertex at position i.
  const double* rows(int i) const { return rows_.data() + static_cast<std::ptrdiff_t>(i) * block_size_; }

 private:
  std::vector<int> order_;
  std::vector<int> rank_;
  std::vector<double> rows_;
  std::ptrdiff_t block_size_ = 0;
};

}  // namespace sscc::detail
