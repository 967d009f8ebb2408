// Continuous self-collision detection of a subspace model over one time step: the straight
// line q(t) = (1 - t) q0 + t q1, t in [0, 1], along which every vertex moves linearly.
//
// Reported: the non-adjacent triangle pairs (no shared vertex) that come into contact
// during the step, found through their vertex-face and edge-edge feature contacts (with
// times of impact), and the earliest time of impact. As in all continuous collision
// detection, the step is assumed to start free of intersections: two triangles that
// already interpenetrate at t = 0 and stay so without a feature contact are not reported
// (query_discrete(q0) finds them). Guarantee: exact for the vertex positions as computed in floating point,
// x = p + U_hat q_hat (the leaf kernels are exact; the node bounds are conservative, with a
// margin for the rounding of those positions), so nothing is missed and nothing is
// invented. Every feature pair is tested once per query, whichever triangle pairs share it.
// Pairs the model excludes (SubspaceModel::excluding, excluded_pairs.hpp) are treated as
// adjacent ones: never reported, and their features tested only through the pairs considered.
//
// With certificates (SSCC paper, Algorithm 1 made continuous): s = max(||q0||_M, ||q1||_M)
// is computed once per step; intra(n) returns when s < R_n, inter(a, b) of siblings when
// s < R_ab (the ellipsoid is convex, so the whole step lies inside it), and on steps taken
// lazily a node pair below siblings when s < R_xy (pair certificates). A step with s below
// the root's radius costs O(r). Normal cones (on by default) skip nodes and pairs of nodes
// proven free of self-contact over the step (src/query/patch_cull.hpp). Certificates and
// cones switched off give the traditional query: the same code, so the reports are
// identical and speedups compare like with like.
// The certificates' guarantee is for the exact positions; see certificates.hpp.
//
// Parallel: the top of the traversal is expanded into node pairs, in the order the serial
// traversal reaches them, that threads traverse independently, each with its own scratch;
// their hits are merged in that order, so the report does not depend on the thread count
// (SelfCcdOptions::threads). A step the root's certificate decides starts no thread.
//
// A built detector is immutable; query() keeps its scratch per call and is thread-safe.
// It owns its hierarchy, model and certificates (shared with its copies).
#pragma once

#include <Eigen/Core>

#include <memory>
#include <vector>

#include "sscc/bvh/subspace_bvh.hpp"
#include "sscc/ccd/ccd_types.hpp"
#include "sscc/certificates/certificates.hpp"

namespace sscc {

namespace detail {
class CullData;
}  // namespace detail

enum class FeatureKind : std::uint8_t { kVertexFace, kEdgeEdge };

struct FeatureContact {
  FeatureKind kind;
  int first;   ///< vertex (vertex-face) or edge index (edge-edge)
  int second;  ///< triangle (vertex-face) or edge index (edge-edge), first < second for edges
  double toi;
  friend bool operator==(const FeatureContact& a, const FeatureContact& b) {
    return a.kind == b.kind && a.first == b.first && a.second == b.second && a.toi == b.toi;
  }
};

struct TrianglePairContact {
  int first;  ///< first < second
  int second;
  double toi;  ///< the earliest of its features' times
  friend bool operator==(const TrianglePairContact& a, const TrianglePairContact& b) {
    return a.first == b.first && a.second == b.second && a.toi == b.toi;
  }
};

enum class SelfCcdMode : std::uint8_t {
  kAllContacts,  ///< every colliding pair and feature
  kEarliest,     ///< only the features at the earliest time of impact and their pairs
  kAnyHit,       ///< stop at the first feature contact found: the report holds it and the
                 ///< triangle pairs that contain it
};

/// Nodes with more triangles than this are bounded by their O(r) subspace bound under
/// NodeBounds::kHybrid, smaller ones by refitting. Self-collision culls at the lower levels
/// (siblings high up always touch), so loose boxes up there cost little, while refitting a
/// large node would compute every vertex under it. Lower: fewer vertices computed in steps
/// the certificates nearly decide, more node tests; higher: the reverse.
inline constexpr int kRefitTriangleLimit = 64;

/// How node boxes are bounded over the step (each is computed at most once per query, for
/// the nodes the traversal reaches; a query() that computes every vertex up front, without
/// certificates or far past them, refits every box in one pass instead, unless under
/// kHybrid the normal cones' radii cull most of the mesh in large nodes; query_positions
/// refits on demand).
enum class NodeBounds : std::uint8_t {
  /// Subspace bounds for nodes above kRefitTriangleLimit triangles, refitted boxes below:
  /// the vertices computed are those near where the traversal goes. The default. When every
  /// box is refitted in one pass (above), the large nodes' boxes are refitted too.
  kHybrid,
  /// Boxes refitted bottom-up from the vertex positions at both ends (3r flops per vertex
  /// under the node): tight whatever the deformation.
  kRefit,
  /// The O(r) subspace bounds of SubspaceBvh for every node, vertex positions only where a
  /// leaf needs them: cheap for small deformations, loose for large ones.
  kSubspace,
};

struct SelfCcdOptions {
  SelfCcdMode mode = SelfCcdMode::kAllContacts;
  NodeBounds bounds = NodeBounds::kHybrid;
  /// Cull by the certificates when the detector has them; false (with use_normal_cones and
  /// use_displacement_bounds false) gives the traditional query.
  bool use_certificates = true;
  /// Skip nodes, and pairs of neighbouring nodes, that form a patch whose normals stay in a
  /// cone and whose contour stays one simple polygon in projection over the step: proven free
  /// of self-contact (src/query/patch_cull.hpp states the theorem). Exact, like every cull
  /// here. Not applied with a minimum separation (it proves no contact, not a distance) nor to
  /// query_discrete. Two forms: query() bounds the cones from the step's norm, O(1) per node,
  /// with radii built once per hierarchy for the patches proven at rest and their unions
  /// (src/query/patch_radius.hpp; prepare() builds them);
  /// where those cull little, and in query_positions, the cones are formed from the positions,
  /// on meshes whose patches proven at rest average 16 triangles or more (patch_cull.hpp,
  /// kSmallestMeanRestPatch), on the steps the certificates or the displacement bounds leave
  /// mostly to the traversal (src/query/self_ccd.cpp). With certificates, on the nodes they do
  /// not cull. With them, each triangle pair whose boxes may meet is first tested against
  /// both triangles' own planes: one triangle's vertices strictly on one side of the other's
  /// moving plane for the whole step proves the pair apart (src/query/separating_plane.hpp),
  /// before any feature's kernel, and pairs of leaves that hold no considered triangle pair
  /// are skipped before their box test (src/query/unconsidered_leaf_pairs.hpp). The README's
  /// self-CCD table gives the speed against the plain traversal.
  bool use_normal_cones = true;
  /// Skip nodes, and pairs of nodes, whose triangles the step's deformation moves too little,
  /// relative to one another, to close the gaps they have at rest: bounded mode by mode from
  /// the step's coordinates in O(r) per node (src/query/displacement_bound.hpp states the
  /// theorem), so a deformation concentrated in one part leaves the others culled where the
  /// certificates' norm bound cannot. Exact, like every cull here. Applied to query() when
  /// it uses no certificates (with them it costs more than it saves: they cull the same nodes
  /// sooner); query_positions has no coordinates. All three switches false give the
  /// traditional query, the SSCC paper's baseline.
  bool use_displacement_bounds = true;
  /// Threads for one query: 0 uses every thread OpenMP may use (the cores, or
  /// OMP_NUM_THREADS), 1 the serial traversal. The report is the same for every count, in
  /// the same order, first hits included; only the statistics differ (work that several
  /// threads repeat, such as node and triangle boxes, counts once per thread; the vertex
  /// positions are computed once, shared by the threads). query_discrete and
  /// query_exhaustive run on one thread.
  int threads = 0;
  /// The kernels' options. A minimum separation (kernel.minimum_separation > 0) cannot be
  /// combined with certificates, which bound contact, not proximity: such queries throw.
  ccd::CcdOptions kernel;
};

/// Makes `options` the traditional query's (the SSCC paper's baseline, the plain swept-box
/// traversal): certificates, normal cones and displacement bounds off, the rest kept.
inline void set_traditional(SelfCcdOptions& options) {
  options.use_certificates = false;
  options.use_normal_cones = false;
  options.use_displacement_bounds = false;
}

struct SelfCcdStats {
  long nodes_visited = 0;
  long box_tests = 0;
  long triangle_pairs = 0;  ///< non-adjacent pairs whose boxes over the step may meet
  long kernel_calls = 0;
  long vertices_computed = 0;
  /// Of vertices_computed, those whose start position was the previous step's end: a query
  /// starting where an earlier one on the detector ended (q0 equal to its q1, bit for bit, as
  /// a simulator's next step does), its buffers still holding that end, computes only their end.
  long vertex_starts_reused = 0;
  long certified = 0;  ///< nodes, sibling pairs and node pairs below them culled by a certificate
  /// Of those, node pairs below sibling pairs (pair certificates; 0 on steps computing every vertex).
  long pair_certified = 0;
  long cone_culled = 0;          ///< nodes and node pairs culled by the normal-cone test
  long cone_radius_culled = 0;   ///< of those, culled from the step's norm alone (patch radii)
  long plane_culled = 0;         ///< of triangle_pairs, culled by a separating plane (normal cones' queries)
  long displacement_culled = 0;  ///< nodes and node pairs culled by the displacement bounds
  /// Of the box tests, node pairs found apart with at least one node's box moved from the
  /// previous step's (a query continuing an earlier one, as for vertex_starts_reused),
  /// sparing that node's vertices.
  long moved_box_culled = 0;
  bool root_certified = false;  ///< the whole step decided by the root's certificate
  double seconds = 0.0;
};

/// Which parts of the culls' static data a detector (with its copies) has built: each is built
/// by the first query, or prepare(), whose options use it, and never for options that do not.
struct SelfCcdBuiltParts {
  bool cone_boundaries = false;          ///< the normal cones' boundary chains (use_normal_cones)
  bool cone_radii = false;               ///< the patches at rest and their radii (use_normal_cones)
  bool unconsidered_leaf_pairs = false;  ///< the leaf pairs skipped with the cones (use_normal_cones)
  bool certified_radii = false;          ///< the certificates' sorted radii (use_normal_cones, certificates)
  bool displacement_bounds = false;      ///< rest clearances and fits (use_displacement_bounds, no certificates)
};

struct SelfCcdReport {
  std::vector<TrianglePairContact> pairs;  ///< sorted by (first, second)
  std::vector<FeatureContact> features;    ///< sorted by (kind, first, second)
  double earliest_toi = 1.0;               ///< meaningful when collided()
  SelfCcdStats stats;
  bool collided() const { return !pairs.empty(); }
};

/// A detector owns what it queries: it holds its hierarchy (and through it the model) and
/// its certificates by shared ownership, so it stays valid whatever happens to the objects
/// it was built from. Copies share them (copying is O(1)). It also keeps the buffers of its
/// finished queries (positions, box and cone caches: a few hundred bytes per triangle, one
/// set per query or query thread that ran at the same time) and lends them to the next, so
/// that a simulator's loop of queries allocates none of them per step.
class SelfCcd {
 public:
  /// Copies the hierarchy (the model inside it is shared, not copied).
  explicit SelfCcd(const SubspaceBvh& bvh);
  /// With certificates (copied); throws std::invalid_argument when they were computed for
  /// another model or hierarchy.
  SelfCcd(const SubspaceBvh& bvh, const Certificates& certificates);
  /// Shares a hierarchy and certificates (may be null) with other detectors, without copies.
  explicit SelfCcd(std::shared_ptr<const SubspaceBvh> bvh, std::shared_ptr<const Certificates> certificates = nullptr);

  const SubspaceBvh& bvh() const { return *bvh_; }
  const Certificates* certificates() const { return certificates_.get(); }

  /// Swept-box traversal of the hierarchy (culled by the certificates), then the kernels.
  /// q0 and q1 are reduced coordinates (not scaled); wrong sizes or NaN/infinity throw
  /// std::invalid_argument.
  SelfCcdReport query(const Eigen::VectorXd& q0, const Eigen::VectorXd& q1, const SelfCcdOptions& options = {}) const;

  /// Builds what queries with these options precompute on their first use (the normal
  /// cones' boundary chains, patches at rest and radii, the certificates' sorted radii, the
  /// displacement bounds' rest clearances and affine fits), so that no query pays for it.
  /// Optional; thread-safe; on every thread. Without it the first query with the defaults
  /// takes that much longer (without certificates, two threads: 0.49 s on the 15k-triangle
  /// lion, 3.6 s on the 75k-triangle bunny; the next queries 1.9 and 6.2 ms).
  void prepare(const SelfCcdOptions& options = {}) const;
  /// What the queries and prepare() have built so far (shared with the detector's copies).
  SelfCcdBuiltParts built_parts() const;

  /// Whether the root's certificate alone decides the step (what query() then reports in
  /// O(r)): false without usable certificates. Throws as query() does for a bad q.
  bool root_certifies(const Eigen::VectorXd& q0, const Eigen::VectorXd& q1, const SelfCcdOptions& options = {}) const;

  /// The threads query(q0, q1, options) runs on: every thread options.threads allows without
  /// certificates, or far past the root's while the certificates leave most of the hierarchy
  /// to the traversal; else one (certificates cull most of what threads would share). For
  /// schedulers such as Scene::step. Throws as query() does for a bad q.
  int query_threads(const Eigen::VectorXd& q0, const Eigen::VectorXd& q1, const SelfCcdOptions& options = {}) const;

  /// The traditional query on explicit vertex positions at both ends of the step (each
  /// vertex moving linearly): for poses the subspace does not hold, where certificates do
  /// not apply. Simulators without a subspace use PositionCcd (position_ccd.hpp), built from
  /// the mesh alone. Refitted boxes, the same traversal and kernels. Throws
  /// std::invalid_argument for a wrong count or a NaN/infinity.
  SelfCcdReport query_positions(const std::vector<Eigen::Vector3d>& x0, const std::vector<Eigen::Vector3d>& x1,
                                const SelfCcdOptions& options = {}) const;

  /// Discrete query for a single configuration: the non-adjacent triangle pairs that
  /// intersect (exact), as pairs with toi 0; no features.
  SelfCcdReport query_discrete(const Eigen::VectorXd& q, const SelfCcdOptions& options = {}) const;

  /// Reference: every non-adjacent triangle pair, with the same leaf code (O(N^2)); no
  /// cull (certificates, cones and the triangle pairs' separating planes ignored).
  SelfCcdReport query_exhaustive(const Eigen::VectorXd& q0, const Eigen::VectorXd& q1,
                                 const SelfCcdOptions& options = {}) const;

 private:
  /// max(||q_hat0||, ||q_hat1||), the scaled coordinates' norms (throws for a bad q).
  double step_norm(const Eigen::VectorXd& q0, const Eigen::VectorXd& q1) const;
  std::shared_ptr<const SubspaceBvh> bvh_;
  std::shared_ptr<const Certificates> certificates_;
  // What the normal-cone and displacement culls precompute, each on the first query that
  // uses it (thread-safe; copies share it).
  std::shared_ptr<detail::CullData> culls_;
};

}  // namespace sscc
