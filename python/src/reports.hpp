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
#include "sscc/scene/contact_geometry.hpp"

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

/// The contact points and normals of a report's feature contacts, one row per feature in the
/// features' order (sscc/scene/contact_geometry.hpp): each feature's four vertices, their
/// weights (the barycentric coordinates of the two contact points, +1 and -1 in sum), the
/// first side's contact point at the time of impact and the unit normal there.
struct ContactGeometry {
  std::vector<std::array<int, 4>> vertices;
  std::vector<std::array<double, 4>> barycentric;
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3d> normals;

  /// Adds the row of one feature contact whose four vertices are at `start` and `end` at the
  /// two ends of the step.
  void add(FeatureKind kind, const std::array<int, 4>& feature_vertices, const std::array<Eigen::Vector3d, 4>& start,
           const std::array<Eigen::Vector3d, 4>& end, double toi) {
    const ContactFrame frame = contact_frame(kind, start, end, toi);
    const int first_side = kind == FeatureKind::kVertexFace ? 1 : 2;
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    for (int i = 0; i < first_side; ++i) point += frame.weights[i] * ((1 - toi) * start[i] + toi * end[i]);
    vertices.push_back(feature_vertices);
    barycentric.push_back(frame.weights);
    points.push_back(point);
    normals.push_back(frame.normal);
  }
};

/// A self query's report with its contact geometry (the Python SelfCcdReport).
struct SelfReport : SelfCcdReport {
  ContactGeometry geometry;
};

/// The geometry of a self report's features, for the vertex positions at both ends of its
/// step given by position(vertex, end) (end 0 or 1) over `mesh`.
template <typename Position>
ContactGeometry self_contact_geometry(const TriangleMesh& mesh, const std::vector<FeatureContact>& features,
                                      Position position) {
  ContactGeometry geometry;
  for (const FeatureContact& f : features) {
    const std::array<int, 4> v = contact_vertices(mesh, mesh, f.kind, f.first, f.second);
    std::array<Eigen::Vector3d, 4> start, end;
    for (int i = 0; i < 4; ++i) start[i] = position(v[i], 0), end[i] = position(v[i], 1);
    geometry.add(f.kind, v, start, end, f.toi);
  }
  return geometry;
}

void bind_feature_arrays(py::module_& m);
/// The Python ContactGeometry class.
void bind_contact_geometry(py::module_& m);
/// SelfCcdReport's members (pairs, toi, features, geometry, earliest_toi, collided, stats).
void bind_self_report(py::module_& m);

}  // namespace sscc::python
