// `sscc precompute`: builds a model's hierarchy and certificates and writes the
// certificate file, printing one summary line
//   precompute: triangles=N nodes=N r=R time_s=X root_radius=X
// and the radius per tree level (min, median, max) on the output.
#pragma once

#include <ostream>
#include <string>

#include "model_loading.hpp"
#include "sscc/certificates/certificates.hpp"

namespace sscc::validation {

struct PrecomputeCommandOptions {
  ModelSource model;
  CertificateParameters parameters;
  std::string output;  ///< the certificate file
};

/// Returns 0 (errors throw).
long run_precompute(const PrecomputeCommandOptions& options, std::ostream& out, std::ostream& progress);

/// Lines "level L: nodes=N min_radius=X median_radius=X max_radius=X" (the paper's Figure 7).
void print_radius_per_level(const SubspaceBvh& bvh, const Certificates& certificates, std::ostream& out);

}  // namespace sscc::validation
