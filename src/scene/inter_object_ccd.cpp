#include "scene/inter_object_ccd.hpp"

#include <algorithm>
#include <array>
#include <tuple>

#include "query/descent.hpp"
#include "sscc/ccd/kernels.hpp"

namespace sscc::detail {

namespace {

/// Whether triangle t is the first (in mesh order) around vertex v.
bool first_around_vertex(const TriangleMesh& mesh, int v, int t) { return *mesh.triangles_of_vertex_begin(v) == t; }
bool first_around_edge(const TriangleMesh& mesh, int e, int t) { return *mesh.triangles_of_edge_begin(e) == t; }

Aabb point_box(ObjectMotion& m, int v) { return {m.start(v).cwiseMin(m.end(v)), m.start(v).cwiseMax(m.end(v))}; }
Aabb edge_box(ObjectMotion& m, int e) {
  const Edge& ends = m.mesh().edges()[e];
  return hull(point_box(m, ends[0]), point_box(m, ends[1]));
}
Aabb swept_box(const Sweep& s) { return hull(s.start, s.end); }

}  // namespace

InterObjectCcd::InterObjectCcd(ObjectMotion& a, int object_a, ObjectMotion& b, int object_b,
                               const SceneOptions& options)
    : a_(a), b_(b), object_a_(object_a), object_b_(object_b), options_(options), hits_(options.mode, &kernel_calls_) {}

bool InterObjectCcd::roots_meet() {
  ++box_tests_;
  return sweeps_may_touch(a_.node_sweep(0), b_.node_sweep(0), separation());
}

void InterObjectCcd::run() { traverse(0, 0); }

void InterObjectCcd::run_exhaustive() {
  const int na = a_.mesh().triangle_count();
  const int nb = b_.mesh().triangle_count();
  for (int i = 0; i < na && !stopped(); ++i) {
    for (int j = 0; j < nb && !stopped(); ++j) test_triangle_pair(i, j);
  }
}

void InterObjectCcd::traverse(int node_a, int node_b) {
  if (stopped()) return;
  ++box_tests_;
  if (!sweeps_may_touch(a_.node_sweep(node_a), b_.node_sweep(node_b), separation())) return;
  const SubspaceBvh::Node& na = a_.bvh().nodes()[node_a];
  const SubspaceBvh::Node& nb = b_.bvh().nodes()[node_b];
  if (na.is_leaf() && nb.is_leaf()) {
    for_each_pruned_leaf_pair(
        na, nb, [&](int i) { return sweeps_may_touch(a_.triangle_sweep(i), b_.node_sweep(node_b), separation()); },
        [&](int j) { return sweeps_may_touch(b_.triangle_sweep(j), a_.node_sweep(node_a), separation()); },
        [&](int i, int j) { test_triangle_pair(i, j); });
    return;
  }
  descend_larger(a_.bvh(), node_a, b_.bvh(), node_b, [&](int x, int y) { traverse(x, y); });
}

void InterObjectCcd::test_triangle_pair(int i, int j) {
  if (stopped()) return;
  const Sweep& sweep_a = a_.triangle_sweep(i);
  const Sweep& sweep_b = b_.triangle_sweep(j);
  if (!sweeps_may_touch(sweep_a, sweep_b, separation())) return;
  ++triangle_pairs_;
  const int ta = a_.bvh().triangle_order()[i];
  const int tb = b_.bvh().triangle_order()[j];
  const TriangleMesh& mesh_a = a_.mesh();
  const TriangleMesh& mesh_b = b_.mesh();
  const Aabb box_a = swept_box(sweep_a);
  const Aabb box_b = swept_box(sweep_b);
  for (int k = 0; k < 3; ++k) {
    const int v = mesh_a.triangles()[ta][k];
    if (first_around_vertex(mesh_a, v, ta) && overlap(point_box(a_, v), box_b, separation()))
      vertex_face(a_, object_a_, v, b_, object_b_, tb);
    const int w = mesh_b.triangles()[tb][k];
    if (first_around_vertex(mesh_b, w, tb) && overlap(point_box(b_, w), box_a, separation()))
      vertex_face(b_, object_b_, w, a_, object_a_, ta);
  }
  for (int k = 0; k < 3; ++k) {
    const int e = mesh_a.triangle_edges(ta)[k];
    if (!first_around_edge(mesh_a, e, ta)) continue;
    const Aabb box_e = edge_box(a_, e);
    if (!overlap(box_e, box_b, separation())) continue;
    for (int l = 0; l < 3; ++l) {
      const int g = mesh_b.triangle_edges(tb)[l];
      if (first_around_edge(mesh_b, g, tb) && overlap(box_e, edge_box(b_, g), separation())) edge_edge(e, g);
    }
  }
}

void InterObjectCcd::vertex_face(ObjectMotion& vertex_side, int object_v, int v, ObjectMotion& face_side, int object_f,
                                 int f) {
  if (stopped()) return;
  const Triangle& t = face_side.mesh().triangles()[f];
  hits_.record(ccd::vertex_face_ccd(vertex_side.start(v), face_side.start(t[0]), face_side.start(t[1]),
                                    face_side.start(t[2]), vertex_side.end(v), face_side.end(t[0]), face_side.end(t[1]),
                                    face_side.end(t[2]), options_.kernel),
               {FeatureKind::kVertexFace, object_v, v, object_f, f, 1.0});
}

void InterObjectCcd::edge_edge(int e, int g) {
  if (stopped()) return;
  const Edge& p = a_.mesh().edges()[e];
  const Edge& q = b_.mesh().edges()[g];
  hits_.record(ccd::edge_edge_ccd(a_.start(p[0]), a_.start(p[1]), b_.start(q[0]), b_.start(q[1]), a_.end(p[0]),
                                  a_.end(p[1]), b_.end(q[0]), b_.end(q[1]), options_.kernel),
               {FeatureKind::kEdgeEdge, object_a_, e, object_b_, g, 1.0});
}

std::vector<InterObjectContact> InterObjectCcd::contacts() const {
  EarliestPerKey<std::tuple<int, int, int, int>> earliest;
  const auto mesh_of = [&](int object) -> const TriangleMesh& { return object == object_a_ ? a_.mesh() : b_.mesh(); };
  for (const InterObjectFeature& c : hits_.hits()) {
    for_each_triangle_pair_of(
        c.kind, mesh_of(c.object_first), c.first, mesh_of(c.object_second), c.second, [&](int t, int u) {
          earliest.add(c.object_first < c.object_second ? std::make_tuple(c.object_first, t, c.object_second, u)
                                                        : std::make_tuple(c.object_second, u, c.object_first, t),
                       c.toi);
        });
  }
  std::vector<InterObjectContact> result;
  for (const auto& [key, toi] : earliest.earliest()) {
    result.push_back({std::get<0>(key), std::get<1>(key), std::get<2>(key), std::get<3>(key), toi});
  }
  return result;
}

}  // namespace sscc::detail
