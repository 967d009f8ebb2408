// `sscc selfccd`: whole-mesh continuous self-collision over a seeded random trajectory,
// by several methods side by side (the traversal, exhaustive all-pairs testing, FCL),
// with their agreement; disagreements with FCL are settled by the exact kernels.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace sscc::validation {

struct SelfCcdValidationOptions {
  std::string mesh;
  std::string basis = "polynomial:27";  ///< "polynomial:R" or a basis file (.U or text)
  std::string weights;                  ///< weights file; "" means all ones
  int steps = 20;
  double amplitude = 0.1;  ///< typical ||q||_M (see trajectory.hpp)
  std::uint64_t seed = 1;
  std::vector<std::string> methods = {"traditional"};  ///< traditional, exhaustive, fcl
};

/// Prints the report; returns the number of disagreements between the sscc methods plus
/// FCL disagreements the exact kernels do not settle against FCL (0 when all is well).
long run_selfccd_validation(const SelfCcdValidationOptions& options, std::ostream& out,
                            std::ostream& progress);

}  // namespace sscc::validation
