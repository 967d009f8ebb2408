#include "sscc/threads.hpp"

#include <omp.h>

#include <atomic>
#include <stdexcept>
#include <string>

namespace sscc {

namespace {
std::atomic<int> chosen_threads{0};  // 0: every thread OpenMP may use
}  // namespace

int default_threads() {
  const int chosen = chosen_threads.load(std::memory_order_relaxed);
  return chosen > 0 ? chosen : omp_get_max_threads();
}

void set_default_threads(int threads) {
  if (threads < 0) throw std::invalid_argument("thread count " + std::to_string(threads) + " is negative");
  chosen_threads.store(threads, std::memory_order_relaxed);
}

}  // namespace sscc
