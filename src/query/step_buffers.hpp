// The buffers of one self-query context (vertex positions, the query numbers that know them,
// the lazy box and cone caches), kept by a detector between queries: a simulator that calls
// it once per step then allocates none of them per step, nor touches fresh memory (whose
// first writes fault pages in; on the default demo the queries' buffers made most of the
// run's page faults). Private to the library.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "query/normal_cone.hpp"
#include "query/patch_cull.hpp"
#include "query/sweep.hpp"
#include "sscc/geometry/aabb.hpp"

namespace sscc::detail {

struct StepBuffers {
  std::vector<Eigen::Vector3d> x0, x1;  // the positions, unless the query shares them
  /// Per vertex, the number of the last query on these buffers that knew both its
  /// positions (queries numbered from 1 by `queries`: 0 is none). Numbers, not flags, so that
  /// a query starts without touching every vertex.
  std::vector<std::uint64_t> computed_in;
  std::uint64_t queries = 0;
  /// The q_hat1 of the last query, when it computed its positions from coordinates (empty
  /// otherwise). A next query starting there (q_hat0 bitwise equal: a simulator's next step)
  /// takes the last one's end positions as its start.
  Eigen::VectorXd end_coordinates;
  LazyBoxes<Aabb> subspace_boxes;
  LazyBoxes<Sweep> node_sweeps;
  LazyBoxes<Sweep> triangle_sweeps;              // by position in the hierarchy's triangle order
  LazyBoxes<BernsteinNormals> triangle_normals;  // likewise: the separating planes' normals
  PatchCull::Caches patch_cull;                  // the cones formed from the positions
};

/// The buffers of finished queries, lent to the next ones: as many sets as queries ever ran
/// at once on the detector. Thread-safe (a lock per lease, a few per query).
class StepBufferPool {
 public:
  /// A set of buffers, back to the pool when the lease ends. Their contents are whatever the
  /// last query left: the context resets what it reads.
  class Lease {
   public:
    Lease(StepBufferPool& pool, std::unique_ptr<StepBuffers> buffers) : pool_(&pool), buffers_(std::move(buffers)) {}
    Lease(Lease&&) = default;
    Lease& operator=(Lease&&) = delete;
    ~Lease() {
      if (buffers_) pool_->give_back(std::move(buffers_));
    }
    StepBuffers& operator*() const { return *buffers_; }
    StepBuffers* operator->() const { return buffers_.get(); }

   private:
    StepBufferPool* pool_;
    std::unique_ptr<StepBuffers> buffers_;
  };

  Lease lend() {
    std::unique_ptr<StepBuffers> buffers;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!free_.empty()) {
        buffers = std::move(free_.back());
        free_.pop_back();
      }
    }
    if (!buffers) buffers = std::make_unique<StepBuffers>();
    return {*this, std::move(buffers)};
  }

 private:
  /// Called by a lease's destructor, so it must not throw: a set the list has no room for
  /// (out of memory) is freed instead.
  void give_back(std::unique_ptr<StepBuffers> buffers) noexcept {
    const std::lock_guard<std::mutex> lock(mutex_);
    try {
      free_.push_back(std::move(buffers));
    } catch (...) {
    }
  }

  std::mutex mutex_;
  std::vector<std::unique_ptr<StepBuffers>> free_;
};

}  // namespace sscc::detail
