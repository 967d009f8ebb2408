// SelfCcd and its reports.
#include "bindings.hpp"
#include "options.hpp"
#include "reports.hpp"
#include "sscc/query/self_ccd.hpp"

namespace sscc::python {

namespace {

static_assert(offsetof(TrianglePairContact, second) == offsetof(TrianglePairContact, first) + sizeof(int),
              "a pair's triangles are viewed as one row");
static_assert(offsetof(FeatureContact, second) == offsetof(FeatureContact, first) + sizeof(int),
              "a feature's indices are viewed as one row");

NodeBounds parse_bounds(const std::string& bounds) {
  if (bounds == "hybrid") return NodeBounds::kHybrid;
  if (bounds == "refit") return NodeBounds::kRefit;
  if (bounds == "subspace") return NodeBounds::kSubspace;
  throw py::value_error("bounds: expected 'hybrid', 'refit' or 'subspace', got '" + bounds + "'");
}

SelfCcdOptions query_options(const std::string& mode, const std::string& bounds, bool use_certificates,
                             bool use_normal_cones, bool use_displacement_bounds, double toi_tolerance,
                             double minimum_separation) {
  SelfCcdOptions options;
  options.mode = parse_mode(mode);
  options.bounds = parse_bounds(bounds);
  options.use_certificates = use_certificates;
  options.use_normal_cones = use_normal_cones;
  options.use_displacement_bounds = use_displacement_bounds;
  options.kernel = kernel_options(toi_tolerance, minimum_separation);
  return options;
}

py::dict stats_dict(const SelfCcdStats& s) {
  py::dict d;
  d["nodes_visited"] = s.nodes_visited;
  d["box_tests"] = s.box_tests;
  d["triangle_pairs"] = s.triangle_pairs;
  d["kernel_calls"] = s.kernel_calls;
  d["vertices_computed"] = s.vertices_computed;
  d["certified"] = s.certified;
  d["cone_culled"] = s.cone_culled;
  d["cone_radius_culled"] = s.cone_radius_culled;
  d["plane_culled"] = s.plane_culled;
  d["displacement_culled"] = s.displacement_culled;
  d["root_certified"] = s.root_certified;
  d["seconds"] = s.seconds;
  return d;
}

constexpr const char* kModeDoc =
    "mode: 'all' (every colliding pair and feature), 'earliest' (only the contacts at the earliest "
    "time of impact) or 'any' (stop at the first contact found). ";
constexpr const char* kKernelDoc =
    "toi_tolerance: the reported time of impact is within it below the true one. minimum_separation: "
    "d > 0 reports pairs coming within distance d (conservative; not with certificates). ";

}  // namespace

void bind_queries(py::module_& m) {
  bind_feature_arrays(m);

  py::class_<SelfCcdReport>(m, "SelfCcdReport",
                            "The result of a self-collision query. Arrays are read-only views into the report.")
      .def_property_readonly(
          "pairs",
          [](py::object self) {
            return index_columns(self.cast<const SelfCcdReport&>().pairs, &TrianglePairContact::first, 2, self);
          },
          "(k, 2) int32: the colliding non-adjacent triangle pairs, first < second, sorted.")
      .def_property_readonly(
          "toi", [](py::object self) { return toi_column(self.cast<const SelfCcdReport&>().pairs, self); },
          "(k,) float64: each pair's time of impact in [0, 1] (the earliest of its features).")
      .def_property_readonly(
          "features",
          [](py::object self) {
            return feature_arrays(self.cast<const SelfCcdReport&>().features, &FeatureContact::first, 2, self);
          },
          "The vertex-face and edge-edge feature contacts (sscc.Features), sorted by kind and indices.")
      .def_readonly("earliest_toi", &SelfCcdReport::earliest_toi,
                    "The earliest time of impact (1.0 when nothing collided).")
      .def_property_readonly("collided", &SelfCcdReport::collided, "Whether any pair collided.")
      .def_property_readonly(
          "stats", [](const SelfCcdReport& r) { return stats_dict(r.stats); },
          "The query's work as a dict: nodes_visited, box_tests, triangle_pairs, kernel_calls, "
          "vertices_computed, certified (nodes and sibling pairs culled by a certificate), "
          "root_certified (the whole step decided by the root's certificate) and seconds.")
      .def("__repr__", [](const SelfCcdReport& r) {
        return "<sscc.SelfCcdReport: " + std::to_string(r.pairs.size()) + " pairs, " +
               std::to_string(r.features.size()) + " features" +
               (r.collided() ? ", earliest toi " + std::to_string(r.earliest_toi) : std::string()) + ">";
      });

  py::class_<SelfCcd>(m, "SelfCcd",
                      "Continuous self-collision detection of a subspace model over straight-line steps "
                      "q0 -> q1, culled by certificates when given (otherwise by the step's displacements, mode by "
                      "mode). Nothing is missed for the positions as computed. Immutable; queries release the "
                      "GIL and may run from several threads.")
      .def(py::init([](std::shared_ptr<SubspaceBvh> bvh, std::shared_ptr<Certificates> certificates) {
             if (!bvh) throw py::value_error("SelfCcd: no hierarchy");
             py::gil_scoped_release release;
             return std::make_unique<SelfCcd>(std::move(bvh), std::move(certificates));
           }),
           py::arg("bvh"), py::arg("certificates") = py::none(), py::keep_alive<1, 2>(), py::keep_alive<1, 3>(),
           "A detector for the hierarchy, with or without certificates (shared, not copied: kept alive "
           "as long as the detector). Raises ValueError when the certificates belong to another model or "
           "hierarchy.")
      .def_property_readonly("bvh", &SelfCcd::bvh, py::return_value_policy::reference_internal, "The hierarchy.")
      .def_property_readonly("certificates", &SelfCcd::certificates, py::return_value_policy::reference_internal,
                             "The certificates, or None.")
      .def(
          "query",
          [](const SelfCcd& detector, py::object q0, py::object q1, const std::string& mode, const std::string& bounds,
             bool use_certificates, bool use_normal_cones, bool use_displacement_bounds, double toi_tolerance,
             double minimum_separation) {
            const Eigen::VectorXd a = vector_from(q0, "q0");
            const Eigen::VectorXd b = vector_from(q1, "q1");
            const SelfCcdOptions options = query_options(mode, bounds, use_certificates, use_normal_cones,
                                                         use_displacement_bounds, toi_tolerance, minimum_separation);
            py::gil_scoped_release release;
            return detector.query(a, b, options);
          },
          py::arg("q0"), py::arg("q1"), py::kw_only(), py::arg("mode") = "all", py::arg("bounds") = "hybrid",
          py::arg("use_certificates") = true, py::arg("use_normal_cones") = true,
          py::arg("use_displacement_bounds") = true, py::arg("toi_tolerance") = ccd::kDefaultToiTolerance,
          py::arg("minimum_separation") = 0.0,
          (std::string("The step q0 -> q1 (reduced coordinates, (r,) each). ") + kModeDoc +
           "bounds: node boxes 'hybrid' (default), 'refit' or 'subspace'. use_normal_cones: cull patches "
           "whose normals stay in a cone and whose contour stays simple. use_displacement_bounds: without "
           "certificates, cull by the step's displacements mode by mode. All three False give the "
           "traditional query. " +
           kKernelDoc + "Raises ValueError for q of the wrong size or not finite.")
              .c_str())
      .def(
          "prepare",
          [](const SelfCcd& detector, bool use_certificates, bool use_normal_cones, bool use_displacement_bounds) {
            SelfCcdOptions options;
            options.use_certificates = use_certificates;
            options.use_normal_cones = use_normal_cones;
            options.use_displacement_bounds = use_displacement_bounds;
            py::gil_scoped_release release;
            detector.prepare(options);
          },
          py::kw_only(), py::arg("use_certificates") = true, py::arg("use_normal_cones") = true,
          py::arg("use_displacement_bounds") = true,
          "Builds what queries with these culls precompute on their first use (the normal cones' radii and "
          "boundary chains, the displacement bounds' rest data: under a second on a 15k-triangle mesh), so "
          "that no query pays for it. Optional.")
      .def(
          "query_positions",
          [](const SelfCcd& detector, py::object x0, py::object x1, const std::string& mode, bool use_normal_cones,
             double toi_tolerance, double minimum_separation) {
            const std::vector<Eigen::Vector3d> a = points_from(x0, "x0");
            const std::vector<Eigen::Vector3d> b = points_from(x1, "x1");
            const SelfCcdOptions options =
                query_options(mode, "hybrid", false, use_normal_cones, false, toi_tolerance, minimum_separation);
            py::gil_scoped_release release;
            return detector.query_positions(a, b, options);
          },
          py::arg("x0"), py::arg("x1"), py::kw_only(), py::arg("mode") = "all", py::arg("use_normal_cones") = true,
          py::arg("toi_tolerance") = ccd::kDefaultToiTolerance, py::arg("minimum_separation") = 0.0,
          (std::string("The query on explicit vertex positions at both ends of the step ((n, 3) each; every "
                       "vertex moves linearly): for poses the subspace does not hold. use_normal_cones: as for "
                       "query (False: the traditional query). ") +
           kModeDoc + kKernelDoc)
              .c_str())
      .def(
          "query_discrete",
          [](const SelfCcd& detector, py::object q, bool use_certificates) {
            const Eigen::VectorXd coordinates = vector_from(q, "q");
            SelfCcdOptions options;
            options.use_certificates = use_certificates;
            py::gil_scoped_release release;
            return detector.query_discrete(coordinates, options);
          },
          py::arg("q"), py::kw_only(), py::arg("use_certificates") = true,
          "The non-adjacent triangle pairs that intersect in configuration q (exact), with toi 0 and no "
          "features.")
      .def(
          "query_exhaustive",
          [](const SelfCcd& detector, py::object q0, py::object q1, const std::string& mode, double toi_tolerance,
             double minimum_separation) {
            const Eigen::VectorXd a = vector_from(q0, "q0");
            const Eigen::VectorXd b = vector_from(q1, "q1");
            const SelfCcdOptions options =
                query_options(mode, "hybrid", false, false, false, toi_tolerance, minimum_separation);
            py::gil_scoped_release release;
            return detector.query_exhaustive(a, b, options);
          },
          py::arg("q0"), py::arg("q1"), py::kw_only(), py::arg("mode") = "all",
          py::arg("toi_tolerance") = ccd::kDefaultToiTolerance, py::arg("minimum_separation") = 0.0,
          "Reference: every non-adjacent triangle pair through the same kernels, O(n^2), no certificates.")
      .def("__repr__", [](const SelfCcd& detector) {
        return "<sscc.SelfCcd over " + std::to_string(detector.bvh().model().mesh().triangle_count()) + " triangles, " +
               (detector.certificates() ? "with" : "without") + " certificates>";
      });
}

}  // namespace sscc::python
