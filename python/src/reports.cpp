#include "reports.hpp"

namespace sscc::python {

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

}  // namespace sscc::python
