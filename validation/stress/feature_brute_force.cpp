#include "feature_brute_force.hpp"

#include <algorithm>
#include <map>
#include <sstream>
#include <string>
#include <tuple>

#include "sscc/ccd/kernels.hpp"

namespace sscc::validation {

namespace {

bool share_a_vertex(const Triangle& a, const Triangle& b) {
  for (int u : a) {
    if (std::find(b.begin(), b.end(), u) != b.end()) return true;
  }
  return false;
}

using FeatureKey = std::tuple<FeatureKind, int, int>;

/// Keeps the earliest time seen for each key (a feature met in several triangle pairs gets
/// the same kernel call, hence the same time, each time).
template <typename Key>
void keep_earliest(std::map<Key, double>& earliest, const Key& key, double toi) {
  const auto [it, inserted] = earliest.emplace(key, toi);
  if (!inserted) it->second = std::min(it->second, toi);
}

std::string describe(const FeatureContact& c) {
  std::ostringstream s;
  s.precision(17);
  s << (c.kind == FeatureKind::kVertexFace ? "vertex-face (" : "edge-edge (") << c.first << ", " << c.second << ") at "
    << c.toi;
  return s.str();
}

std::string describe(const TrianglePairContact& c) {
  std::ostringstream s;
  s.precision(17);
  s << "pair (" << c.first << ", " << c.second << ") at " << c.toi;
  return s.str();
}

template <typename Contact>
std::string first_difference(const std::vector<Contact>& expected, const std::vector<Contact>& actual,
                             const char* what) {
  const std::size_t common = std::min(expected.size(), actual.size());
  for (std::size_t i = 0; i < common; ++i) {
    if (!(expected[i] == actual[i])) {
      return std::string(what) + " " + std::to_string(i) + ": expected " + describe(expected[i]) + ", got " +
             describe(actual[i]);
    }
  }
  if (expected.size() == actual.size()) return "";
  std::string message =
      std::string(what) + ": expected " + std::to_string(expected.size()) + ", got " + std::to_string(actual.size());
  if (expected.size() > common) message += " (first missing: " + describe(expected[common]) + ")";
  if (actual.size() > common) message += " (first extra: " + describe(actual[common]) + ")";
  return message;
}

}  // namespace

SelfCcdReport feature_brute_force(const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& x0,
                                  const std::vector<Eigen::Vector3d>& x1, const ccd::CcdOptions& kernel) {
  std::map<FeatureKey, double> features;
  std::map<std::pair<int, int>, double> pairs;
  long kernel_calls = 0;
  const std::vector<Triangle>& triangles = mesh.triangles();
  const int count = mesh.triangle_count();
  for (int a = 0; a < count; ++a) {
    for (int b = a + 1; b < count; ++b) {
      if (share_a_vertex(triangles[a], triangles[b])) continue;
      double earliest = 2.0;
      const auto record = [&](const ccd::CcdResult& result, FeatureKey key) {
        ++kernel_calls;
        if (!result.hit) return;
        keep_earliest(features, key, result.toi);
        earliest = std::min(earliest, result.toi);
      };
      for (int side = 0; side < 2; ++side) {
        const int face = side == 0 ? b : a;
        const Triangle& f = triangles[face];
        for (int v : triangles[side == 0 ? a : b]) {
          record(ccd::vertex_face_ccd(x0[v], x0[f[0]], x0[f[1]], x0[f[2]], x1[v], x1[f[0]], x1[f[1]], x1[f[2]], kernel),
                 {FeatureKind::kVertexFace, v, face});
        }
      }
      for (int e : mesh.triangle_edges(a)) {
        for (int g : mesh.triangle_edges(b)) {
          // An edge feature is named by its index, the smaller first, each edge's vertices in
          // increasing order: the orientation every query of the library uses.
          const Edge& p = mesh.edges()[std::min(e, g)];
          const Edge& s = mesh.edges()[std::max(e, g)];
          record(ccd::edge_edge_ccd(x0[p[0]], x0[p[1]], x0[s[0]], x0[s[1]], x1[p[0]], x1[p[1]], x1[s[0]], x1[s[1]],
                                    kernel),
                 {FeatureKind::kEdgeEdge, std::min(e, g), std::max(e, g)});
        }
      }
      if (earliest <= 1.0) pairs.emplace(std::make_pair(a, b), earliest);
    }
  }
  SelfCcdReport report;
  for (const auto& [key, toi] : features)
    report.features.push_back({std::get<0>(key), std::get<1>(key), std::get<2>(key), toi});
  for (const auto& [key, toi] : pairs) {
    report.pairs.push_back({key.first, key.second, toi});
    report.earliest_toi = std::min(report.earliest_toi, toi);
  }
  report.stats.kernel_calls = kernel_calls;
  return report;
}

std::string report_difference(const SelfCcdReport& expected, const SelfCcdReport& actual) {
  std::string difference = first_difference(expected.pairs, actual.pairs, "pairs");
  if (difference.empty()) difference = first_difference(expected.features, actual.features, "features");
  if (difference.empty() && expected.collided() && expected.earliest_toi != actual.earliest_toi) {
    std::ostringstream s;
    s.precision(17);
    s << "earliest time: expected " << expected.earliest_toi << ", got " << actual.earliest_toi;
    difference = s.str();
  }
  return difference;
}

}  // namespace sscc::validation
