#include "reports.hpp"

#include <cstddef>
#include <string>

namespace sscc::python {

namespace {

static_assert(offsetof(TrianglePairContact, second) == offsetof(TrianglePairContact, first) + sizeof(int),
              "a pair's triangles are viewed as one row");
static_assert(offsetof(FeatureContact, second) == offsetof(FeatureContact, first) + sizeof(int),
              "a feature's indices are viewed as one row");

py::dict stats_dict(const SelfCcdStats& s) {
  py::dict d;
  d["nodes_visited"] = s.nodes_visited;
  d["box_tests"] = s.box_tests;
  d["triangle_pairs"] = s.triangle_pairs;
  d["kernel_calls"] = s.kernel_calls;
  d["vertices_computed"] = s.vertices_computed;
  d["vertex_starts_reused"] = s.vertex_starts_reused;
  d["certified"] = s.certified;
  d["cone_culled"] = s.cone_culled;
  d["cone_radius_culled"] = s.cone_radius_culled;
  d["pair_certified"] = s.pair_certified;
  d["plane_culled"] = s.plane_culled;
  d["displacement_culled"] = s.displacement_culled;
  d["moved_box_culled"] = s.moved_box_culled;
  d["root_certified"] = s.root_certified;
  d["seconds"] = s.seconds;
  return d;
}

}  // namespace

void bind_feature_arrays(py::module_& m) {
  m.attr("VERTEX_FACE") = static_cast<int>(FeatureKind::kVertexFace);
  m.attr("EDGE_EDGE") = static_cast<int>(FeatureKind::kEdgeEdge);
  py::class_<FeatureArrays>(m, "Features",
                            "Feature contacts, one row per contact: kind (uint8, VERTEX_FACE or EDGE_EDGE), "
                            "indices (int32: vertex and triangle for vertex-face, two edges for edge-edge; "
                            "in a scene, preceded by their objects) and toi (float64). Unpacks as "
                            "kind, indices, toi = features. Read-only views into the report.")
      .def_readonly("kind", &FeatureArrays::kind, "(k,) uint8: VERTEX_FACE or EDGE_EDGE.")
      .def_readonly("indices", &FeatureArrays::indices, "(k, 2) int32, or (k, 4) in a scene.")
      .def_readonly("toi", &FeatureArrays::toi, "(k,) float64 time of impact in [0, 1].")
      .def("__len__", [](const FeatureArrays& f) { return f.toi.shape(0); })
      .def("__iter__", [](const FeatureArrays& f) { return py::iter(py::make_tuple(f.kind, f.indices, f.toi)); })
      .def("__repr__",
           [](const FeatureArrays& f) { return "<sscc.Features: " + std::to_string(f.toi.shape(0)) + " contacts>"; });
}

void bind_contact_geometry(py::module_& m) {
  py::class_<ContactGeometry>(
      m, "ContactGeometry",
      "Where and along which normal each feature contact of a report touches, one row per feature "
      "(in the order of the report's features), computed with the report from the positions of the "
      "feature's four vertices at both ends of the step, in the frame the query's motion is linear in "
      "(the model's for SelfCcd, the given positions for PositionCcd; in a scene, the object's frame for "
      "self contacts, or the world for world_linear objects, and the world between objects). Read-only "
      "views into the report.")
      .def_property_readonly(
          "vertices", [](py::object self) { return rows_view(self.cast<const ContactGeometry&>().vertices, self); },
          "(k, 4) int32: the feature's vertices: vertex-face (the vertex, then the triangle's three), "
          "edge-edge (the first edge's two, then the second's). In a scene, the first one or two belong "
          "to the first object of the feature's row, the others to the second.")
      .def_property_readonly(
          "barycentric",
          [](py::object self) { return rows_view(self.cast<const ContactGeometry&>().barycentric, self); },
          "(k, 4) float64: the contact points as weights of the four vertices at the time of impact: "
          "vertex-face (1, -b0, -b1, -b2) with b the point's barycentric coordinates on the triangle; "
          "edge-edge (1 - s, s, -(1 - u), -u) with s and u the parameters along the two edges. Each side's "
          "weights sum to +1 and -1, so sum_i w_i x_i(toi) is the (zero) gap vector.")
      .def_property_readonly(
          "points", [](py::object self) { return rows_view(self.cast<const ContactGeometry&>().points, self); },
          "(k, 3) float64: the contact point at the time of impact (the first side's: the vertex, or the "
          "point on the first edge).")
      .def_property_readonly(
          "normals", [](py::object self) { return rows_view(self.cast<const ContactGeometry&>().normals, self); },
          "(k, 3) float64: the unit contact normal at the time of impact (the triangle's, or the two "
          "edges' cross product), pointing from the second side towards where the first side started.")
      .def("__len__", [](const ContactGeometry& g) { return g.vertices.size(); })
      .def("__repr__", [](const ContactGeometry& g) {
        return "<sscc.ContactGeometry: " + std::to_string(g.vertices.size()) + " contacts>";
      });
}

void bind_self_report(py::module_& m) {
  py::class_<SelfReport>(m, "SelfCcdReport",
                         "The result of a self-collision query. Arrays are read-only views into the report.")
      .def_property_readonly(
          "pairs",
          [](py::object self) {
            return index_columns(self.cast<const SelfReport&>().pairs, &TrianglePairContact::first, 2, self);
          },
          "(k, 2) int32: the colliding non-adjacent triangle pairs, first < second, sorted.")
      .def_property_readonly(
          "toi", [](py::object self) { return toi_column(self.cast<const SelfReport&>().pairs, self); },
          "(k,) float64: each pair's time of impact in [0, 1] (the earliest of its features).")
      .def_property_readonly(
          "features",
          [](py::object self) {
            return feature_arrays(self.cast<const SelfReport&>().features, &FeatureContact::first, 2, self);
          },
          "The vertex-face and edge-edge feature contacts (sscc.Features), sorted by kind and indices.")
      .def_readonly("geometry", &SelfReport::geometry, py::return_value_policy::reference_internal,
                    "The features' contact points and normals (sscc.ContactGeometry), one row per feature.")
      .def_readonly("earliest_toi", &SelfReport::earliest_toi,
                    "The earliest time of impact (1.0 when nothing collided).")
      .def_property_readonly("collided", &SelfReport::collided, "Whether any pair collided.")
      .def_property_readonly(
          "stats", [](const SelfReport& r) { return stats_dict(r.stats); },
          "The query's work as a dict: nodes_visited, box_tests, triangle_pairs, kernel_calls, "
          "vertices_computed, vertex_starts_reused (of those, the ones whose start was the previous "
          "step's end), moved_box_culled (node pairs found apart with a node's box moved from the "
          "previous step's, its vertices spared), certified (nodes and sibling pairs culled by a certificate), "
          "root_certified (the whole step decided by the root's certificate) and seconds.")
      .def("__repr__", [](const SelfReport& r) {
        return "<sscc.SelfCcdReport: " + std::to_string(r.pairs.size()) + " pairs, " +
               std::to_string(r.features.size()) + " features" +
               (r.collided() ? ", earliest toi " + std::to_string(r.earliest_toi) : std::string()) + ">";
      });
}

}  // namespace sscc::python
