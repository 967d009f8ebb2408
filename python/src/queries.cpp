// SelfCcd, PositionCcd and their reports.
#include <memory>
#include <utility>

#include "bindings.hpp"
#include "options.hpp"
#include "reports.hpp"
#include "sscc/query/position_ccd.hpp"
#include "sscc/query/self_ccd.hpp"

namespace sscc::python {

namespace {

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

constexpr const char* kModeDoc =
    "mode: 'all' (every colliding pair and feature), 'earliest' (only the contacts at the earliest "
    "time of impact) or 'any' (stop at the first contact found). ";
constexpr const char* kKernelDoc =
    "toi_tolerance: the reported time of impact is within it below the true one. minimum_separation: "
    "d > 0 reports pairs coming within distance d (conservative; not with certificates). ";
constexpr const char* kGeometryDoc =
    "The report's geometry holds each feature's contact points and normal, computed from the feature's "
    "vertices at both ends of the step. ";

/// A subspace query's report with its geometry, the positions x = p + U q at q0 and q1
/// computed as the query computes them.
SelfReport with_geometry(SelfCcdReport report, const SubspaceModel& model, const Eigen::VectorXd& q0,
                         const Eigen::VectorXd& q1) {
  SelfReport result;
  static_cast<SelfCcdReport&>(result) = std::move(report);
  if (result.features.empty()) return result;
  const Eigen::VectorXd q_hat[2] = {model.scaled_coordinates(q0), model.scaled_coordinates(q1)};
  result.geometry = self_contact_geometry(model.mesh(), result.features,
                                          [&](int v, int end) { return model.position(v, q_hat[end]); });
  return result;
}

/// A positions query's report with its geometry.
SelfReport with_geometry(SelfCcdReport report, const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& x0,
                         const std::vector<Eigen::Vector3d>& x1) {
  SelfReport result;
  static_cast<SelfCcdReport&>(result) = std::move(report);
  result.geometry = self_contact_geometry(mesh, result.features, [&](int v, int end) { return end ? x1[v] : x0[v]; });
  return result;
}

}  // namespace

void bind_queries(py::module_& m) {
  bind_feature_arrays(m);

  bind_contact_geometry(m);
  bind_self_report(m);

  py::class_<SelfCcd>(m, "SelfCcd",
                      "Continuous self-collision detection of a subspace model over straight-line steps "
                      "q0 -> q1, culled by certificates when given (otherwise by the step's displacements, mode by "
                      "mode). Nothing is missed for the positions as computed. Immutable; queries release the "
                      "GIL and may run from several threads.")
      .def(py::init([](std::shared_ptr<SubspaceBvh> bvh, std::shared_ptr<Certificates> certificates) {
             if (!bvh) throw py::value_error("SelfCcd: bvh is None");
             py::gil_scoped_release release;
             return std::make_unique<SelfCcd>(std::move(bvh), std::move(certificates));
           }),
           py::arg("bvh"), py::arg("certificates") = py::none(),
           "A detector for the hierarchy, with or without certificates, which it shares (no copy): they "
           "live as long as the detector or any other holder. Raises ValueError when the certificates "
           "belong to another model or hierarchy.")
      .def_property_readonly("bvh", &SelfCcd::bvh, py::return_value_policy::reference_internal,
                             "The hierarchy (the one the detector was built with, not a copy).")
      .def_property_readonly("certificates", &SelfCcd::certificates, py::return_value_policy::reference_internal,
                             "The certificates (the ones the detector was built with), or None.")
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
            return with_geometry(detector.query(a, b, options), detector.bvh().model(), a, b);
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
           kKernelDoc + kGeometryDoc + "Raises ValueError for q of the wrong size or not finite.")
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
            return with_geometry(detector.query_positions(a, b, options), detector.bvh().model().mesh(), a, b);
          },
          py::arg("x0"), py::arg("x1"), py::kw_only(), py::arg("mode") = "all", py::arg("use_normal_cones") = true,
          py::arg("toi_tolerance") = ccd::kDefaultToiTolerance, py::arg("minimum_separation") = 0.0,
          (std::string("The query on explicit vertex positions at both ends of the step ((n, 3) each; every "
                       "vertex moves linearly): for poses the subspace does not hold. use_normal_cones: as for "
                       "query (False: the traditional query). ") +
           kModeDoc + kKernelDoc + kGeometryDoc)
              .c_str())
      .def(
          "query_discrete",
          [](const SelfCcd& detector, py::object q, bool use_certificates) {
            const Eigen::VectorXd coordinates = vector_from(q, "q");
            SelfCcdOptions options;
            options.use_certificates = use_certificates;
            py::gil_scoped_release release;
            return with_geometry(detector.query_discrete(coordinates, options), detector.bvh().model(), coordinates,
                                 coordinates);
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
            return with_geometry(detector.query_exhaustive(a, b, options), detector.bvh().model(), a, b);
          },
          py::arg("q0"), py::arg("q1"), py::kw_only(), py::arg("mode") = "all",
          py::arg("toi_tolerance") = ccd::kDefaultToiTolerance, py::arg("minimum_separation") = 0.0,
          "Reference: every non-adjacent triangle pair through the same kernels, O(n^2), no certificates.")
      .def("__repr__", [](const SelfCcd& detector) {
        return "<sscc.SelfCcd over " + std::to_string(detector.bvh().model().mesh().triangle_count()) + " triangles, " +
               (detector.certificates() ? "with" : "without") + " certificates>";
      });

  py::class_<PositionCcd>(m, "PositionCcd",
                          "Continuous self-collision detection for simulators without a subspace (cloth, full-space "
                          "finite elements): built from the mesh alone, no basis, no certificates; each query takes "
                          "the vertex positions at both ends of the step and runs the traversal, culls and kernels "
                          "of SelfCcd.query_positions, so its report is the same. Exact for the given positions. "
                          "Immutable; queries release the GIL and may run from several threads.")
      .def(py::init([](const TriangleMesh& mesh, const ExcludedPairs* excluded) {
             py::gil_scoped_release release;
             return std::make_unique<PositionCcd>(mesh, excluded ? *excluded : ExcludedPairs());
           }),
           py::arg("mesh"), py::arg("excluded") = py::none(),
           "Builds the hierarchy over the mesh's rest positions (the detector keeps its own copy of the "
           "mesh). excluded: None or an ExcludedPairs of the mesh (for instance "
           "ExcludedPairs.touching_at_rest(mesh)), ignored like adjacent pairs. Raises ValueError when the "
           "set was made for a mesh of another triangle count.")
      .def_property_readonly("mesh", &PositionCcd::mesh, py::return_value_policy::reference_internal,
                             "The mesh (the detector's copy).")
      .def_property_readonly("excluded_pairs", &PositionCcd::excluded_pairs,
                             py::return_value_policy::reference_internal, "The excluded pairs (ExcludedPairs).")
      .def(
          "query",
          [](const PositionCcd& ccd, py::object x0, py::object x1, const std::string& mode, bool use_normal_cones,
             double toi_tolerance, double minimum_separation) {
            const std::vector<Eigen::Vector3d> a = points_from(x0, "x0");
            const std::vector<Eigen::Vector3d> b = points_from(x1, "x1");
            const SelfCcdOptions options =
                query_options(mode, "hybrid", false, use_normal_cones, false, toi_tolerance, minimum_separation);
            py::gil_scoped_release release;
            return with_geometry(ccd.query(a, b, options), ccd.mesh(), a, b);
          },
          py::arg("x0"), py::arg("x1"), py::kw_only(), py::arg("mode") = "all", py::arg("use_normal_cones") = true,
          py::arg("toi_tolerance") = ccd::kDefaultToiTolerance, py::arg("minimum_separation") = 0.0,
          (std::string("The step from positions x0 to x1 ((n, 3) each, every vertex moving linearly). "
                       "use_normal_cones: False gives the traditional query. ") +
           kModeDoc + kKernelDoc + kGeometryDoc + "Raises ValueError for a wrong count or a NaN/infinity.")
              .c_str())
      .def("__repr__", [](const PositionCcd& ccd) {
        return "<sscc.PositionCcd over " + std::to_string(ccd.mesh().triangle_count()) + " triangles, " +
               std::to_string(ccd.excluded_pairs().size()) + " excluded pairs>";
      });
}

}  // namespace sscc::python
