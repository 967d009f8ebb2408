#include "basis_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "pose_files.hpp"
#include "sscc/mesh/mesh_io.hpp"
#include "sscc/mesh/write_off.hpp"
#include "sscc/model/basis_io.hpp"
#include "sscc/model/polynomial_basis.hpp"

namespace sscc::validation {

std::string default_weights_path(const std::string& basis_path) {
  return std::filesystem::path(basis_path).replace_extension(".weights").string();
}

long run_basis(const BasisCommandOptions& o, std::ostream& out, std::ostream& progress) {
  if (o.output.empty()) throw std::invalid_argument("basis: no output file given");
  MeshReadReport mesh_report;
  const TriangleMesh mesh = read_mesh(o.mesh, &mesh_report);
  progress << "mesh " << o.mesh << ": " << mesh.vertex_count() << " vertices, " << mesh.triangle_count()
           << " triangles (" << mesh_report.summary() << ")\n";
  const auto start = std::chrono::steady_clock::now();
  Eigen::MatrixXd basis;
  Eigen::VectorXd weights;
  double lowest_frequency = std::nan("");
  std::optional<TriangleMesh> mean_shape;  // method pca: the model's rest mesh
  const auto take = [&](const ElasticBasis& elastic) {
    basis = elastic.basis;
    weights = elastic.weights;
    if (elastic.frequencies_hz.size() > 0) lowest_frequency = elastic.frequencies_hz[0];
    progress << "basis: volume " << elastic.volume_method << " (" << elastic.volume_nodes << " nodes, "
             << elastic.tetrahedra << " tetrahedra" << (elastic.volume_note.empty() ? "" : "; " + elastic.volume_note)
             << "), " << elastic.zero_energy_modes << " zero-energy modes dropped\n";
  };
  if (o.method == "modal") {
    take(modal_basis(mesh, o.elastic, &progress));
  } else if (o.method == "polynomial" && o.scaling == PolynomialScaling::kStiffness) {
    take(stiffness_scaled_polynomial_basis(mesh, o.elastic, &progress));
  } else if (o.method == "polynomial") {
    basis = polynomial_basis(mesh, o.elastic.modes);
    weights = Eigen::VectorXd::Ones(basis.cols());
  } else if (o.method == "stiffness") {
    if (o.input_basis.empty()) throw std::invalid_argument("basis: method stiffness needs --input FILE.U");
    take(stiffness_scaled_basis(mesh, read_basis(o.input_basis), o.elastic, &progress));
  } else if (o.method == "pca") {
    if (o.poses.empty()) throw std::invalid_argument("basis: method pca needs --poses LIST");
    const PoseSubspace subspace = pose_subspace_from_files(mesh, o.poses, o.pca, progress);
    basis = subspace.basis();
    weights = subspace.weights();
    mean_shape = subspace.mean_shape();
  } else {
    throw std::invalid_argument("basis: unknown method '" + o.method + "' (modal, polynomial, stiffness, pca)");
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string weights_path = o.weights_output.empty() ? default_weights_path(o.output) : o.weights_output;
  write_vega_basis(o.output, basis);
  write_weights(weights_path, weights);
  progress << "basis: wrote " << o.output << " and " << weights_path << '\n';
  if (mean_shape) {
    const std::string mean_path =
        o.mean_output.empty() ? std::filesystem::path(o.output).replace_extension(".mean.off").string() : o.mean_output;
    write_off(mean_path, *mean_shape);
    progress << "basis: wrote the mean shape (the rest mesh of x = mean + U q) to " << mean_path << '\n';
  }
  char line[256];
  std::snprintf(line, sizeof line, "basis: method=%s vertices=%d modes=%d time_s=%.3f lowest_frequency_hz=%.6g",
                o.method.c_str(), mesh.vertex_count(), static_cast<int>(basis.cols()), seconds, lowest_frequency);
  out << line << '\n';
  return 0;
}

}  // namespace sscc::validation
