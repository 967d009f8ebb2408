// A scene of reduced deformable objects, queried once per time step: what a simulator calls.
//
// Each object is an instance of a precomputed model (its SelfCcd detector: model, hierarchy
// and, optionally, certificates); many instances share one detector, so sixteen bunnies
// need one precomputation. Per step the caller gives every object its reduced coordinates
// q0 -> q1 and, optionally, its rigid frame at both ends (x_world = R x_local + t).
//
// Reported:
//  - self-collisions per object, for the motion its SceneObjectOptions::self_motion names:
//    SelfMotion::kObjectFrame (the default): vertices move linearly with q in the object's
//    own frame and the frame moves rigidly, which changes no self contact (SelfCcd::query,
//    certificates included);
//    SelfMotion::kWorldLinear: each vertex moves on the straight line between its world
//    positions at the two ends, as between objects (SelfCcd::query_positions on those
//    paths: no certificates);
//  - collisions between objects, for world-space linear vertex trajectories: each vertex
//    moves on the straight line between its world positions at the two ends of the step
//    (the usual linearisation of a rigid motion over a step), found by a swept-box
//    traversal of the two hierarchies and the same exact kernels;
//  - the earliest time of impact over everything.
// Guarantee: nothing is missed for those trajectories (the self query's guarantee, and for
// pairs of objects: conservative node bounds, exact kernels on the positions as computed).
//
// Which self motion to use: the two coincide when the frame does not turn (a translation
// linear in t changes no contact), and kWorldLinear is then answered in the object frame,
// certificates included. When the frame turns by theta, a world-linear vertex at distance
// rho from the rotation axis cuts the chord of its arc, up to rho (1 - cos(theta / 2)) inside
// the rigid path: a half-turn collapses a sphere onto the axis, which the object-frame test
// never sees. So: a simulator that moves vertices on straight lines in world space (as the
// inter-object test assumes) wants kWorldLinear, or steps that turn little; one
// that moves each object rigidly along its frame's interpolation wants kObjectFrame with any
// rotation (raise SceneOptions::max_object_frame_rotation). The object-frame test refuses a
// step whose frame turns by more than max_object_frame_rotation (kMaxObjectFrameRotation by
// default): take smaller steps, or choose kWorldLinear, which costs a traversal whenever the
// frame turns (the certificates bound the object-frame motion only).
//
// Skipping what a step does not need: an object that did not move (q0 == q1 and equal
// frames) costs nothing: nothing can come into contact during the step, and, as in every
// continuous query, a contact that already exists at t = 0 (an object resting in contact
// with itself, or two static objects touching) is not reported; SelfCcd::query_discrete
// finds such contacts; an object certified for the step costs O(r); a pair of objects
// whose swept bounds (the root's O(r) subspace bound, in world space) do not meet costs one
// box test; the vertices of an object are computed only where another object's bounds
// reach them; self and inter-object tests can be switched off per object.
//
// Parallel: the objects' self tests that need a traversal and the object pairs whose roots
// meet are the step's tasks, shared by the threads (one such self test alone gets them all,
// inside its query); the rest is decided before any thread starts. Results are merged in the
// serial order, so the report is the same for every thread count (SceneOptions::threads).
//
// A built scene is immutable; step() keeps its scratch per call and is thread-safe.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "sscc/query/self_ccd.hpp"

namespace sscc {

/// A rigid frame: x_world = rotation x_local + translation (rotation orthonormal).
struct RigidFrame {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  friend bool operator==(const RigidFrame& a, const RigidFrame& b) {
    return a.rotation == b.rotation && a.translation == b.translation;
  }
};

/// Largest deviation of R^T R from the identity accepted as a rotation (entry-wise): far
/// above the rounding of a product of a few rotations, far below any real shear.
inline constexpr double kRotationTolerance = 1e-9;

/// Largest rotation of an object's frame over one step (radians) that the object-frame self
/// test accepts by default. At this angle a world-linear vertex path leaves the rigid path by
/// at most 1 - cos(0.125) < 0.8 % of the vertex's distance from the rotation axis (at 60
/// steps per second, 2.4 turns per second). Larger: steps pass whose world-linear motion
/// differs more from the motion tested (self contacts a world-linear simulator meets go
/// unreported); smaller: more ordinary rigid steps are refused.
inline constexpr double kMaxObjectFrameRotation = 0.25;

/// The vertex motion an object's self test assumes (see the top of this header).
enum class SelfMotion : std::uint8_t {
  kObjectFrame,  ///< linear in q in the object's frame, the frame moving rigidly
  kWorldLinear,  ///< straight lines in world space between the step's two ends
};

struct SceneObjectOptions {
  bool self_collision = true;  ///< test the object against itself
  bool inter_object = true;    ///< test it against the other objects (both must allow it)
  SelfMotion self_motion = SelfMotion::kObjectFrame;
};

/// One object's motion over the step.
struct ObjectStep {
  Eigen::VectorXd q0, q1;  ///< reduced coordinates (not scaled)
  RigidFrame frame0, frame1;
};

/// The options of a step: those of the self queries, applied to every object's self test
/// (mode for the whole step; set_traditional makes every self test the traditional query;
/// bounds; the kernels' options, also used between
/// objects). `threads` are the step's: 0 uses every thread OpenMP may use (the cores, or
/// OMP_NUM_THREADS), 1 runs everything on the caller's thread. The report does not depend
/// on it; the statistics' vertex counts and times may (self_seconds and inter_seconds add
/// up the time of every thread).
struct SceneOptions : SelfCcdOptions {
  /// Largest rotation of a frame over the step (radians) accepted for a self test in the
  /// object's frame; larger steps are refused. Infinity accepts every step: for a simulator
  /// whose objects follow their frames rigidly, where the object-frame test is exact.
  double max_object_frame_rotation = kMaxObjectFrameRotation;
};

enum class SelfTestOutcome : std::uint8_t {
  kTraversed,  ///< the self query ran (partly culled by certificates, or not at all)
  kCertified,  ///< the root certificate decided the step in O(r)
  kStatic,     ///< the object did not move: nothing to test (contacts at t = 0 not reported)
  kSwitchedOff,
  kNotReached,  ///< any-hit mode stopped the step before this object
};

struct ObjectSelfResult {
  SelfTestOutcome outcome = SelfTestOutcome::kNotReached;
  SelfCcdReport report;  ///< empty unless traversed
};

/// A colliding pair of triangles of two objects: triangle `first` of `object_first` and
/// triangle `second` of `object_second`, object_first < object_second.
struct InterObjectContact {
  int object_first, first, object_second, second;
  double toi;
  friend bool operator==(const InterObjectContact& x, const InterObjectContact& y) {
    return x.object_first == y.object_first && x.first == y.first && x.object_second == y.object_second &&
           x.second == y.second && x.toi == y.toi;
  }
};

/// A feature contact between two objects: vertex-face (the vertex of `object_first`, the
/// face of `object_second`) or edge-edge.
struct InterObjectFeature {
  FeatureKind kind;
  int object_first, first, object_second, second;
  double toi;
  friend bool operator==(const InterObjectFeature& x, const InterObjectFeature& y) {
    return x.kind == y.kind && x.object_first == y.object_first && x.first == y.first &&
           x.object_second == y.object_second && x.second == y.second && x.toi == y.toi;
  }
};

struct SceneStats {
  int objects_static = 0;
  int objects_certified = 0;
  int objects_traversed = 0;
  long object_pairs = 0;         ///< pairs whose tests were switched on
  long object_pairs_culled = 0;  ///< decided by one box test (or both static)
  long inter_box_tests = 0;
  long inter_triangle_pairs = 0;
  long inter_kernel_calls = 0;
  long inter_vertices_computed = 0;
  double self_seconds = 0.0;
  double inter_seconds = 0.0;
  double seconds = 0.0;
};

struct SceneReport {
  std::vector<ObjectSelfResult> objects;     ///< one per object, in order
  std::vector<InterObjectContact> contacts;  ///< sorted
  std::vector<InterObjectFeature> features;  ///< sorted
  double earliest_toi = 1.0;                 ///< over all contacts; meaningful when collided()
  SceneStats stats;
  bool collided() const;
};

class Scene {
 public:
  /// Adds an instance of a detector (the scene holds a copy, which shares the detector's
  /// hierarchy and certificates) and returns its index.
  int add_object(const SelfCcd& detector, SceneObjectOptions options = {});
  int object_count() const { return static_cast<int>(objects_.size()); }
  /// Object `object`'s detector (the scene's copy, sharing the one added) and options; throws
  /// std::out_of_range for an index out of range.
  const SelfCcd& detector(int object) const { return objects_.at(static_cast<std::size_t>(object)).detector; }
  const SceneObjectOptions& object_options(int object) const {
    return objects_.at(static_cast<std::size_t>(object)).options;
  }

  /// One time step. `steps` holds one entry per object. Throws std::invalid_argument for a
  /// wrong count, q of the wrong size or with NaN/infinity, a frame that is not rigid, or a
  /// frame turning by more than options.max_object_frame_rotation under an object-frame self
  /// test.
  SceneReport step(const std::vector<ObjectStep>& steps, const SceneOptions& options = {}) const;

  /// Reference for tests: every pair of objects, all triangle pairs, the same kernels.
  std::vector<InterObjectContact> inter_object_exhaustive(const std::vector<ObjectStep>& steps,
                                                          const SceneOptions& options = {}) const;

 private:
  struct Object {
    SelfCcd detector;
    SceneObjectOptions options;
  };
  std::vector<Object> objects_;
};

}  // namespace sscc
