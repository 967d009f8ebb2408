// What the self and inter-object queries do with feature contacts, in one place: running a
// kernel and recording its hit (the first hit ends an any-hit query), and turning feature
// hits into the triangle pairs that contain them. Private to the library.
#pragma once

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

#include "sscc/ccd/ccd_types.hpp"
#include "sscc/mesh/triangle_mesh.hpp"
#include "sscc/query/self_ccd.hpp"

namespace sscc::detail {

/// The feature hits of one query (or one task of it) and whether it has stopped (any-hit
/// mode stops at the first hit). Feature is FeatureContact or InterObjectFeature: a
/// struct with a `toi` member.
template <typename Feature>
class FeatureHits {
 public:
  /// Kernel calls are counted in *kernel_calls (the caller's statistics).
  FeatureHits(SelfCcdMode mode, long* kernel_calls)
      : stop_at_first_(mode == SelfCcdMode::kAnyHit), kernel_calls_(kernel_calls) {}

  /// Counts the kernel call; records `feature` at the kernel's time of impact if it hit.
  void record(const ccd::CcdResult& result, Feature feature) {
    ++*kernel_calls_;
    if (!result.hit) return;
    feature.toi = result.toi;
    hits_.push_back(feature);
    if (stop_at_first_) stopped_ = true;
  }
  bool stopped() const { return stopped_; }
  const std::vector<Feature>& hits() const { return hits_; }
  std::vector<Feature>& hits() { return hits_; }
  /// Hands the hits over and starts afresh (not stopped): one task of a parallel query.
  std::vector<Feature> take() {
    stopped_ = false;
    return std::exchange(hits_, {});
  }
  /// The hits of a whole query, merged from its tasks.
  void replace(std::vector<Feature> hits) { hits_ = std::move(hits); }

 private:
  bool stop_at_first_;
  bool stopped_ = false;
  long* kernel_calls_;
  std::vector<Feature> hits_;
};

/// Calls add(t, u) for every triangle t containing feature `first` of `first_mesh` and u
/// containing feature `second` of `second_mesh`: a vertex and the face itself
/// (vertex-face), or two edges (edge-edge).
template <typename Add>
void for_each_triangle_pair_of(FeatureKind kind, const TriangleMesh& first_mesh, int first,
                               const TriangleMesh& second_mesh, int second, Add add) {
  if (kind == FeatureKind::kVertexFace) {
    for (const int* t = first_mesh.triangles_of_vertex_begin(first); t != first_mesh.triangles_of_vertex_end(first);
         ++t) {
      add(*t, second);
    }
    return;
  }
  for (const int* t = first_mesh.triangles_of_edge_begin(first); t != first_mesh.triangles_of_edge_end(first); ++t) {
    for (const int* u = second_mesh.triangles_of_edge_begin(second); u != second_mesh.triangles_of_edge_end(second);
         ++u) {
      add(*t, *u);
    }
  }
}

/// The earliest time per key: collects (key, toi) and keeps the minimum per key, in key order.
template <typename Key>
class EarliestPerKey {
 public:
  void add(const Key& key, double toi) {
    const auto [it, inserted] = earliest_.emplace(key, toi);
    if (!inserted) it->second = std::min(it->second, toi);
  }
  const std::map<Key, double>& earliest() const { return earliest_; }

 private:
  std::map<Key, double> earliest_;
};

}  // namespace sscc::detail
