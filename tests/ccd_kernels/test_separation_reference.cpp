// The minimum-separation mode held against a reference for the minimum distance over the
// step (validation/min_distance.hpp: a Lipschitz branch-and-bound over t with direct
// distance evaluation, independent of the kernels' search). For each query and separation d:
// - no false negative: a query whose minimum distance is at most d is a contact;
// - false positives only within the band: a contact's minimum distance is at most
//   d (1 + kSeparationRelativeTolerance);
// - the reported time: the distance stays above d before it, and comes within the band
//   within the time-of-impact tolerance after it.
// The separations tried include the two sides of each query's own minimum distance, just
// inside d and just outside the band, where a loose bound would answer wrongly.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "min_distance.hpp"
#include "query_generators.hpp"
#include "sscc/ccd/kernels.hpp"

namespace {

using sscc::ccd::kSeparationRelativeTolerance;
using sscc::validation::BracketOptions;
using sscc::validation::DistanceBracket;
using sscc::validation::Kind;
using sscc::validation::min_distance_bracket;
using sscc::validation::Query;

/// How far past the reference bracket the separations probing its two sides are placed:
/// well above the bracket's relative width (1e-6 by default) and its rounding.
constexpr double kProbeMargin = 1e-5;

/// Below this fraction of the query's extent, d is in the kernel's rounding-limited range
/// (separation_search.hpp): a contact may be reported somewhat beyond the band there, so
/// the band is checked only above it (no false negative is allowed anywhere).
constexpr double kRoundingLimitedSeparation = 1e-7;

/// The largest distance between two of the eight points: the primitives' sizes and motion.
double extent(const Query& q) {
  double e = 0.0;
  for (const auto& p : q.points) {
    for (const auto& r : q.points) e = std::max(e, (p - r).norm());
  }
  return e;
}

struct Tally {
  int contacts = 0;
  int misses = 0;
  int probed = 0;  // queries not touching, probed on both sides of their minimum distance
  int sharp = 0;   // of which the reference bracketed the minimum within kProbeMargin
};

/// The reference's answer to "does the distance come within `threshold` on [t_begin, t_end]?".
DistanceBracket decide(const Query& q, double threshold, double t_begin = 0.0, double t_end = 1.0) {
  BracketOptions options;
  options.threshold = threshold;
  options.t_begin = t_begin;
  options.t_end = t_end;
  return min_distance_bracket(q, options);
}

void check_separation(const Query& q, double d, Tally& tally) {
  sscc::ccd::CcdOptions options;
  options.minimum_separation = d;
  const sscc::ccd::CcdResult result = sscc::validation::run_kernel(q, options);
  const double reach = d * (1 + kSeparationRelativeTolerance);
  INFO("d " << d << " hit " << result.hit << " toi " << result.toi);
  if (!result.hit) {
    ++tally.misses;
    const DistanceBracket within = decide(q, d);
    INFO("minimum distance in [" << within.lower << ", " << within.upper << "]");
    CHECK_FALSE(within.upper <= d);
    return;
  }
  ++tally.contacts;
  if (d >= kRoundingLimitedSeparation * extent(q)) {
    const DistanceBracket band = decide(q, reach);
    INFO("minimum distance in [" << band.lower << ", " << band.upper << "]");
    CHECK(band.lower <= reach);
  }
  // Before the reported time the distance stays above d (every earlier stretch was
  // excluded, the reported time's own sample included).
  if (result.toi > 0) CHECK(decide(q, d, 0.0, result.toi).upper > d);
  CHECK(decide(q, reach, result.toi, std::min(1.0, result.toi + options.toi_tolerance)).lower <= reach);
}

/// The query at separations around its own minimum distance and at a few fixed ones
/// (relative to its extent).
void check_query(const Query& q, Tally& tally) {
  for (double fraction : {1e-4, 1e-2, 0.1}) check_separation(q, fraction * extent(q), tally);
  const DistanceBracket whole = min_distance_bracket(q);
  if (whole.lower > 0.0) {
    ++tally.probed;
    tally.sharp += whole.upper - whole.lower <= kProbeMargin * whole.upper;
    check_separation(q, whole.upper * (1 + kProbeMargin), tally);
    check_separation(q, whole.lower / (1 + kSeparationRelativeTolerance) * (1 - kProbeMargin), tally);
  }
}

}  // namespace

TEST_CASE("minimum separation against the minimum-distance reference: random queries", "[kernels][separation]") {
  std::mt19937_64 rng(23);
  Tally tally;
  for (int i = 0; i < 400; ++i) {
    for (Kind kind : {Kind::kVertexFace, Kind::kEdgeEdge}) {
      INFO(sscc::validation::to_string(kind) << " query " << i);
      check_query(sscc::validation::random_query(kind, rng), tally);
    }
  }
  CHECK(tally.contacts > 800);
  CHECK(tally.misses > 2000);
  CHECK(tally.sharp >= 0.9 * tally.probed);
}

TEST_CASE("minimum separation against the minimum-distance reference: far from the origin", "[kernels][separation]") {
  // Rounding that grew with the coordinates' magnitude rather than the primitives' extent
  // would loosen the bound past the band here.
  const Eigen::Vector3d far(1e6, -3e5, 7e5);
  std::mt19937_64 rng(31);
  Tally tally;
  for (int i = 0; i < 150; ++i) {
    for (Kind kind : {Kind::kVertexFace, Kind::kEdgeEdge}) {
      INFO(sscc::validation::to_string(kind) << " query " << i);
      Query q = sscc::validation::random_query(kind, rng);
      for (auto& p : q.points) p += far;
      check_query(q, tally);
    }
  }
  CHECK(tally.contacts > 200);
  CHECK(tally.misses > 600);
  CHECK(tally.sharp >= 0.9 * tally.probed);
}

TEST_CASE("minimum separation against the minimum-distance reference: degenerate queries", "[kernels][separation]") {
  std::mt19937_64 rng(29);
  Tally tally;
  for (int i = 0; i < 200; ++i) {
    for (Kind kind : {Kind::kVertexFace, Kind::kEdgeEdge}) {
      INFO(sscc::validation::to_string(kind) << " query " << i);
      check_query(sscc::validation::near_degenerate_query(kind, rng), tally);
      check_query(sscc::validation::integer_grid_query(kind, rng), tally);
      check_query(sscc::validation::resting_contact_query(kind, rng), tally);
    }
  }
  CHECK(tally.contacts > 2000);
  CHECK(tally.misses > 1500);
  CHECK(tally.sharp >= 0.9 * tally.probed);
}

TEST_CASE("minimum separation: exactly parallel edges far from the origin are decided, not reported at once",
          "[kernels][separation]") {
  // Two parallel edges about 15,000 apart, half a million from the origin, one end moving by
  // an ulp: the directions of closest approach are too poor for the search over t, which
  // used to run out and report contact for any d; the box search decides instead.
  using V = Eigen::Vector3d;
  const V a0(494920.61915488512, 545454.54545454541, 14.231483827328516);
  const V a0_moved(494920.61915488512, 545454.54545454541, 14.231483827328518);
  const V a1(479756.08173698478, 636363.63636363635, 28.173255684142969);
  const V b0(494920.61915488512, 636363.63636363635, 14.231483827328516);
  const V b1(479756.08173698478, 727272.72727272729, 28.173255684142969);
  for (double d : {100.0, 1000.0, 10000.0, 14000.0}) {
    sscc::ccd::CcdOptions options;
    options.minimum_separation = d;
    INFO("d = " << d);
    CHECK_FALSE(sscc::ccd::edge_edge_ccd(a0, a1, b0, b1, a0_moved, a1, b0, b1, options).hit);
  }
}
