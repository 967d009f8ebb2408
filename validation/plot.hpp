// Figures rendered to PNG with gnuplot when it is installed; validation output is complete
// without it (the CSV files hold the data). A figure is described, not scripted: panels of
// series read from CSV files (comma-separated, one header line).
#pragma once

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace sscc::validation {

/// One curve: column `x` of `csv` against `y` (a column number, or a gnuplot expression in
/// parentheses such as "($5*100)").
struct PlotSeries {
  std::string csv;
  int x = 1;
  std::string y;
  std::string title;
  std::string style = "linespoints lw 2";
  bool right_axis = false;  ///< against the y2 axis
};

enum class LogScale { kNone, kX, kY };

struct PlotPanel {
  PlotPanel(std::string panel_title, std::string x, std::string y, LogScale log, std::vector<PlotSeries> curves)
      : title(std::move(panel_title)),
        x_label(std::move(x)),
        y_label(std::move(y)),
        log_x(log == LogScale::kX),
        log_y(log == LogScale::kY),
        series(std::move(curves)) {}
  std::string title, x_label, y_label;
  std::string y2_label;  ///< empty: no right axis
  bool log_x, log_y;
  std::vector<PlotSeries> series;
  /// gnuplot's key placement: below the axes by default, so that no legend covers a curve.
  std::string key = "below";
};

/// Panels side by side in one PNG of width x height pixels.
struct Figure {
  std::string png;
  int width = 900, height = 500;
  std::vector<PlotPanel> panels;
};

/// Writes the figure's gnuplot script next to the PNG (same name, .gnuplot) and runs gnuplot
/// on it; reports the PNG, or that only the CSV files were written, on `progress`.
void render_figure(const Figure& figure, std::ostream& progress);

}  // namespace sscc::validation
