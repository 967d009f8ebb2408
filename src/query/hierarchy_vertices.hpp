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
  /// thread, the hard spring (`sscc demo --scene spring --strike-speed 7 --steps 17640
  /// --fcl-steps 0`, 20 modes), SSCC's speedup over the traditional query in two runs: chunks
  /// of 1 vertex 23.0x and 23.0x, 8: 23.8x and 25.0x, 16: 25.6x and 25.4x, 32: 25.2x and
  /// 25.3x, 64: 24.8x and 23.4x. Larger: vertices computed that the step never reaches;
  /// smaller: more waits for the memory.
  static constexpr int kChunk = 16;

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
