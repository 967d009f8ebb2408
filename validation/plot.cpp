#include "plot.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace sscc::validation {

namespace {

std::string script_of(const Figure& figure) {
  std::ostringstream g;
  g << "set terminal pngcairo size " << figure.width << ',' << figure.height << "\nset output '" << figure.png
    << "'\nset datafile separator ','\n";
  if (figure.panels.size() > 1) g << "set multiplot layout 1," << figure.panels.size() << '\n';
  for (const PlotPanel& panel : figure.panels) {
    // Titles verbatim (noenhanced): they hold file and scene names, whose underscores
    // gnuplot would otherwise take for subscripts; labels keep the markup (||q||_M).
    g << "set title '" << panel.title << "' noenhanced\nset xlabel '" << panel.x_label << "'\nset ylabel '"
      << panel.y_label << "'\nset key " << panel.key << '\n';
    g << (panel.log_x ? "set logscale x\n" : "unset logscale x\n");
    g << (panel.log_y ? "set logscale y\n" : "unset logscale y\n");
    if (panel.y2_label.empty()) {
      g << "unset y2label\nunset y2tics\n";
    } else {
      g << "set y2label '" << panel.y2_label << "'\nset y2tics\n";
    }
    g << "plot ";
    for (std::size_t k = 0; k < panel.series.size(); ++k) {
      const PlotSeries& s = panel.series[k];
      g << (k ? ", " : "") << '\'' << s.csv << "' using " << s.x << ':' << s.y << " skip 1"
        << (s.right_axis ? " axes x1y2" : "") << " with " << s.style << " title '" << s.title << '\'';
    }
    g << '\n';
  }
  if (figure.panels.size() > 1) g << "unset multiplot\n";
  return g.str();
}

}  // namespace

void render_figure(const Figure& figure, std::ostream& progress) {
  const std::string png_suffix = ".png";
  std::string script_path = figure.png;
  if (script_path.size() > png_suffix.size() &&
      script_path.compare(script_path.size() - png_suffix.size(), png_suffix.size(), png_suffix) == 0) {
    script_path.resize(script_path.size() - png_suffix.size());
  }
  script_path += ".gnuplot";
  std::ofstream(script_path) << script_of(figure);
  if (std::system(("gnuplot '" + script_path + "' 2>/dev/null").c_str()) == 0) {
    progress << "plot: " << figure.png << '\n';
  } else {
    progress << "gnuplot not available or failed: CSV files only\n";
  }
}

}  // namespace sscc::validation
