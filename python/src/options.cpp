#include "options.hpp"

#include <pybind11/pybind11.h>

namespace sscc::python {

SelfCcdMode parse_mode(const std::string& mode) {
  if (mode == "all") return SelfCcdMode::kAllContacts;
  if (mode == "earliest") return SelfCcdMode::kEarliest;
  if (mode == "any") return SelfCcdMode::kAnyHit;
  throw pybind11::value_error("mode: expected 'all', 'earliest' or 'any', got '" + mode + "'");
}

ccd::CcdOptions kernel_options(double toi_tolerance, double minimum_separation) {
  ccd::CcdOptions options;
  options.toi_tolerance = toi_tolerance;
  options.minimum_separation = minimum_separation;
  return options;
}

}  // namespace sscc::python
