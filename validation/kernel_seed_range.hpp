// The kernels' check against the exact reference, split by seed: seed s alone makes its
// queries (kQueriesPerSeed random ones of each kind and a tenth as many near-degenerate ones,
// from a generator seeded with s), so the counts of seeds a..c are those of a..b plus those of
// b..c, and a long validation runs as independent ranges on as many processes or machines
// (`sscc kernels --seeds A:B`; python/examples/dask_precompute.py runs them through Dask).
#pragma once

#include <cstdint>
#include <ostream>

namespace sscc::validation {

/// Random queries of each kind per seed: a seed's check takes about a second.
inline constexpr long kQueriesPerSeed = 1000;

struct KernelCounts {
  long queries = 0;
  long contacts = 0;  ///< the reference's
  long disagreements = 0;
  friend bool operator==(const KernelCounts& a, const KernelCounts& b) {
    return a.queries == b.queries && a.contacts == b.contacts && a.disagreements == b.disagreements;
  }
};

struct SeedRangeCounts {
  // By kind: vertex-face, edge-edge.
  KernelCounts random[2], near_degenerate[2];
  SeedRangeCounts& operator+=(const SeedRangeCounts& other);
  KernelCounts total() const;
  friend bool operator==(const SeedRangeCounts& a, const SeedRangeCounts& b);
};

struct SeedRangeOptions {
  std::uint64_t begin = 1, end = 2;  ///< seeds begin..end-1
  long per_seed = kQueriesPerSeed;
};

/// Checks the queries of seeds begin..end-1 against the exact reference; the first few
/// disagreements are described on `out`, the progress on `progress`.
SeedRangeCounts check_seed_range(const SeedRangeOptions& options, std::ostream& out, std::ostream& progress);

/// `sscc kernels --seeds A:B`: the counts per kind and set, then the line
///   kernels: seeds=A:B queries=N contacts=N disagreements=N
/// Returns the disagreements.
long run_seed_range(const SeedRangeOptions& options, std::ostream& out, std::ostream& progress);

}  // namespace sscc::validation
