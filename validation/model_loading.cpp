#include "model_loading.hpp"

#include "sscc/mesh/mesh_io.hpp"
#include "sscc/model/basis_io.hpp"
#include "sscc/model/polynomial_basis.hpp"

namespace sscc::validation {

SubspaceModel load_model(const ModelSource& source, std::ostream& progress) {
  MeshReadReport mesh_report;
  TriangleMesh mesh = read_mesh(source.mesh, &mesh_report);
  progress << "mesh " << source.mesh << ": " << mesh.vertex_count() << " vertices, " << mesh.triangle_count()
           << " triangles (" << mesh_report.summary() << ")\n";
  Eigen::MatrixXd basis;
  const std::string prefix = "polynomial:";
  if (source.basis.compare(0, prefix.size(), prefix) == 0) {
    basis = polynomial_basis(mesh, std::stoi(source.basis.substr(prefix.size())));
  } else {
    basis = read_basis(source.basis);
  }
  const Eigen::VectorXd weights =
      source.weights.empty() ? Eigen::VectorXd::Ones(basis.cols()) : read_weights(source.weights);
  return SubspaceModel(std::move(mesh), basis, weights);
}

}  // namespace sscc::validation
