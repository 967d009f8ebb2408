// Wall-clock timing for statistics and progress output (steady clock, seconds).
#pragma once

#include <chrono>

namespace sscc {

/// Seconds elapsed since `start` on the steady clock.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace sscc
