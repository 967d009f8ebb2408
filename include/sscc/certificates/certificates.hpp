// Subspace self-collision certificates (SSCC paper, sections 4 and 5).
//
// For every node n of a SubspaceBvh, the intra-node radius R_n: no two non-adjacent
// triangles under n touch in any configuration with ||q||_M < R_n. For every pair of
// sibling nodes (a, b), the inter-node radius R_ab: no triangle under a touches a
// non-adjacent triangle under b while ||q||_M < R_ab. The set ||q||_M < R is an ellipsoid,
// convex, so a straight-line step whose two ends lie inside it is certified whole.
// Pairs the model excludes (excluded_pairs.hpp) count as adjacent here, as in the queries;
// the key records them, so certificates of a model with and without them differ.
//
// Guarantee: every stored radius is a lower bound of the true one (for the exact positions
// p + U q): built from the conservative triangle-pair bounds of triangle_pair_bound.hpp, the
// box-box and 1D bounds in Cauchy-Schwarz form, and clamps that only lower values (the
// global radius R_global, and a computation stopped early keeps the minimum it was handed).
// The pair bounds also pad the rounding of the positions a query computes in floating point
// (triangle_pair_bound.cpp: (r + 2) units of roundoff of each coordinate's magnitude and of
// ||U_hat_v|| ||q_hat||), so a contact that exists only through that rounding, as far from
// the origin, is never certified away: reports with and without certificates agree.
// Radii are not tight: a pair's radius is resolved to within the relative accuracy epsilon
// where it matters, and every radius is capped at R_global.
//
// Below each sibling pair, pair certificates (the SSCC paper certifies siblings only): the
// node pairs the traversal meets when it descends between the two siblings (each splitting
// the larger node of its pair, as SelfCcd's traversal does) get radii of their own, R_xy: no
// triangle under x touches a non-adjacent triangle under y while ||q||_M < R_xy. A step whose
// norm lies above a sibling pair's radius then still skips most of the pairs below it, where
// the pair's closest triangles are not (SelfCcd::query walks them on the steps it takes
// lazily, not on those that compute every vertex, where few hold). Each is the minimum over
// the pair's children, down to its leaves' triangle pairs, with the same conservative bounds
// as the radii above (with the looser accuracy kPairEpsilon), resolved up to pair_reach times
// the sibling pair's radius: the pair's children are stored where they are near at rest
// (their rest boxes within kNearPairMargin of each other) and their radius is below that
// reach; a child stored without children of its own holds a radius the traversal tests, then
// descends uncertified below it.
//
// Units: radii are norms of the scaled coordinates, ||q_hat||_2 = ||q||_M.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sscc/bvh/subspace_bvh.hpp"

namespace sscc {

struct CertificateParameters {
  /// Relative accuracy of the triangle-pair radii (norms): refined until the lower bound
  /// is at least (1 - epsilon) times a contact configuration found. Smaller: tighter
  /// certificates, longer precomputation.
  double epsilon = 0.1;
  /// R_global = scale * (the norm at which the floppiest mode direction moves some vertex
  /// by half the mesh's bounding-box diagonal). Radii are resolved up to R_global only.
  double global_radius_scale = 1.0;
  /// Limits of the refinement of one triangle pair (past them the bound reached is kept).
  int max_subdivision_depth = 16;
  int max_evaluations_per_pair = 2048;
  /// Pair certificates below each sibling pair are resolved up to this multiple of its
  /// radius (and R_global); 0: none. Larger: steps further past the sibling radii keep
  /// certificates below them, for a longer precomputation and a larger file.
  double pair_reach = 4.0;
};

/// A node pair below a sibling pair: the radius below which no considered triangle pair across
/// it touches (at most R_global), and the index of its first child pair's certificate (its
/// children, in the traversal's order, are consecutive), or -1 when none are stored.
struct PairCertificate {
  double radius = 0.0;
  std::int32_t first_child = -1;
};

/// Rest boxes of two nodes within this fraction of the larger node's largest rest half extent
/// make a near pair, whose children get pair certificates of their own; farther pairs get one
/// radius, and the traversal descends below it uncertified. Larger: more pairs stored and
/// resolved; smaller: fewer pairs certified below the near ones.
inline constexpr double kNearPairMargin = 0.5;
/// Relative accuracy (and most constant-mode evaluations) of the triangle-pair bounds of the
/// pair certificates, looser than the node radii's (CertificateParameters::epsilon is used when
/// larger): the pairs below a sibling pair are many, and a radius within 30% decides most
/// steps. Smaller: a longer precomputation for slightly larger radii.
inline constexpr double kPairEpsilon = 0.3;
inline constexpr int kPairEvaluations = 64;

/// What is wrong with `parameters` ("" when they are valid): epsilon in (0, 1), a positive
/// finite global radius scale, a non-negative depth, at least one evaluation per pair and a
/// finite pair reach of 0 or at least 1.
/// precompute() refuses invalid parameters, read() refuses files that hold them.
std::string problem_with(const CertificateParameters& parameters);

/// The certificates hold for scaled bases whose largest entry lies within 2^-this..2^this:
/// past it the Gram matrices of the mode blocks (their entries' products) underflow or
/// overflow. Measured on a sphere's 27 polynomial modes times 2^e: the root's radius, scaled
/// back, within 1e-4 of scale 1's (the hierarchies differ) for e from -500 to 500 with
/// floating-point traps off, but from e = -300 down the precomputation overflows on the way;
/// at e = -565 (entries near 1e-170) every radius came out infinite, a certificate for
/// everything; at 520 and above every radius 0. Larger: bases whose precomputation leaves the
/// double range, then whose certificates are not valid; smaller: refused bases that would
/// have been fine.
inline constexpr int kLargestCertifiedModeExponent = 200;

/// What keeps certificates from being valid for `model` ("" when nothing): a scaled basis
/// whose largest entry is outside 2^-kLargestCertifiedModeExponent..2^kLargestCertifiedModeExponent
/// (a model in other units is fine; queries without certificates hold at any scale).
/// precompute() refuses such models, check_belongs_to() their certificates.
std::string basis_scale_problem(const SubspaceModel& model);

struct PrecomputeStats {
  long node_pairs_visited = 0;
  long node_pairs_culled = 0;       ///< by the box-box bound or the group floor
  long triangle_pairs_culled = 0;   ///< by the 1D bound
  long triangle_pairs_bounded = 0;  ///< triangle_pair_radius calls
  long constant_mode_evaluations = 0;
  long pair_certificates = 0;  ///< stored below the sibling pairs
  long pair_tree_tasks = 0;    ///< descents below the pair certificates run as tasks any thread takes up
  int threads = 1;
  double seconds = 0.0;
};

/// Where a precomputation stands. Its work items are a leaf's own triangle pairs and a pair of
/// sibling nodes; each counts as many units as it has triangle pairs, plus 1024 per triangle, a
/// measure of its cost known before it runs (nearly every pair is screened by the 1D bound,
/// and the pairs bounded lie along the nodes' borders), so work_done / work says roughly how
/// far it is. The pairs make the levels near the root the largest: about three quarters of
/// all pairs are between the root's children.
struct PrecomputeStatus {
  int levels_done = 0;  ///< tree levels finished (the deepest first)
  int levels = 0;       ///< levels to compute
  long work_done = 0;   ///< units of the work items finished
  long work = 0;        ///< units of every work item
};

/// Called as work items finish (from the threads computing them, one call at a time) and after
/// each level. An exception it throws stops the precomputation and reaches the caller.
using PrecomputeProgress = std::function<void(const PrecomputeStatus&)>;

class CertificateShard;  // certificate_shards.hpp
namespace detail {
struct PrecomputeDriver;  // src/certificates/precompute_driver.hpp
}  // namespace detail

class Certificates {
 public:
  /// Computes the certificates of every node and sibling pair, in parallel (OpenMP).
  /// Throws std::invalid_argument for parameters out of range and for a basis of entries
  /// outside the range certificates hold for (basis_scale_problem).
  static Certificates precompute(const SubspaceBvh& bvh, const CertificateParameters& parameters = {},
                                 const PrecomputeProgress& progress = {});
  /// Shard `index` of `count` of the precomputation (certificate_shards.hpp), for one process
  /// or machine each; merge() puts the shards together.
  static CertificateShard precompute_shard(const SubspaceBvh& bvh, const CertificateParameters& parameters, int index,
                                           int count, const PrecomputeProgress& progress = {});
  /// The certificates of `shards`, one of each index, computed for bvh (in any order): the top
  /// levels the shards leave are computed here. Equal to precompute()'s, their file byte for
  /// byte. Throws std::invalid_argument naming a missing or repeated shard, or shards of
  /// another model, hierarchy, parameters or shard count.
  static Certificates merge(const SubspaceBvh& bvh, const std::vector<CertificateShard>& shards,
                            const PrecomputeProgress& progress = {});

  /// For a model and hierarchy, the identity the certificates are tied to: a hash of the
  /// rest positions, triangles, scaled basis, excluded pairs, the tree and the parameters.
  static std::uint64_t key_of(const SubspaceBvh& bvh, const CertificateParameters& parameters);

  /// Writes the versioned, checksummed binary file; throws std::runtime_error on I/O failure.
  void write(const std::string& path) const;
  /// Reads a file written by write() for this hierarchy. Throws CertificateFileError when
  /// the file is missing, truncated, corrupt, of another version, or computed for another
  /// mesh, basis, weights or tree.
  static Certificates read(const std::string& path, const SubspaceBvh& bvh);

  double global_radius() const { return global_radius_; }
  /// R_n.
  double node_radius(int n) const { return node_radius_[n]; }
  /// R_ab for two children of one node; 0 (no certificate) for any other pair.
  double sibling_radius(int a, int b) const {
    return first_sibling_[a] == first_sibling_[b] && a != b ? sibling_radius_[a][b - first_sibling_[b]] : 0.0;
  }
  int node_count() const { return static_cast<int>(node_radius_.size()); }
  /// The index of the pair certificate of sibling pair (a, b) (a != b, children of one node),
  /// whose children certify the pairs below it; -1 when none.
  int sibling_pair_certificate(int a, int b) const { return sibling_tree_[a][b - first_sibling_[b]]; }
  const PairCertificate& pair_certificate(int k) const { return pairs_[k]; }
  const std::vector<PairCertificate>& pair_certificates() const { return pairs_; }
  const CertificateParameters& parameters() const { return parameters_; }
  std::uint64_t key() const { return key_; }
  /// Statistics of the precomputation (zero for certificates read from a file; after merge(),
  /// of the merge's own levels).
  const PrecomputeStats& stats() const { return stats_; }
  /// Throws std::invalid_argument when the certificates were not computed for bvh, or its
  /// basis is outside the range certificates hold for (basis_scale_problem).
  void check_belongs_to(const SubspaceBvh& bvh) const;

 private:
  friend class CertificateShard;
  friend struct detail::PrecomputeDriver;
  Certificates(const SubspaceBvh& bvh, const CertificateParameters& parameters);
  /// The certificate file's bytes, and the certificates they hold for bvh (`source` names them
  /// in errors).
  std::string to_bytes() const;
  static Certificates from_bytes(const std::string& bytes, const SubspaceBvh& bvh, const std::string& source);
  /// What is wrong with the pair certificates' structure for bvh ("" when nothing): indices
  /// out of range or not increasing, children blocks of the wrong size, radii not in
  /// [0, R_global]. read() refuses files that have such a problem.
  std::string pair_certificate_problem(const SubspaceBvh& bvh) const;
  /// Lays the pair certificates of every sibling pair (by its first node and the position of
  /// the second) out in one array, in node order, and points the sibling pairs at them.
  void assemble_pair_certificates(std::vector<std::array<std::vector<PairCertificate>, kBranchingFactor>>& trees);
  /// The pair certificates below sibling pair (a, b) (a < b), laid out as the precomputation
  /// built them (entry 0 the pair itself, indices relative); empty when none.
  std::vector<PairCertificate> pair_tree(const SubspaceBvh& bvh, int a, int b) const;

  // Each node's results (what a shard carries for its nodes) are listed in
  // detail::PrecomputeDriver::copy_node (precompute.cpp).
  CertificateParameters parameters_;
  std::uint64_t key_ = 0;
  double global_radius_ = 0.0;
  std::vector<double> node_radius_;
  std::vector<int> first_sibling_;                                    // the first child of the node's parent
  std::vector<std::array<double, kBranchingFactor>> sibling_radius_;  // by the sibling's position
  std::vector<std::array<int, kBranchingFactor>> sibling_tree_;       // likewise: the pair certificate's index
  std::vector<PairCertificate> pairs_;
  PrecomputeStats stats_;
};

struct CertificateFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace sscc
