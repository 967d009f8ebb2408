#include "plot.hpp"

#include <cstdlib>
#include <fstream>

namespace sscc::validation {

void render_plot(const std::string& script, const std::string& script_path, const std::string& png,
                 std::ostream& progress) {
  std::ofstream(script_path) << script;
  if (std::system(("gnuplot " + script_path + " 2>/dev/null").c_str()) == 0) {
    progress << "plot: " << png << '\n';
  } else {
    progress << "gnuplot not available or failed: CSV files only\n";
  }
}

}  // namespace sscc::validation
