// Giving up a cull that does not pay within one query: its tests are tallied per size class of
// the nodes tried, and a class whose tests keep failing is not tried again. Only fewer culls
// follow, never a wrong one. Private to the library (the normal cones use it).
#pragma once

#include <array>

namespace sscc::detail {

/// A size class (nodes of 2^k to 2^(k+1) - 1 triangles, pairs by their total) is given up
/// once kJudgedAfterTries of its tests have been tried and fewer than one in kGiveUpBelowOneIn
/// passed: where patches of that size are too curved or too jagged for the cones (coarse
/// meshes, large motions), each failed test costs more than descending. Measured on
/// the bench's table: without it the cones were up to 27% slower than the plain query on the
/// elephant. Lower counts: given up sooner, also where a few culls would pay.
inline constexpr int kJudgedAfterTries = 16;
inline constexpr int kGiveUpBelowOneIn = 8;

/// Tries and passes of one kind of test per size class.
class CullRecord {
 public:
  static int size_class(int triangles) {
    int k = 0;
    while (triangles >>= 1) ++k;
    return k;
  }
  bool worth_trying(int size_class) const {
    return tries_[size_class] < kJudgedAfterTries || passes_[size_class] * kGiveUpBelowOneIn >= tries_[size_class];
  }
  /// Tallies a test and returns its result.
  bool record(int size_class, bool passed) {
    ++tries_[size_class];
    passes_[size_class] += passed;
    return passed;
  }

 private:
  std::array<int, 32> tries_{}, passes_{};
};

}  // namespace sscc::detail
