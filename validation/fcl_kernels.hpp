// FCL 0.7's continuous vertex-face and edge-edge tests, in our query form.
#pragma once

#include "query.hpp"

namespace sscc::validation {

/// False when the build has no FCL (SSCC_WITH_FCL off).
bool fcl_available();
/// FCL's answer: fcl::detail::Intersect<double>::intersect_VF (face vertices first, the
/// point last) or intersect_EE. Precondition: fcl_available().
bool run_fcl(const Query& q);

}  // namespace sscc::validation
