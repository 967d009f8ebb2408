// A progress display with an estimate of the time left, for the commands that run long: on a
// terminal, one line redrawn in place; elsewhere (a CI log, a file) a plain line now and then
// and at each change of its note.
//
//   precompute [########............] 41% level 6/9, 1m05s so far, about 1m33s left
//
// The estimate extrapolates linearly: the time so far times the work left over the work done,
// so it is as good as the units of work are even (PrecomputeStatus's units for the
// precomputation, steps or cases elsewhere).
#pragma once

#include <chrono>
#include <ostream>
#include <string>

#include "sscc/certificates/certificates.hpp"

namespace sscc::validation {

/// Seconds between redraws on a terminal: often enough to look alive, rarely enough that
/// drawing costs nothing next to the work.
inline constexpr double kRedrawSeconds = 0.25;
/// Seconds between plain lines off a terminal: a long CI log gains a line per this.
inline constexpr double kPlainLineSeconds = 10.0;
/// The time left is shown from this fraction done and this many seconds on: before, it is
/// mostly noise (the first units of the precomputation take a hundredth of their share).
inline constexpr double kLeastFractionForEstimate = 0.02;
inline constexpr double kLeastSecondsForEstimate = 2.0;

class ProgressBar {
 public:
  /// Lines on `out` start with `label`. Drawn in place when `out` is standard error and that is
  /// a terminal; nothing at all when `out` discards what it gets (the commands' --quiet).
  ProgressBar(std::ostream& out, std::string label);
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;
  /// Ends the line on a terminal when finish() was not called.
  ~ProgressBar();

  /// `done` of `total` units, and a note shown after the percentage ("level 3/9"). Drawn when
  /// the note changes, else at most every kRedrawSeconds on a terminal, kPlainLineSeconds off it.
  void update(double done, double total, const std::string& note = "");
  /// The last line: everything done, and the time taken.
  void finish(const std::string& note = "");
  /// Erases the line drawn on a terminal, before other output (the next update redraws it).
  void clear();

 private:
  void draw(double done, double total, const std::string& note, bool last);

  std::ostream& out_;
  std::string label_;
  bool terminal_;
  bool open_line_ = false;  // a terminal line drawn and not ended
  bool finished_ = false;
  std::string last_note_;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

/// The precomputation's progress on `bar`: its units of work, the levels as the note.
PrecomputeProgress precompute_progress(ProgressBar& bar);

/// "42s", "3m05s", "2h07m".
std::string duration_text(double seconds);

}  // namespace sscc::validation
