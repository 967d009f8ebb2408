// Query options from Python keyword arguments.
#pragma once

#include <string>

#include "sscc/ccd/ccd_types.hpp"
#include "sscc/query/self_ccd.hpp"

namespace sscc::python {

/// "all", "earliest" or "any"; ValueError otherwise.
SelfCcdMode parse_mode(const std::string& mode);
ccd::CcdOptions kernel_options(double toi_tolerance, double minimum_separation);

}  // namespace sscc::python
