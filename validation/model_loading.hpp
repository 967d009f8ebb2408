// Loads the subspace model the validation commands work on: a mesh file and a basis
// ("polynomial:R", "modal:R" for modal analysis with the default material and volume, or
// a basis file), with optional weights (default: modal weights for "modal:R", else all
// ones; a weights file overrides both).
#pragma once

#include <ostream>
#include <string>

#include "sscc/model/subspace_model.hpp"

namespace sscc::validation {

struct ModelSource {
  std::string mesh;
  std::string basis = "polynomial:27";  ///< "polynomial:R", "modal:R" or a basis file (.U or text)
  std::string weights;                  ///< weights file; "" means all ones
};

/// Reads and builds the model, reporting the mesh on `progress`.
SubspaceModel load_model(const ModelSource& source, std::ostream& progress);

}  // namespace sscc::validation
