#include "progress_bar.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <utility>

namespace sscc::validation {

namespace {

/// Characters of the bar between its brackets.
constexpr int kBarWidth = 20;

bool is_terminal(const std::ostream& out) { return &out == &std::cerr && isatty(STDERR_FILENO) == 1; }

double seconds_between(std::chrono::steady_clock::time_point from, std::chrono::steady_clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

}  // namespace

std::string duration_text(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char text[32];
  if (s < 60) {
    std::snprintf(text, sizeof text, "%lds", s);
  } else if (s < 3600) {
    std::snprintf(text, sizeof text, "%ldm%02lds", s / 60, s % 60);
  } else {
    std::snprintf(text, sizeof text, "%ldh%02ldm", s / 3600, s / 60 % 60);
  }
  return text;
}

ProgressBar::ProgressBar(std::ostream& out, std::string label)
    : out_(out),
      label_(std::move(label)),
      terminal_(is_terminal(out)),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

ProgressBar::~ProgressBar() {
  if (open_line_) out_ << std::endl;
}

void ProgressBar::update(double done, double total, const std::string& note) {
  if (finished_ || !out_.rdbuf()) return;
  const auto now = std::chrono::steady_clock::now();
  const bool due = seconds_between(last_draw_, now) >= (terminal_ ? kRedrawSeconds : kPlainLineSeconds);
  if (!due && note == last_note_) return;
  last_draw_ = now;
  last_note_ = note;
  draw(done, total, note, false);
}

void ProgressBar::finish(const std::string& note) {
  if (finished_ || !out_.rdbuf()) return;
  finished_ = true;
  draw(1.0, 1.0, note, true);
}

void ProgressBar::clear() {
  if (!open_line_) return;
  out_ << "\r\033[K" << std::flush;
  open_line_ = false;
}

void ProgressBar::draw(double done, double total, const std::string& note, bool last) {
  const double fraction = total > 0.0 ? std::clamp(done / total, 0.0, 1.0) : 0.0;
  const double elapsed = seconds_between(start_, std::chrono::steady_clock::now());
  std::string line = label_ + " [";
  const int filled = static_cast<int>(fraction * kBarWidth);
  line += std::string(filled, '#') + std::string(kBarWidth - filled, '.') + "] ";
  char percent[16];
  std::snprintf(percent, sizeof percent, "%3d%%", static_cast<int>(100.0 * fraction));
  line += percent;
  if (!note.empty()) line += " " + note;
  if (last) {
    line += ", done in " + duration_text(elapsed);
  } else {
    line += ", " + duration_text(elapsed) + " so far";
    if (fraction >= kLeastFractionForEstimate && elapsed >= kLeastSecondsForEstimate) {
      line += ", about " + duration_text(elapsed * (1.0 - fraction) / fraction) + " left";
    }
  }
  if (terminal_) {
    out_ << '\r' << line << "\033[K";  // clear what a longer line left
    open_line_ = !last;
    if (last) out_ << '\n';
    out_ << std::flush;
  } else {
    out_ << line << std::endl;
  }
}

PrecomputeProgress precompute_progress(ProgressBar& bar) {
  return [&bar](const PrecomputeStatus& s) {
    const int level = std::min(s.levels_done + 1, s.levels);  // the one in progress
    const std::string note = "level " + std::to_string(level) + "/" + std::to_string(s.levels);
    bar.update(static_cast<double>(s.work_done), static_cast<double>(s.work), note);
  };
}

}  // namespace sscc::validation
