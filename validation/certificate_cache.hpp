// Certificates kept in a file between runs: read when the file holds valid ones for the
// hierarchy (the file checks itself: key, checksum, parameters), otherwise precomputed with
// the default parameters and written there. Shared by the demo and the bench.
#pragma once

#include <ostream>
#include <string>

#include "sscc/certificates/certificates.hpp"

namespace sscc::validation {

struct CachedCertificates {
  Certificates certificates;
  double seconds = 0.0;  ///< the precomputation's, 0 when read from the file
};

/// `fresh`: precompute even when the file is valid. Progress lines start with `who`.
CachedCertificates read_or_precompute_certificates(const SubspaceBvh& bvh, const std::string& path, bool fresh,
                                                   const std::string& who, std::ostream& progress);

}  // namespace sscc::validation
