// Renders a gnuplot script to PNG when gnuplot is installed; validation output is complete
// without it (the CSV files hold the data).
#pragma once

#include <ostream>
#include <string>

namespace sscc::validation {

/// Writes `script` to `script_path` and runs gnuplot on it; reports the PNG, or that only
/// the CSV files were written, on `progress`.
void render_plot(const std::string& script, const std::string& script_path, const std::string& png,
                 std::ostream& progress);

}  // namespace sscc::validation
