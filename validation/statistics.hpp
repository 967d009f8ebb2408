// Summaries of repeated measurements for the validation reports.
#pragma once

#include <algorithm>
#include <vector>

namespace sscc::validation {

/// The median (the upper one of an even count); 0 for no values.
inline double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

}  // namespace sscc::validation
