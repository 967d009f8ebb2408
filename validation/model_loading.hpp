// Loads the subspace model the validation commands work on: a mesh file and a basis
// ("polynomial:R", "modal:R" for modal analysis with the default material and volume, or
// a basis file), with optional weights (default: modal weights for "modal:R", else all
// ones; a weights file overrides both). On request, the triangle pairs touching at rest are
// excluded (excluded_pairs.hpp) and their number reported.
#pragma once

#include <ostream>
#include <string>

#include "sscc/model/subspace_model.hpp"

namespace sscc::validation {

struct ModelSource {
  std::string mesh;
  std::string basis = "polynomial:27";  ///< "polynomial:R", "modal:R" or a basis file (.U or text)
  std::string weights;                  ///< weights file; "" means all ones
  bool exclude_rest_contacts = false;   ///< --exclude-rest-contacts
};

/// Reads and builds the model, reporting the mesh on `progress`.
SubspaceModel load_model(const ModelSource& source, std::ostream& progress);

/// The model excluding its pairs that touch at rest when `exclude` is set (reported on
/// `progress` as "N pairs touch at rest and are excluded"), else the model itself.
SubspaceModel with_rest_contacts_excluded(const SubspaceModel& model, bool exclude, std::ostream& progress);

}  // namespace sscc::validation
