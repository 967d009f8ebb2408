// The leaf kernels: one query at a time, and vectorised over (n, 4, 3) arrays so that many
// queries cross the language boundary once.
#include <array>
#include <chrono>
#include <cstdint>

#include "arrays.hpp"
#include "bindings.hpp"
#include "options.hpp"
#include "sscc/ccd/kernels.hpp"

namespace sscc::python {

namespace {

using Kernel = ccd::CcdResult (*)(const Eigen::Vector3d&, const Eigen::Vector3d&, const Eigen::Vector3d&,
                                  const Eigen::Vector3d&, const Eigen::Vector3d&, const Eigen::Vector3d&,
                                  const Eigen::Vector3d&, const Eigen::Vector3d&, const ccd::CcdOptions&);

/// A C-ordered (n, 4, 3) float64 array (copied only when the input is not one).
CArray primitives_from(py::object object, const char* name) {
  CArray array = CArray::ensure(object);
  if (!array) throw py::value_error(std::string(name) + ": expected an array of numbers");
  if (array.ndim() != 3 || array.shape(1) != 4 || array.shape(2) != 3) {
    throw py::value_error(std::string(name) + ": expected an (n, 4, 3) array, got shape " + shape_text(array));
  }
  return array;
}

/// Query i of start and end arrays (4 points each, 12 doubles) through the kernel.
ccd::CcdResult run(Kernel kernel, const double* start, const double* end, const ccd::CcdOptions& options) {
  using Point = Eigen::Map<const Eigen::Vector3d>;
  return kernel(Point(start), Point(start + 3), Point(start + 6), Point(start + 9), Point(end), Point(end + 3),
                Point(end + 6), Point(end + 9), options);
}

py::tuple run_many(Kernel kernel, py::object start_object, py::object end_object, double toi_tolerance,
                   double minimum_separation) {
  const CArray start = primitives_from(start_object, "start");
  const CArray end = primitives_from(end_object, "end");
  if (start.shape(0) != end.shape(0)) {
    throw py::value_error("start and end: " + std::to_string(start.shape(0)) + " and " + std::to_string(end.shape(0)) +
                          " queries");
  }
  const py::ssize_t n = start.shape(0);
  py::array_t<bool> hit(n);
  py::array_t<double> toi(n);
  const ccd::CcdOptions options = kernel_options(toi_tolerance, minimum_separation);
  const double* a = start.data();
  const double* b = end.data();
  bool* hits = hit.mutable_data();
  double* tois = toi.mutable_data();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < n; ++i) {
      try {
        const ccd::CcdResult result = run(kernel, a + 12 * i, b + 12 * i, options);
        hits[i] = result.hit;
        tois[i] = result.hit ? result.toi : 1.0;
      } catch (const std::invalid_argument& error) {
        throw std::invalid_argument("query " + std::to_string(i) + ": " + error.what());
      }
    }
  }
  return py::make_tuple(std::move(hit), std::move(toi));
}

py::tuple run_one(Kernel kernel, const char* const names[8], const py::object points[8], double toi_tolerance,
                  double minimum_separation) {
  Eigen::Vector3d p[8];
  for (int k = 0; k < 8; ++k) p[k] = point_from(points[k], names[k]);
  const ccd::CcdResult result =
      kernel(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], kernel_options(toi_tolerance, minimum_separation));
  return py::make_tuple(result.hit, result.hit ? result.toi : 1.0);
}

/// The loop run_many makes, on data already in C++ (arrays of points), timed: what the
/// vectorised call costs without the language boundary.
double native_loop_seconds(Kernel kernel, py::object start_object, py::object end_object) {
  const CArray start = primitives_from(start_object, "start");
  const CArray end = primitives_from(end_object, "end");
  const std::size_t n = static_cast<std::size_t>(std::min(start.shape(0), end.shape(0)));
  std::vector<std::array<Eigen::Vector3d, 8>> queries(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 4; ++k) {
      queries[i][k] = Eigen::Map<const Eigen::Vector3d>(start.data() + 12 * i + 3 * k);
      queries[i][4 + k] = Eigen::Map<const Eigen::Vector3d>(end.data() + 12 * i + 3 * k);
    }
  }
  std::vector<std::uint8_t> hits(n);
  std::vector<double> tois(n);
  py::gil_scoped_release release;
  const auto begin = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& q = queries[i];
    const ccd::CcdResult result = kernel(q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7], ccd::CcdOptions{});
    hits[i] = result.hit;
    tois[i] = result.hit ? result.toi : 1.0;
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

Kernel kernel_named(const std::string& name) {
  if (name == "vertex_face") return &ccd::vertex_face_ccd;
  if (name == "edge_edge") return &ccd::edge_edge_ccd;
  throw py::value_error("kernel: expected 'vertex_face' or 'edge_edge', got '" + name + "'");
}

constexpr const char* kOptionsDoc =
    " toi_tolerance: the reported time lies within it below the first contact. minimum_separation: "
    "d > 0 reports coming within distance d (conservative). With d = 0 the decision is exact for the "
    "given doubles, degenerate cases included. Raises ValueError for non-finite coordinates.";

/// Binds `name` (one query, eight points named `points`) and `name`_many (n queries).
void bind_kernel(py::module_& m, const std::string& name, Kernel kernel, const std::array<const char*, 8>& points,
                 const std::string& doc, const std::string& many_doc) {
  m.def(
      name.c_str(),
      [kernel, points](py::object p0, py::object p1, py::object p2, py::object p3, py::object p4, py::object p5,
                       py::object p6, py::object p7, double toi_tolerance, double minimum_separation) {
        const py::object given[8] = {p0, p1, p2, p3, p4, p5, p6, p7};
        return run_one(kernel, points.data(), given, toi_tolerance, minimum_separation);
      },
      py::arg(points[0]), py::arg(points[1]), py::arg(points[2]), py::arg(points[3]), py::arg(points[4]),
      py::arg(points[5]), py::arg(points[6]), py::arg(points[7]), py::kw_only(),
      py::arg("toi_tolerance") = ccd::kDefaultToiTolerance, py::arg("minimum_separation") = 0.0,
      (doc + " Returns (hit, toi); toi is 1.0 without a hit." + kOptionsDoc).c_str());
  m.def((name + "_many").c_str(),
        [kernel](py::object start, py::object end, double toi_tolerance, double minimum_separation) {
          return run_many(kernel, start, end, toi_tolerance, minimum_separation);
        },
        py::arg("start"), py::arg("end"), py::kw_only(), py::arg("toi_tolerance") = ccd::kDefaultToiTolerance,
        py::arg("minimum_separation") = 0.0,
        (many_doc +
         " at t = 0 and t = 1 (float64 in C order is read in place). Returns (hit, toi): (n,) bool "
         "and (n,) float64 arrays, toi 1.0 where there is no hit. The loop runs without the GIL." +
         kOptionsDoc)
            .c_str());
}

}  // namespace

void bind_kernels(py::module_& m) {
  m.attr("DEFAULT_TOI_TOLERANCE") = ccd::kDefaultToiTolerance;
  bind_kernel(m, "vertex_face_ccd", &ccd::vertex_face_ccd, {"v0", "f0", "f1", "f2", "v1", "g0", "g1", "g2"},
              "Vertex-face CCD: vertex v0 -> v1 against the triangle (f0, f1, f2) -> (g0, g1, g2), every point "
              "moving linearly over t in [0, 1].",
              "Vertex-face CCD for n queries at once: start and end are (n, 4, 3) arrays, rows (vertex, f0, f1, "
              "f2)");
  bind_kernel(m, "edge_edge_ccd", &ccd::edge_edge_ccd, {"a0", "a1", "b0", "b1", "c0", "c1", "d0", "d1"},
              "Edge-edge CCD: edge (a0, a1) -> (c0, c1) against edge (b0, b1) -> (d0, d1), every point moving "
              "linearly over t in [0, 1].",
              "Edge-edge CCD for n queries at once: start and end are (n, 4, 3) arrays, rows (a0, a1, b0, b1)");

  m.def(
      "triangles_intersect",
      [](py::object a0, py::object a1, py::object a2, py::object b0, py::object b1, py::object b2) {
        return ccd::triangles_intersect(point_from(a0, "a0"), point_from(a1, "a1"), point_from(a2, "a2"),
                                        point_from(b0, "b0"), point_from(b1, "b1"), point_from(b2, "b2"));
      },
      py::arg("a0"), py::arg("a1"), py::arg("a2"), py::arg("b0"), py::arg("b1"), py::arg("b2"),
      "Exact discrete test: do the closed triangles (a0, a1, a2) and (b0, b1, b2) share a point?");

  m.def(
      "_native_kernel_loop_seconds",
      [](const std::string& kernel, py::object start, py::object end) {
        return native_loop_seconds(kernel_named(kernel), start, end);
      },
      py::arg("kernel"), py::arg("start"), py::arg("end"),
      "Benchmark support: seconds taken by the plain C++ loop over the same queries as "
      "vertex_face_ccd_many / edge_edge_ccd_many (kernel 'vertex_face' or 'edge_edge', default options), "
      "with the data already in C++ containers; the boundary's cost is the ratio to the vectorised call.");
}

}  // namespace sscc::python
