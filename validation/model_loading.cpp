#include "model_loading.hpp"

#include <stdexcept>

#include "sscc/basis/modal_analysis.hpp"
#include "sscc/mesh/mesh_io.hpp"
#include "sscc/model/basis_io.hpp"
#include "sscc/model/polynomial_basis.hpp"

namespace sscc::validation {

namespace {

int mode_count(const std::string& text) {
  std::size_t used = 0;
  int modes = 0;
  try {
    modes = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || modes < 1) {
    throw std::invalid_argument("--basis: expected a positive mode count after the colon, got '" + text + "'");
  }
  return modes;
}

}  // namespace

SubspaceModel load_model(const ModelSource& source, std::ostream& progress) {
  MeshReadReport mesh_report;
  TriangleMesh mesh = read_mesh(source.mesh, &mesh_report);
  progress << "mesh " << source.mesh << ": " << mesh.vertex_count() << " vertices, " << mesh.triangle_count()
           << " triangles (" << mesh_report.summary() << ")\n";
  Eigen::MatrixXd basis;
  Eigen::VectorXd weights;
  const auto generated = [&](const std::string& prefix) {
    return source.basis.compare(0, prefix.size(), prefix) == 0 ? mode_count(source.basis.substr(prefix.size())) : 0;
  };
  if (const int polynomial_modes = generated("polynomial:")) {
    basis = polynomial_basis(mesh, polynomial_modes);
  } else if (const int modal_modes = generated("modal:")) {
    ElasticBasisOptions options;
    options.modes = modal_modes;
    ElasticBasis modal = modal_basis(mesh, options, &progress);
    basis = std::move(modal.basis);
    weights = std::move(modal.weights);
  } else {
    basis = read_basis(source.basis);
  }
  if (!source.weights.empty()) {
    weights = read_weights(source.weights);
  } else if (weights.size() == 0) {
    weights = Eigen::VectorXd::Ones(basis.cols());
  }
  return with_rest_contacts_excluded(SubspaceModel(std::move(mesh), basis, weights), source.exclude_rest_contacts,
                                     progress);
}

SubspaceModel with_rest_contacts_excluded(const SubspaceModel& model, bool exclude, std::ostream& progress) {
  if (!exclude) return model;
  SubspaceModel excluding = model.excluding_rest_contacts();
  progress << excluding.excluded_pairs().size() << " pairs touch at rest and are excluded\n";
  return excluding;
}

}  // namespace sscc::validation
