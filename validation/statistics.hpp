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

/// The arithmetic mean; 0 for no values.
inline double mean(const std::vector<double>& values) {
  double sum = 0.0;
  for (double x : values) sum += x;
  return values.empty() ? 0.0 : sum / static_cast<double>(values.size());
}

}  // namespace sscc::validation
