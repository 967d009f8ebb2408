// The buffers of the self queries (the vertices' positions, step_vertices.hpp; each
// context's lazy box and cone caches), kept by a detector between queries: a simulator that
// calls it once per step then allocates none of them per step, nor touches fresh memory
// (whose first writes fault pages in; on the default demo the queries' buffers made most of
// the run's page faults). Private to the library.
#pragma once

#include <algorithm>
#include <iterator>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "query/normal_cone.hpp"
#include "query/patch_cull.hpp"
#include "query/sweep.hpp"
#include "sscc/geometry/aabb.hpp"

namespace sscc::detail {

/// One traversal context's caches.
struct BoxBuffers {
  LazyBoxes<Aabb> subspace_boxes;
  LazyBoxes<Sweep> node_sweeps;
  LazyBoxes<Sweep> coherent_sweeps;              // node sweeps from the previous step's end boxes
  LazyBoxes<Sweep> triangle_sweeps;              // by position in the hierarchy's triangle order
  LazyBoxes<BernsteinNormals> triangle_normals;  // likewise: the separating planes' normals
  PatchCull::Caches patch_cull;                  // the cones formed from the positions
};

/// The buffers of finished queries, lent to the next ones: as many sets as were ever in use
/// at once on the detector. Thread-safe (a lock per lease, a few per query).
template <typename Buffers>
class BufferPool {
 public:
  /// A set of buffers, back to the pool when the lease ends. Their contents are whatever the
  /// last query left: a context resets its caches; the positions and node boxes are kept on
  /// purpose, for a query that continues the last one (step_vertices.hpp).
  class Lease {
   public:
    Lease(BufferPool& pool, std::unique_ptr<Buffers> buffers) : pool_(&pool), buffers_(std::move(buffers)) {}
    Lease(Lease&&) = default;
    Lease& operator=(Lease&&) = delete;
    ~Lease() {
      if (buffers_) pool_->give_back(std::move(buffers_));
    }
    Buffers& operator*() const { return *buffers_; }
    Buffers* operator->() const { return buffers_.get(); }

   private:
    BufferPool* pool_;
    std::unique_ptr<Buffers> buffers_;
  };

  /// The most recently returned set that `preferred` accepts, else the most recently
  /// returned, else a new one.
  template <typename Preferred>
  Lease lend(Preferred preferred) {
    std::unique_ptr<Buffers> buffers;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!free_.empty()) {
        auto chosen = std::find_if(free_.rbegin(), free_.rend(), [&](const auto& b) { return preferred(*b); });
        if (chosen == free_.rend()) chosen = free_.rbegin();
        buffers = std::move(*chosen);
        free_.erase(std::next(chosen).base());
      }
    }
    if (!buffers) buffers = std::make_unique<Buffers>();
    return {*this, std::move(buffers)};
  }
  Lease lend() {
    return lend([](const Buffers&) { return false; });
  }

 private:
  /// Called by a lease's destructor, so it must not throw: a set the list has no room for
  /// (out of memory) is freed instead.
  void give_back(std::unique_ptr<Buffers> buffers) noexcept {
    const std::lock_guard<std::mutex> lock(mutex_);
    try {
      free_.push_back(std::move(buffers));
    } catch (...) {
    }
  }

  std::mutex mutex_;
  std::vector<std::unique_ptr<Buffers>> free_;
};

}  // namespace sscc::detail
