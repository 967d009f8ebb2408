// Holds one kernel answer against the exact reference.
#pragma once

#include <string>

#include "query.hpp"

namespace sscc::validation {

/// Empty when the kernel agrees with the reference: the same contact decision and, on
/// contact, a time of impact in [t* - tolerance, t*] at which the primitives, placed by the
/// reported parameters, are no farther apart than the motion allows in that time.
/// Otherwise a one-line description of the disagreement with the query's coordinates.
/// `truth`, when given, receives the reference's contact decision.
std::string disagreement_with_reference(const Query& q, const ccd::CcdOptions& options = {}, bool* truth = nullptr);

/// The query as text with full-precision coordinates (for reports and failing tests).
std::string describe(const Query& q);

}  // namespace sscc::validation
