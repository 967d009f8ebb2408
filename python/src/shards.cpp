// The precomputation in shards (certificate_shards.hpp): Certificates.precompute_shard for one
// process or machine each, CertificateShard's files and bytes between them (a remote task
// returns to_bytes()), and Certificates.merge.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "progress.hpp"
#include "sscc/certificates/certificate_shards.hpp"

namespace sscc::python {

void bind_shards(py::module_& m) {
  py::class_<CertificateShard>(m, "CertificateShard",
                               "The results of one shard of the certificates' precomputation "
                               "(Certificates.precompute_shard), for Certificates.merge. Immutable.")
      .def_property_readonly("index", &CertificateShard::index, "The shard's index, 0 <= index < count.")
      .def_property_readonly("count", &CertificateShard::count, "The number of shards the work was split in.")
      .def_property_readonly("split_depth", &CertificateShard::split_depth,
                             "The depth of the subtrees the shards share out; the merge computes the levels above.")
      .def_property_readonly("subtree_roots", &CertificateShard::subtree_roots,
                             "The roots of the shard's subtrees (node indices).")
      .def_property_readonly("key", &CertificateShard::key,
                             "The hash of the mesh, basis, tree and parameters the shard belongs to.")
      .def(
          "to_bytes",
          [](const CertificateShard& shard) {
            std::string bytes;
            {
              py::gil_scoped_release release;
              bytes = shard.to_bytes();
            }
            return py::bytes(bytes);
          },
          "The shard file's bytes (versioned and checksummed), e.g. to return from a remote task.")
      .def_static(
          "from_bytes",
          [](const std::string& bytes, const SubspaceBvh& bvh) {
            py::gil_scoped_release release;
            return file_operation([&] { return CertificateShard::from_bytes(bytes, bvh); });
          },
          py::arg("data"), py::arg("bvh"),
          "The shard in `data` (to_bytes()), for this hierarchy. Raises OSError when they are truncated, "
          "corrupt, of another version, or computed for another mesh, basis, weights or tree.")
      .def(
          "write",
          [](const CertificateShard& shard, const std::string& path) {
            py::gil_scoped_release release;
            file_operation([&] { shard.write(path); });
          },
          py::arg("path"), "Writes the shard file. Raises OSError when it cannot be written.")
      .def_static(
          "read",
          [](const std::string& path, const SubspaceBvh& bvh) {
            py::gil_scoped_release release;
            return file_operation([&] { return CertificateShard::read(path, bvh); });
          },
          py::arg("path"), py::arg("bvh"),
          "Reads a shard file for this hierarchy. Raises OSError as from_bytes does, or when the file "
          "cannot be opened.")
      .def("__repr__", [](const CertificateShard& shard) {
        return "<sscc.CertificateShard " + std::to_string(shard.index()) + "/" + std::to_string(shard.count()) +
               " of " + std::to_string(shard.subtree_roots().size()) + " subtrees>";
      });

  auto certificates =
      py::reinterpret_borrow<py::class_<Certificates, std::shared_ptr<Certificates>>>(m.attr("Certificates"));
  certificates
      .def_static(
          "precompute_shard",
          [](const SubspaceBvh& bvh, int index, int count, double epsilon, double global_radius_scale,
             py::object progress) {
            CertificateParameters parameters;
            parameters.epsilon = epsilon;
            parameters.global_radius_scale = global_radius_scale;
            return precompute_with(progress, [&](const PrecomputeProgress& report) {
              return Certificates::precompute_shard(bvh, parameters, index, count, report);
            });
          },
          py::arg("bvh"), py::arg("index"), py::arg("count"), py::arg("epsilon") = CertificateParameters{}.epsilon,
          py::arg("global_radius_scale") = CertificateParameters{}.global_radius_scale,
          py::arg("progress") = py::none(),
          "Shard `index` of `count` of precompute() (the subtrees below a split depth, dealt to the shards by "
          "their triangles), for one process or machine each; merge() puts them together. Parameters and "
          "progress as for precompute(). Raises ValueError for an index outside 0..count-1.")
      .def_static(
          "merge",
          [](const SubspaceBvh& bvh, const std::vector<const CertificateShard*>& shards, py::object progress) {
            std::vector<CertificateShard> copies;
            for (const CertificateShard* shard : shards) {
              if (!shard) throw py::value_error("merge: None among the shards");
              copies.push_back(*shard);
            }
            return precompute_with(
                progress, [&](const PrecomputeProgress& report) { return Certificates::merge(bvh, copies, report); });
          },
          py::arg("bvh"), py::arg("shards"), py::arg("progress") = py::none(),
          "The certificates of `shards` (one of each index, in any order, computed for this hierarchy): "
          "equal to precompute()'s, their file byte for byte; the levels above the split depth are computed "
          "here. Raises ValueError naming a missing or repeated shard, or shards of another model, tree, "
          "parameters or shard count.");
}

}  // namespace sscc::python
