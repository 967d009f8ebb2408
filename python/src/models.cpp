// SubspaceModel, SubspaceBvh and Certificates.
#include <pybind11/eigen.h>
#include <pybind11/functional.h>

#include <memory>

#include "arrays.hpp"
#include "bindings.hpp"
#include "progress.hpp"
#include "sscc/bvh/subspace_bvh.hpp"
#include "sscc/certificates/certificates.hpp"
#include "sscc/model/subspace_model.hpp"

namespace sscc::python {

namespace {

py::dict build_stats_dict(const BvhBuildStats& s) {
  py::dict d;
  d["nodes"] = s.nodes;
  d["leaves"] = s.leaves;
  d["depth"] = s.depth;
  d["largest_leaf"] = s.largest_leaf;
  d["seconds"] = s.seconds;
  return d;
}

py::dict precompute_stats_dict(const PrecomputeStats& s) {
  py::dict d;
  d["node_pairs_visited"] = s.node_pairs_visited;
  d["node_pairs_culled"] = s.node_pairs_culled;
  d["triangle_pairs_culled"] = s.triangle_pairs_culled;
  d["triangle_pairs_bounded"] = s.triangle_pairs_bounded;
  d["constant_mode_evaluations"] = s.constant_mode_evaluations;
  d["pair_tree_tasks"] = s.pair_tree_tasks;
  d["threads"] = s.threads;
  d["seconds"] = s.seconds;
  return d;
}

py::dict parameters_dict(const CertificateParameters& p) {
  py::dict d;
  d["epsilon"] = p.epsilon;
  d["global_radius_scale"] = p.global_radius_scale;
  d["max_subdivision_depth"] = p.max_subdivision_depth;
  d["max_evaluations_per_pair"] = p.max_evaluations_per_pair;
  return d;
}

}  // namespace

void bind_models(py::module_& m) {
  py::class_<SubspaceModel>(m, "SubspaceModel",
                            "A reduced deformable object, x = p + U q: the mesh's rest positions p, a basis U "
                            "(3n, r) and weights w (||q||_M^2 = sum w_i q_i^2). Immutable.")
      .def(py::init([](const TriangleMesh& mesh, py::object basis, py::object weights) {
             const Eigen::MatrixXd u = matrix_from(basis, "U");
             const Eigen::VectorXd w = vector_from(weights, "weights");
             py::gil_scoped_release release;
             return std::make_unique<SubspaceModel>(mesh, u, w);
           }),
           py::arg("mesh"), py::arg("U"), py::arg("weights"),
           "The model keeps its own copy of the mesh and the (scaled) basis. Raises ValueError when U "
           "is not (3n, r), r is 0, the weights are not r positive finite numbers, or an entry is not "
           "finite.")
      .def_property_readonly("mesh", &SubspaceModel::mesh, py::return_value_policy::reference_internal,
                             "The model's mesh (kept alive by references to it).")
      .def(
          "excluding",
          [](const SubspaceModel& model, const ExcludedPairs& excluded) { return model.excluding(excluded); },
          py::arg("excluded"),
          "This model (sharing its mesh and basis, no copy) with the pairs of `excluded` (ExcludedPairs) "
          "ignored by every hierarchy, certificate and query built on it, like adjacent pairs; the "
          "certificates' key records them. Raises ValueError when the set was made for a mesh of another "
          "triangle count.")
      .def(
          "excluding_rest_contacts",
          [](const SubspaceModel& model) {
            py::gil_scoped_release release;
            return model.excluding_rest_contacts();
          },
          "excluding(ExcludedPairs.touching_at_rest(mesh)): the non-adjacent pairs that touch in the rest "
          "shape (exact test), for meshes that touch themselves at rest.")
      .def_property_readonly("excluded_pairs", &SubspaceModel::excluded_pairs,
                             py::return_value_policy::reference_internal,
                             "The excluded pairs (ExcludedPairs; empty unless excluding() made this model).")
      .def(
          "considers",
          [](const SubspaceModel& model, int a, int b) {
            const int n = model.mesh().triangle_count();
            if (a < 0 || a >= n || b < 0 || b >= n) {
              throw py::index_error("triangle out of range (" + std::to_string(n) + " triangles)");
            }
            return model.considers(a, b);
          },
          py::arg("a"), py::arg("b"),
          "Whether queries consider triangles a and b: neither adjacent nor excluded. Raises IndexError for "
          "a triangle out of range.")
      .def_property_readonly("mode_count", &SubspaceModel::mode_count, "r, the number of modes.")
      .def_property_readonly(
          "weights",
          [](py::object self) {
            const Eigen::VectorXd& w = self.cast<const SubspaceModel&>().weights();
            return view(w.data(), {w.size()}, {py::ssize_t(sizeof(double))}, self);
          },
          "The weights w, (r,), a read-only view.")
      .def_property_readonly(
          "scaled_basis",
          [](py::object self) {
            const RowMajorMatrix& u = self.cast<const SubspaceModel&>().scaled_basis();
            return view(u.data(), {u.rows(), u.cols()},
                        {py::ssize_t(u.cols() * sizeof(double)), py::ssize_t(sizeof(double))}, self);
          },
          "U M^(-1/2), (3n, r), a read-only view: the basis every bound works with.")
      .def(
          "weighted_norm",
          [](const SubspaceModel& model, py::object q) { return model.weighted_norm(vector_from(q, "q")); },
          py::arg("q"), "||q||_M = sqrt(sum w_i q_i^2), the norm the certificates' radii are in.")
      .def(
          "deformed_positions",
          [](const SubspaceModel& model, py::object q) {
            const Eigen::VectorXd coordinates = vector_from(q, "q");
            std::vector<Eigen::Vector3d> x;
            {
              py::gil_scoped_release release;
              x = model.deformed_positions(coordinates);
            }
            const py::ssize_t n = static_cast<py::ssize_t>(x.size());
            return adopt<double>(std::move(x), {n, 3});
          },
          py::arg("q"), "The vertex positions p + U q, (n, 3).")
      .def("__repr__", [](const SubspaceModel& model) {
        return "<sscc.SubspaceModel with " + std::to_string(model.mesh().triangle_count()) + " triangles and " +
               std::to_string(model.mode_count()) + " modes>";
      });

  // Held by shared pointers, which detectors share (SelfCcd holds its hierarchy and certificates
  // so): one copy however many detectors and Python references there are.
  py::class_<SubspaceBvh, std::shared_ptr<SubspaceBvh>>(
      m, "SubspaceBvh",
      "A 4-ary bounding volume hierarchy over a model's triangles whose node boxes hold in "
      "every configuration q (built by k-means on rest positions and modes). Immutable.")
      .def(py::init([](const SubspaceModel& model, std::uint64_t seed) {
             py::gil_scoped_release release;
             return std::make_shared<SubspaceBvh>(model, seed);
           }),
           py::arg("model"), py::arg("seed") = 1,
           "Builds the hierarchy; `seed` makes the k-means seeding reproducible. The hierarchy shares the "
           "model's data (a model is a handle: no copy), which lives as long as either.")
      .def_property_readonly("model", &SubspaceBvh::model, py::return_value_policy::reference_internal,
                             "The model the hierarchy was built for.")
      .def_property_readonly(
          "node_count", [](const SubspaceBvh& bvh) { return static_cast<int>(bvh.nodes().size()); },
          "Number of nodes (node 0 is the root).")
      .def_property_readonly(
          "build_stats", [](const SubspaceBvh& bvh) { return build_stats_dict(bvh.build_stats()); },
          "Nodes, leaves, depth, largest leaf and build time (seconds), as a dict.")
      .def("__repr__", [](const SubspaceBvh& bvh) {
        return "<sscc.SubspaceBvh with " + std::to_string(bvh.nodes().size()) + " nodes, depth " +
               std::to_string(bvh.build_stats().depth) + ">";
      });

  py::class_<Certificates, std::shared_ptr<Certificates>>(
      m, "Certificates",
      "Subspace self-collision certificates: for every node n of a hierarchy a radius R_n "
      "such that no two non-adjacent triangles under n touch while ||q||_M < R_n (and "
      "likewise for sibling pairs). Every radius is a lower bound of the true one. "
      "Immutable.")
      .def_static(
          "precompute",
          [](const SubspaceBvh& bvh, double epsilon, double global_radius_scale, py::object progress) {
            CertificateParameters parameters;
            parameters.epsilon = epsilon;
            parameters.global_radius_scale = global_radius_scale;
            return precompute_with(progress, [&](const PrecomputeProgress& report) {
              return Certificates::precompute(bvh, parameters, report);
            });
          },
          py::arg("bvh"), py::arg("epsilon") = CertificateParameters{}.epsilon,
          py::arg("global_radius_scale") = CertificateParameters{}.global_radius_scale,
          py::arg("progress") = py::none(),
          "Computes the certificates of every node and sibling pair (in parallel). epsilon: relative "
          "accuracy of the triangle-pair radii; global_radius_scale: radii are resolved up to this "
          "multiple of the global radius. progress: None or a callable progress(levels_done, levels) "
          "called after each tree level; an exception it raises stops the precomputation. Raises "
          "ValueError for parameters out of range.")
      .def_static(
          "read",
          [](const std::string& path, const SubspaceBvh& bvh) {
            py::gil_scoped_release release;
            return file_operation([&] { return Certificates::read(path, bvh); });
          },
          py::arg("path"), py::arg("bvh"),
          "Reads a certificate file written by write() for this hierarchy. Raises OSError when the file "
          "is missing, truncated, corrupt, of another version, or computed for another mesh, basis, "
          "weights or tree.")
      .def(
          "write",
          [](const Certificates& certificates, const std::string& path) {
            py::gil_scoped_release release;
            file_operation([&] { certificates.write(path); });
          },
          py::arg("path"),
          "Writes the versioned, checksummed binary file, tied to the mesh, basis, weights and tree. "
          "Raises OSError when it cannot be written.")
      .def_property_readonly(
          "root_radius", [](const Certificates& c) { return c.node_radius(0); },
          "R of the root: a step whose two ends have ||q||_M below it is free of self-collisions.")
      .def_property_readonly("global_radius", &Certificates::global_radius,
                             "The cap on every radius (radii are resolved up to it only).")
      .def_property_readonly("node_count", &Certificates::node_count, "Number of nodes certified.")
      .def(
          "node_radius",
          [](const Certificates& c, int n) {
            if (n < 0 || n >= c.node_count()) throw py::index_error("node " + std::to_string(n) + " out of range");
            return c.node_radius(n);
          },
          py::arg("n"), "R_n of node n.")
      .def_property_readonly("key", &Certificates::key,
                             "The hash of the mesh, basis, tree and parameters the certificates belong to.")
      .def_property_readonly(
          "parameters", [](const Certificates& c) { return parameters_dict(c.parameters()); },
          "The parameters of the precomputation, as a dict.")
      .def_property_readonly(
          "stats", [](const Certificates& c) { return precompute_stats_dict(c.stats()); },
          "Statistics of the precomputation as a dict (zeros for certificates read from a file).")
      .def("__repr__", [](const Certificates& c) {
        return "<sscc.Certificates of " + std::to_string(c.node_count()) + " nodes, root radius " +
               std::to_string(c.node_radius(0)) + ">";
      });
}

}  // namespace sscc::python
