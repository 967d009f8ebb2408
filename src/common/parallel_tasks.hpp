// Running an ordered list of independent tasks on several threads (OpenMP), for the queries
// and the scene: each task writes only its own result slot and its thread's scratch, so the
// caller merges results in task order and gets the same answer for any thread count.
// Private to the library.
#pragma once

#include <omp.h>

#include <atomic>
#include <climits>
#include <exception>
#include <vector>

#include "sscc/threads.hpp"

namespace sscc::detail {

/// The thread count a query or step uses: `requested` when positive, otherwise the
/// library's default (sscc/threads.hpp).
inline int resolve_threads(int requested) { return requested > 0 ? requested : default_threads(); }

/// For the modes that stop at the first hit: the lowest index of a task that hit so far.
/// The serial answer is the first hit in task order, so tasks after that one are cancelled
/// and tasks before it run to the end (one of them may still hit first).
class FirstHitTask {
 public:
  void hit(int task) {
    int current = first_.load(std::memory_order_relaxed);
    while (task < current && !first_.compare_exchange_weak(current, task, std::memory_order_relaxed)) {
    }
  }
  /// Whether `task` can no longer be part of the answer. A relaxed read: a late view only
  /// delays the cancellation, the merge discards what comes after the first hit anyway.
  bool cancels(int task) const { return task > first_.load(std::memory_order_relaxed); }

 private:
  std::atomic<int> first_{INT_MAX};
};

/// Runs run(task, thread) for task = 0 .. count - 1 on `threads` threads, each task on one
/// thread (thread in [0, threads), for per-thread scratch), handed out one at a time in
/// increasing order. An exception in a task is rethrown here after every task ended (the
/// first in task order); on one thread, at once (the later tasks do not run).
template <typename Run>
void run_tasks(int count, int threads, Run run) {
  if (threads <= 1) {  // no parallel region to open
    for (int task = 0; task < count; ++task) run(task, 0);
    return;
  }
  std::vector<std::exception_ptr> errors(count);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int task = 0; task < count; ++task) {
    try {
      run(task, omp_get_thread_num());
    } catch (...) {
      errors[task] = std::current_exception();
    }
  }
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

}  // namespace sscc::detail
