// Meshes and bases: TriangleMesh, read_mesh, polynomial_basis, modal_basis, basis files.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cctype>
#include <string>
#include <utility>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "sscc/basis/modal_analysis.hpp"
#include "sscc/mesh/excluded_pairs.hpp"
#include "sscc/mesh/mesh_io.hpp"
#include "sscc/model/basis_io.hpp"
#include "sscc/model/polynomial_basis.hpp"

namespace sscc::python {

namespace {

bool has_vega_extension(const std::string& path) {
  if (path.size() < 2) return false;
  const std::string tail = path.substr(path.size() - 2);
  return tail[0] == '.' && std::toupper(static_cast<unsigned char>(tail[1])) == 'U';
}

}  // namespace

void bind_meshes(py::module_& m) {
  py::class_<TriangleMesh>(m, "TriangleMesh",
                           "A triangle mesh: vertices, triangles and their connectivity. Two triangles are "
                           "adjacent when they share a vertex; adjacent pairs are never reported as colliding. "
                           "Immutable.")
      .def(py::init([](py::object vertices, py::object triangles) {
             return TriangleMesh(points_from(vertices, "vertices"), index_triples_from(triangles, "triangles"));
           }),
           py::arg("vertices"), py::arg("triangles"),
           "From an (n, 3) float array of vertices and an (m, 3) integer array of triangles (vertex "
           "indices). Raises ValueError for a non-finite coordinate, an index out of range or a triangle "
           "that repeats a vertex.")
      .def_property_readonly(
          "vertices", [](py::object self) { return rows_view(self.cast<const TriangleMesh&>().vertices(), self); },
          "The rest positions, (n, 3) float64, a read-only view (no copy).")
      .def_property_readonly(
          "triangles", [](py::object self) { return rows_view(self.cast<const TriangleMesh&>().triangles(), self); },
          "The triangles' vertex indices, (m, 3) int32, a read-only view (no copy).")
      .def_property_readonly(
          "edges", [](py::object self) { return rows_view(self.cast<const TriangleMesh&>().edges(), self); },
          "The unique edges as sorted vertex pairs, (e, 2) int32, a read-only view. Edge-edge feature "
          "contacts index into these rows.")
      .def_property_readonly("vertex_count", &TriangleMesh::vertex_count, "Number of vertices.")
      .def_property_readonly("triangle_count", &TriangleMesh::triangle_count, "Number of triangles.")
      .def("adjacent", &TriangleMesh::adjacent, py::arg("a"), py::arg("b"),
           "Whether triangles a and b share a vertex (a triangle is adjacent to itself).")
      .def_property_readonly("bounding_box_diagonal", &TriangleMesh::bounding_box_diagonal,
                             "Length of the diagonal of the rest positions' bounding box.")
      .def("__repr__", [](const TriangleMesh& mesh) {
        return "<sscc.TriangleMesh with " + std::to_string(mesh.vertex_count()) + " vertices and " +
               std::to_string(mesh.triangle_count()) + " triangles>";
      });

  static_assert(sizeof(std::pair<int, int>) == 2 * sizeof(int), "a pair is viewed as one row of two ints");
  py::class_<ExcludedPairs>(m, "ExcludedPairs",
                            "Triangle pairs that self-collision queries ignore besides the adjacent ones: on "
                            "request, the non-adjacent pairs that already touch in the rest shape. A pair is "
                            "considered when it is neither adjacent nor excluded; an excluded pair is never "
                            "reported, while a feature it shares with a considered pair still is. Give it to "
                            "SubspaceModel.excluding or PositionCcd. Immutable.")
      .def(py::init([](int triangle_count, py::object pairs) {
             const auto array = py::array::ensure(pairs);
             if (!array || (array.dtype().kind() != 'i' && array.dtype().kind() != 'u')) {
               throw py::value_error("pairs: expected an array of integers");
             }
             const auto rows = py::array_t<long long, py::array::forcecast>::ensure(array);
             if (rows.size() != 0 && (rows.ndim() != 2 || rows.shape(1) != 2)) {
               throw py::value_error("pairs: expected a (k, 2) array, got shape " + shape_text(rows));
             }
             std::vector<std::pair<int, int>> list;
             if (rows.size() != 0) {
               const auto r = rows.unchecked<2>();
               for (py::ssize_t i = 0; i < rows.shape(0); ++i) {
                 for (int k = 0; k < 2; ++k) {
                   if (r(i, k) < 0 || r(i, k) >= triangle_count) {
                     throw py::value_error("pairs: triangle " + std::to_string(r(i, k)) + " in row " +
                                           std::to_string(i) + " is out of range (" + std::to_string(triangle_count) +
                                           " triangles)");
                   }
                 }
                 list.emplace_back(static_cast<int>(r(i, 0)), static_cast<int>(r(i, 1)));
               }
             }
             return ExcludedPairs(triangle_count, std::move(list));
           }),
           py::arg("triangle_count"), py::arg("pairs"),
           "The given pairs ((k, 2) integers, in either order, repeats merged) of a mesh of "
           "triangle_count triangles. Raises ValueError for an index out of range or a pair (t, t).")
      .def_static(
          "touching_at_rest",
          [](const TriangleMesh& mesh) {
            py::gil_scoped_release release;
            return ExcludedPairs::touching_at_rest(mesh);
          },
          py::arg("mesh"),
          "The non-adjacent pairs of the mesh whose closed triangles share a point at its rest positions "
          "(exact predicates): every such pair and no other.")
      .def_property_readonly(
          "pairs",
          [](py::object self) {
            const auto& pairs = self.cast<const ExcludedPairs&>().pairs();
            return view(pairs.empty() ? nullptr : &pairs.front().first, {py::ssize_t(pairs.size()), 2},
                        {py::ssize_t(sizeof(std::pair<int, int>)), py::ssize_t(sizeof(int))}, self);
          },
          "(k, 2) int32, sorted, first < second: the excluded pairs, a read-only view.")
      .def_property_readonly("triangle_count", &ExcludedPairs::triangle_count,
                             "The triangle count of the mesh the set was made for (0 for the empty set).")
      .def(
          "contains",
          [](const ExcludedPairs& excluded, int a, int b) {
            const int n = excluded.triangle_count();
            if (!excluded.empty() && (a < 0 || a >= n || b < 0 || b >= n)) {
              throw py::index_error("triangle out of range (" + std::to_string(n) + " triangles)");
            }
            return excluded.contains(a, b);
          },
          py::arg("a"), py::arg("b"),
          "Whether the pair (a, b), in either order, is excluded. Raises IndexError for a triangle out of "
          "range.")
      .def("__len__", &ExcludedPairs::size)
      .def("__repr__", [](const ExcludedPairs& excluded) {
        return "<sscc.ExcludedPairs: " + std::to_string(excluded.size()) + " pairs>";
      });

  m.def(
      "read_mesh",
      [](const std::string& path) {
        py::gil_scoped_release release;
        return read_mesh(path);
      },
      py::arg("path"),
      "Reads an OFF, OBJ or PLY mesh (by extension). Polygons are fan-triangulated. Raises OSError "
      "naming the file, line and problem for a file that cannot be read or is not a mesh.");

  m.def(
      "polynomial_basis",
      [](const TriangleMesh& mesh, int modes) {
        py::gil_scoped_release release;
        return polynomial_basis(mesh, modes);
      },
      py::arg("mesh"), py::arg("modes") = kMaxPolynomialModes,
      "The first `modes` (1 to 27) polynomial modes (linear, then quadratic functions of rest "
      "position) as U, (3n, modes): row 3v + k is vertex v's coordinate k. Their weights are ones.");

  m.def(
      "modal_basis",
      [](const TriangleMesh& mesh, int modes, double youngs, double poisson, double density,
         const std::string& volume) {
        ElasticBasisOptions options;
        options.modes = modes;
        options.material.youngs_modulus = youngs;
        options.material.poisson_ratio = poisson;
        options.material.density = density;
        options.volume.method = parse_volume_method(volume);
        ElasticBasis basis;
        {
          py::gil_scoped_release release;
          basis = modal_basis(mesh, options);
        }
        return py::make_tuple(std::move(basis.basis), std::move(basis.weights));
      },
      py::arg("mesh"), py::arg("modes") = 30, py::arg("youngs") = ElasticMaterial{}.youngs_modulus,
      py::arg("poisson") = ElasticMaterial{}.poisson_ratio, py::arg("density") = ElasticMaterial{}.density,
      py::arg("volume") = "auto",
      "Linear modal analysis of the solid the closed surface bounds (TetGen tetrahedra, or a voxel "
      "grid for open scans: volume='auto', 'tetgen' or 'voxel'). Material in Pa and kg/m^3 for a mesh "
      "in metres. Returns (U, weights): U (3n, modes), mass-normalised vibration modes; weights "
      "omega^2 / 2, so that ||q||_M^2 is the strain energy in joules.");

  m.def(
      "read_basis",
      [](const std::string& path) {
        py::gil_scoped_release release;
        return file_operation([&] { return read_basis(path); });
      },
      py::arg("path"),
      "Reads a basis U: Vega's binary .U layout when the name ends in .U (any case), a text matrix "
      "otherwise. Raises OSError naming the file and the problem.");

  m.def(
      "write_basis",
      [](const std::string& path, py::object basis) {
        if (!has_vega_extension(path)) {
          throw py::value_error("write_basis: " + path + ": the name must end in .U (Vega's binary layout)");
        }
        const Eigen::MatrixXd matrix = matrix_from(basis, "U");
        py::gil_scoped_release release;
        file_operation([&] { write_vega_basis(path, matrix); });
      },
      py::arg("path"), py::arg("U"),
      "Writes U in Vega's binary .U layout (the name must end in .U so that read_basis reads it "
      "back). Raises OSError when the file cannot be written.");
}

}  // namespace sscc::python
