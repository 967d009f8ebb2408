// `sscc precompute`: builds a model's hierarchy and certificates and writes the
// certificate file, printing one summary line
//   precompute: triangles=N nodes=N r=R time_s=X root_radius=X
// and the radius per tree level (min, median, max) on the output. With a shard (--shard i/n)
// it computes that shard only (certificate_shards.hpp) and writes the shard file, printing
//   precompute: shard=i/n triangles=N subtrees=K split_depth=D time_s=X
// `sscc merge` puts the shard files together into the certificate file, byte for byte the
// one `sscc precompute` writes, with precompute's lines.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "model_loading.hpp"
#include "sscc/certificates/certificates.hpp"

namespace sscc::validation {

struct PrecomputeCommandOptions {
  ModelSource model;
  CertificateParameters parameters;
  std::string output;  ///< the certificate file, or the shard file with a shard
  /// Shard shard_index of shard_count; shard_count 0: the whole precomputation.
  int shard_index = 0;
  int shard_count = 0;
};

/// Returns 0 (errors throw).
long run_precompute(const PrecomputeCommandOptions& options, std::ostream& out, std::ostream& progress);

struct MergeCommandOptions {
  ModelSource model;
  std::vector<std::string> shards;  ///< the shard files, in any order
  std::string output;               ///< the certificate file
};

/// Returns 0 (errors throw).
long run_merge(const MergeCommandOptions& options, std::ostream& out, std::ostream& progress);

/// Lines "level L: nodes=N min_radius=X median_radius=X max_radius=X" (the paper's Figure 7).
void print_radius_per_level(const SubspaceBvh& bvh, const Certificates& certificates, std::ostream& out);

}  // namespace sscc::validation
