// `sscc basis`: makes a subspace basis for a mesh and writes it as a Vega .U file with its
// weights (one number per mode, text), and for method pca the mean shape (the model's rest
// mesh) as an OFF file, printing at the end exactly one line
//   basis: method=M vertices=N modes=R time_s=X lowest_frequency_hz=X
// (the frequency is nan where it does not apply: displacement-normalised polynomial modes
// and example poses).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "sscc/basis/example_poses.hpp"
#include "sscc/basis/modal_analysis.hpp"

namespace sscc::validation {

enum class PolynomialScaling { kStiffness, kDisplacement };

struct BasisCommandOptions {
  std::string mesh;
  std::string method = "modal";  ///< modal, polynomial, stiffness (of input_basis) or pca
  ElasticBasisOptions elastic;   ///< material, volume mesh, modes
  PolynomialScaling scaling = PolynomialScaling::kStiffness;
  std::string input_basis;         ///< method stiffness: the basis to scale
  std::string output;              ///< the .U file
  std::string weights_output;      ///< "" means output with its extension replaced by .weights
  std::vector<std::string> poses;  ///< method pca: example pose files or directories of them
  PcaOptions pca;                  ///< method pca: modes or explained-variance fraction
  std::string mean_output;         ///< method pca: "" means output with its extension replaced by .mean.off
};

/// The weights file written next to a basis file: the extension replaced by ".weights".
std::string default_weights_path(const std::string& basis_path);

/// Returns 0 (errors throw).
long run_basis(const BasisCommandOptions& options, std::ostream& out, std::ostream& progress);

}  // namespace sscc::validation
