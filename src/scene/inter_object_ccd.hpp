// Continuous collision between two scene objects over one step: a swept-box traversal of
// the two hierarchies in world space (boxes at both ends, interpolated: sweep.hpp), then
// the exact kernels on the features of triangle pairs whose sweeps meet. Every triangle
// pair of two objects is non-adjacent; each feature pair is tested once, in its owner: the
// pair of the first triangles (in mesh order) around its two features. Private to the
// library.
#pragma once

#include <vector>

#include "query/feature_hits.hpp"
#include "scene/object_motion.hpp"

namespace sscc::detail {

class InterObjectCcd {
 public:
  InterObjectCcd(ObjectMotion& a, int object_a, ObjectMotion& b, int object_b, const SceneOptions& options);

  /// Whether the objects' root sweeps meet (the one box test that culls most pairs).
  bool roots_meet();
  /// The traversal from the roots.
  void run();
  /// Every triangle pair, no hierarchy (the reference).
  void run_exhaustive();

  bool stopped() const { return hits_.stopped(); }
  const std::vector<InterObjectFeature>& features() const { return hits_.hits(); }
  /// The colliding triangle pairs: every pair containing a feature that hit, at the
  /// earliest of its features' times (unsorted).
  std::vector<InterObjectContact> contacts() const;
  long box_tests() const { return box_tests_; }
  long triangle_pairs() const { return triangle_pairs_; }
  long kernel_calls() const { return kernel_calls_; }

 private:
  /// Every cull is widened by the kernels' minimum separation.
  double separation() const { return options_.kernel.minimum_separation; }
  void traverse(int node_a, int node_b);
  void test_triangle_pair(int i, int j);
  void vertex_face(ObjectMotion& vertex_side, int object_v, int v, ObjectMotion& face_side, int object_f, int f);
  void edge_edge(int e, int g);

  ObjectMotion& a_;
  ObjectMotion& b_;
  int object_a_, object_b_;
  const SceneOptions& options_;
  long box_tests_ = 0, triangle_pairs_ = 0, kernel_calls_ = 0;
  FeatureHits<InterObjectFeature> hits_;
};

}  // namespace sscc::detail
