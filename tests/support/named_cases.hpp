// Named degenerate CCD queries with answers derived by hand (full-precision literals).
// expected_toi is the exact first contact time as a rational "p/q" ("" for no contact).
#pragma once

#include <string>
#include <vector>

#include "query.hpp"

namespace sscc::test {

struct NamedCase {
  std::string name;
  validation::Query query;
  std::string expected_toi;  // "" when the primitives never touch
};

inline std::vector<NamedCase> named_cases() {
  using validation::Kind;
  using V = Eigen::Vector3d;
  const V a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);  // the unit right triangle in z = 0
  const double tiny = 0x1p-60;
  const double just_past_one = 0x1.0000000000001p+0;
  return {
      {"vf-through-interior", {Kind::kVertexFace, {V(0.25, 0.25, 1), a, b, c, V(0.25, 0.25, -1), a, b, c}}, "1/2"},
      {"vf-grazes-edge", {Kind::kVertexFace, {V(0.5, 0, 1), a, b, c, V(0.5, 0, -1), a, b, c}}, "1/2"},
      {"vf-grazes-vertex", {Kind::kVertexFace, {V(0, 0, 1), a, b, c, V(0, 0, -1), a, b, c}}, "1/2"},
      {"vf-misses-edge-by-2^-60", {Kind::kVertexFace, {V(0.5, -tiny, 1), a, b, c, V(0.5, -tiny, -1), a, b, c}}, ""},
      {"vf-coplanar-motion-enters", {Kind::kVertexFace, {V(2, 0.25, 0), a, b, c, V(-1, 0.25, 0), a, b, c}}, "5/12"},
      {"vf-coplanar-motion-misses", {Kind::kVertexFace, {V(2, 2, 0), a, b, c, V(3, -1, 0), a, b, c}}, ""},
      {"vf-static-inside", {Kind::kVertexFace, {V(0.25, 0.25, 0), a, b, c, V(0.25, 0.25, 0), a, b, c}}, "0"},
      {"vf-static-just-above", {Kind::kVertexFace, {V(0.25, 0.25, tiny), a, b, c, V(0.25, 0.25, tiny), a, b, c}}, ""},
      {"vf-zero-area-triangle-crossed",
       {Kind::kVertexFace, {V(0.5, -1, 1), a, b, V(2, 0, 0), V(0.5, 1, -1), a, b, V(2, 0, 0)}},
       "1/2"},
      {"vf-contact-at-t1", {Kind::kVertexFace, {V(0.25, 0.25, 1), a, b, c, V(0.25, 0.25, 0), a, b, c}}, "1"},
      {"vf-contact-at-t0-leaving", {Kind::kVertexFace, {V(0.25, 0.25, 0), a, b, c, V(0.25, 0.25, 1), a, b, c}}, "0"},
      {"vf-double-root-inside",
       {Kind::kVertexFace, {V(0.1, 0.25, -0.5), a, b, V(0, 1, -1), V(0.1, 0.75, 0.5), a, b, V(0, 1, 1)}},
       "1/2"},
      {"vf-double-root-outside",
       {Kind::kVertexFace, {V(0.6, 0.25, -0.5), a, b, V(0, 1, -1), V(0.6, 0.75, 0.5), a, b, V(0, 1, 1)}},
       ""},
      {"vf-static-coplanar-outside", {Kind::kVertexFace, {V(1, 1, 0), a, b, c, V(1, 1, 0), a, b, c}}, ""},
      {"vf-shrinking-triangle", {Kind::kVertexFace, {V(0.5, 0.5, 0), a, b, c, V(0.5, 0.5, 0), a, a, a}}, "0"},
      {"ee-crossing",
       {Kind::kEdgeEdge,
        {V(-1, 0, 0), V(1, 0, 0), V(0, -1, 1), V(0, 1, 1), V(-1, 0, 0), V(1, 0, 0), V(0, -1, -1), V(0, 1, -1)}},
       "1/2"},
      {"ee-collinear-sliding",
       {Kind::kEdgeEdge, {a, b, V(2, 0, 0), V(3, 0, 0), a, b, V(0.5, 0, 0), V(1.5, 0, 0)}},
       "2/3"},
      {"ee-parallel-apart", {Kind::kEdgeEdge, {a, b, V(0, 1, 0), V(1, 1, 0), a, b, V(5, 1, 0), V(6, 1, 0)}}, ""},
      {"ee-endpoints-touch", {Kind::kEdgeEdge, {a, b, V(1, 0, 1), V(1, 1, 1), a, b, V(1, 0, -1), V(1, 1, -1)}}, "1/2"},
      {"ee-endpoints-miss-by-ulp",
       {Kind::kEdgeEdge,
        {a, b, V(just_past_one, 0, 1), V(just_past_one, 1, 1), a, b, V(just_past_one, 0, -1), V(just_past_one, 1, -1)}},
       ""},
      {"ee-zero-length-edge",
       {Kind::kEdgeEdge, {V(0.5, 0, 1), V(0.5, 0, 1), a, b, V(0.5, 0, -1), V(0.5, 0, -1), a, b}},
       "1/2"},
      {"ee-two-points-meet", {Kind::kEdgeEdge, {a, a, b, b, V(1, 1, 1), V(1, 1, 1), V(0, 1, 1), V(0, 1, 1)}}, "1/2"},
      {"ee-coplanar-motion",
       {Kind::kEdgeEdge, {a, b, V(0.5, 2, 0), V(0.5, 3, 0), a, b, V(0.5, -1, 0), V(0.5, 0, 0)}},
       "2/3"},
  };
}

}  // namespace sscc::test
