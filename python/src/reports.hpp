// Reports as NumPy views.
//
// A report's contact lists stay in the C++ report; .pairs, .toi and the features are
// read-only strided views into them that keep the report alive (no copy per access).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "arrays.hpp"
#include "sscc/query/self_ccd.hpp"

namespace sscc::python {

/// Feature contacts: kind (0 vertex-face, 1 edge-edge), the indices of what touches, and the
/// time of impact, each an array with one row per contact.
struct FeatureArrays {
  py::array kind, indices, toi;
};

/// A view of `columns` consecutive int fields of each contact, starting at `first`.
template <typename Contact>
py::array index_columns(const std::vector<Contact>& contacts, int Contact::*first, int columns, py::handle owner) {
  return view(contacts.empty() ? nullptr : &(contacts.front().*first), {py::ssize_t(contacts.size()), columns},
              {py::ssize_t(sizeof(Contact)), py::ssize_t(sizeof(int))}, owner);
}

/// A view of each contact's toi.
template <typename Contact>
py::array toi_column(const std::vector<Contact>& contacts, py::handle owner) {
  return view(contacts.empty() ? nullptr : &contacts.front().toi, {py::ssize_t(contacts.size())},
              {py::ssize_t(sizeof(Contact))}, owner);
}

/// A feature list (kind, `columns` consecutive index fields from `first`, toi) as arrays.
template <typename Feature>
FeatureArrays feature_arrays(const std::vector<Feature>& features, int Feature::*first, int columns, py::handle owner) {
  static_assert(sizeof(FeatureKind) == sizeof(std::uint8_t), "kinds are viewed as uint8");
  const auto* kind = features.empty() ? nullptr : reinterpret_cast<const std::uint8_t*>(&features.front().kind);
  return {view(kind, {py::ssize_t(features.size())}, {py::ssize_t(sizeof(Feature))}, owner),
          index_columns(features, first, columns, owner), toi_column(features, owner)};
}

void bind_feature_arrays(py::module_& m);

}  // namespace sscc::python
