#include "kernel_seed_range.hpp"

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>

#include "agreement.hpp"
#include "progress_bar.hpp"
#include "query_generators.hpp"

namespace sscc::validation {

namespace {

/// Disagreements described on the output per range; the rest are counted only.
constexpr long kDescribedDisagreements = 5;

KernelCounts& operator+=(KernelCounts& a, const KernelCounts& b) {
  a.queries += b.queries;
  a.contacts += b.contacts;
  a.disagreements += b.disagreements;
  return a;
}

}  // namespace

SeedRangeCounts& SeedRangeCounts::operator+=(const SeedRangeCounts& other) {
  for (int k = 0; k < 2; ++k) {
    random[k] += other.random[k];
    near_degenerate[k] += other.near_degenerate[k];
  }
  return *this;
}

KernelCounts SeedRangeCounts::total() const {
  KernelCounts sum;
  for (int k = 0; k < 2; ++k) {
    sum += random[k];
    sum += near_degenerate[k];
  }
  return sum;
}

bool operator==(const SeedRangeCounts& a, const SeedRangeCounts& b) {
  for (int k = 0; k < 2; ++k) {
    if (!(a.random[k] == b.random[k]) || !(a.near_degenerate[k] == b.near_degenerate[k])) return false;
  }
  return true;
}

SeedRangeCounts check_seed_range(const SeedRangeOptions& options, std::ostream& out, std::ostream& progress) {
  const Kind kinds[2] = {Kind::kVertexFace, Kind::kEdgeEdge};
  const long near_degenerate = std::max(1L, options.per_seed / 10);
  SeedRangeCounts counts;
  long described = 0;
  const auto check = [&](const Query& q, KernelCounts& c) {
    bool contact = false;
    const std::string problem = disagreement_with_reference(q, {}, &contact);
    ++c.queries;
    c.contacts += contact;
    if (problem.empty()) return;
    ++c.disagreements;
    if (++described <= kDescribedDisagreements) out << "disagreement: " << problem << '\n';
  };
  ProgressBar bar(progress, "kernels seeds " + std::to_string(options.begin) + ":" + std::to_string(options.end));
  for (std::uint64_t seed = options.begin; seed < options.end; ++seed) {
    std::mt19937_64 rng(seed);
    for (int k = 0; k < 2; ++k) {
      for (long i = 0; i < options.per_seed; ++i) check(random_query(kinds[k], rng), counts.random[k]);
      for (long i = 0; i < near_degenerate; ++i) check(near_degenerate_query(kinds[k], rng), counts.near_degenerate[k]);
    }
    bar.update(static_cast<double>(seed + 1 - options.begin), static_cast<double>(options.end - options.begin),
               "seed " + std::to_string(seed));
  }
  bar.finish();
  return counts;
}

long run_seed_range(const SeedRangeOptions& options, std::ostream& out, std::ostream& progress) {
  const SeedRangeCounts counts = check_seed_range(options, out, progress);
  const char* kind_names[2] = {"vertex-face", "edge-edge"};
  const auto print = [&](const char* set, int k, const KernelCounts& c) {
    char line[200];
    std::snprintf(line, sizeof line, "%s %s: queries=%ld contacts=%ld disagreements=%ld", set, kind_names[k], c.queries,
                  c.contacts, c.disagreements);
    out << line << '\n';
  };
  for (int k = 0; k < 2; ++k) {
    print("random", k, counts.random[k]);
    print("near-degenerate", k, counts.near_degenerate[k]);
  }
  const KernelCounts total = counts.total();
  out << "kernels: seeds=" << options.begin << ':' << options.end << " queries=" << total.queries
      << " contacts=" << total.contacts << " disagreements=" << total.disagreements << '\n';
  return total.disagreements;
}

}  // namespace sscc::validation
