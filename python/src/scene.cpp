// Scene: many instances of precomputed models, each with its own q and rigid frame.
#include <pybind11/stl.h>

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "options.hpp"
#include "reports.hpp"
#include "sscc/scene/contact_geometry.hpp"
#include "sscc/scene/scene.hpp"

namespace sscc::python {

namespace {

static_assert(offsetof(InterObjectContact, second) == offsetof(InterObjectContact, object_first) + 3 * sizeof(int),
              "a contact's objects and triangles are viewed as one row");
static_assert(offsetof(InterObjectFeature, second) == offsetof(InterObjectFeature, object_first) + 3 * sizeof(int),
              "a feature's objects and indices are viewed as one row");

/// None (the identity), a 4x4 homogeneous matrix, or a pair (R, t).
RigidFrame frame_from(py::object object, const std::string& name) {
  RigidFrame frame;
  if (object.is_none()) return frame;
  if ((py::isinstance<py::tuple>(object) || py::isinstance<py::list>(object)) && py::len(object) == 2) {
    const py::sequence pair = py::reinterpret_borrow<py::sequence>(object);
    const Eigen::MatrixXd rotation = matrix_from(pair[0], (name + " R").c_str());
    if (rotation.rows() != 3 || rotation.cols() != 3) {
      throw py::value_error(name + ": R must be 3x3, got " + std::to_string(rotation.rows()) + "x" +
                            std::to_string(rotation.cols()));
    }
    frame.rotation = rotation;
    frame.translation = point_from(pair[1], (name + " t").c_str());
    return frame;
  }
  const Eigen::MatrixXd matrix = matrix_from(object, name.c_str());
  if (matrix.rows() != 4 || matrix.cols() != 4) {
    throw py::value_error(name + ": expected a 4x4 matrix or a pair (R, t), got a " + std::to_string(matrix.rows()) +
                          "x" + std::to_string(matrix.cols()) + " matrix");
  }
  if (matrix.row(3) != Eigen::RowVector4d(0, 0, 0, 1)) {
    throw py::value_error(name + ": the last row of a 4x4 frame must be (0, 0, 0, 1)");
  }
  frame.rotation = matrix.topLeftCorner<3, 3>();
  frame.translation = matrix.topRightCorner<3, 1>();
  return frame;
}

/// Per-object items of a sequence that must have one per object (None: None for each).
/// Owned references: iterating an array makes each row anew.
std::vector<py::object> per_object(py::object sequence, const char* name, std::size_t objects) {
  if (sequence.is_none()) return std::vector<py::object>(objects, py::none());
  std::vector<py::object> items;
  for (py::handle item : py::iter(sequence)) items.push_back(py::reinterpret_borrow<py::object>(item));
  if (items.size() != objects) {
    throw py::value_error(std::string(name) + ": " + std::to_string(items.size()) + " entries for " +
                          std::to_string(objects) + " objects");
  }
  return items;
}

const char* outcome_name(SelfTestOutcome outcome) {
  switch (outcome) {
    case SelfTestOutcome::kTraversed:
      return "traversed";
    case SelfTestOutcome::kCertified:
      return "certified";
    case SelfTestOutcome::kStatic:
      return "static";
    case SelfTestOutcome::kSwitchedOff:
      return "switched_off";
    case SelfTestOutcome::kNotReached:
      return "not_reached";
  }
  return "unknown";
}

/// One object's self test in a scene step, its report with its contact geometry.
struct ObjectResult {
  SelfTestOutcome outcome = SelfTestOutcome::kNotReached;
  SelfReport report;
};

/// A scene step's report with the contact geometry of every feature (the Python SceneReport).
struct SceneResult {
  std::vector<ObjectResult> objects;
  std::vector<InterObjectContact> contacts;
  std::vector<InterObjectFeature> features;
  double earliest_toi = 1.0;
  SceneStats stats;
  bool collided = false;
  ContactGeometry geometry;  ///< of the features between objects, in the world
};

/// The step's report with each feature's contact points and normals, from the positions the
/// step's motion is linear in: x = p + U q at q0 and q1 in each object's frame for its self
/// contacts (in the world, R x + t, for a world_linear object), in the world between objects.
SceneResult with_geometry(const Scene& scene, const std::vector<ObjectStep>& steps, SceneReport report) {
  SceneResult result;
  result.collided = report.collided();
  result.contacts = std::move(report.contacts);
  result.features = std::move(report.features);
  result.earliest_toi = report.earliest_toi;
  result.stats = report.stats;
  const std::size_t objects = report.objects.size();
  // Each object's positions at the two ends of the step, in its frame or the world.
  std::vector<std::array<Eigen::VectorXd, 2>> q_hat(objects);
  const auto position = [&](std::size_t object, int v, int end, bool world) {
    const SubspaceModel& model = scene.detector(static_cast<int>(object)).bvh().model();
    if (q_hat[object][0].size() == 0 && model.mode_count() > 0) {
      q_hat[object] = {model.scaled_coordinates(steps[object].q0), model.scaled_coordinates(steps[object].q1)};
    }
    const Eigen::Vector3d x =
        model.mode_count() > 0 ? model.position(v, q_hat[object][end]) : model.mesh().vertices()[v];
    if (!world) return x;
    const RigidFrame& frame = end ? steps[object].frame1 : steps[object].frame0;
    return Eigen::Vector3d(frame.rotation * x + frame.translation);
  };
  result.objects.resize(objects);
  for (std::size_t o = 0; o < objects; ++o) {
    result.objects[o].outcome = report.objects[o].outcome;
    SelfReport& self = result.objects[o].report;
    static_cast<SelfCcdReport&>(self) = std::move(report.objects[o].report);
    if (self.features.empty()) continue;
    const bool world = scene.object_options(static_cast<int>(o)).self_motion == SelfMotion::kWorldLinear;
    self.geometry = self_contact_geometry(scene.detector(static_cast<int>(o)).bvh().model().mesh(), self.features,
                                          [&](int v, int end) { return position(o, v, end, world); });
  }
  for (const InterObjectFeature& f : result.features) {
    const auto first = static_cast<std::size_t>(f.object_first), second = static_cast<std::size_t>(f.object_second);
    const std::array<int, 4> v =
        contact_vertices(scene.detector(f.object_first).bvh().model().mesh(),
                         scene.detector(f.object_second).bvh().model().mesh(), f.kind, f.first, f.second);
    const int first_side = f.kind == FeatureKind::kVertexFace ? 1 : 2;
    std::array<Eigen::Vector3d, 4> start, end;
    for (int i = 0; i < 4; ++i) {
      const std::size_t object = i < first_side ? first : second;
      start[i] = position(object, v[i], 0, true);
      end[i] = position(object, v[i], 1, true);
    }
    result.geometry.add(f.kind, v, start, end, f.toi);
  }
  return result;
}

py::dict stats_dict(const SceneStats& s) {
  py::dict d;
  d["objects_static"] = s.objects_static;
  d["objects_certified"] = s.objects_certified;
  d["objects_traversed"] = s.objects_traversed;
  d["object_pairs"] = s.object_pairs;
  d["object_pairs_culled"] = s.object_pairs_culled;
  d["inter_box_tests"] = s.inter_box_tests;
  d["inter_triangle_pairs"] = s.inter_triangle_pairs;
  d["inter_kernel_calls"] = s.inter_kernel_calls;
  d["inter_vertices_computed"] = s.inter_vertices_computed;
  d["self_seconds"] = s.self_seconds;
  d["inter_seconds"] = s.inter_seconds;
  d["seconds"] = s.seconds;
  return d;
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<ObjectResult>(m, "SceneObjectResult", "One object's self-collision test in a scene step.")
      .def_property_readonly(
          "outcome", [](const ObjectResult& r) { return outcome_name(r.outcome); },
          "'traversed' (the self query ran), 'certified' (the root certificate decided the step), "
          "'static' (the object did not move), 'switched_off' or 'not_reached' (mode 'any' stopped "
          "first).")
      .def_readonly("report", &ObjectResult::report, py::return_value_policy::reference_internal,
                    "The self query's report (empty unless traversed); its geometry is in the object's frame "
                    "(in the world for a world_linear object).");

  py::class_<SceneResult>(m, "SceneReport", "The result of a scene step. Arrays are read-only views into the report.")
      .def_property_readonly(
          "objects",
          [](py::object self) {
            py::list results;
            for (const ObjectResult& r : self.cast<const SceneResult&>().objects) {
              results.append(py::cast(&r, py::return_value_policy::reference_internal, self));
            }
            return results;
          },
          "One SceneObjectResult per object, in order.")
      .def_property_readonly(
          "pairs",
          [](py::object self) {
            return index_columns(self.cast<const SceneResult&>().contacts, &InterObjectContact::object_first, 4, self);
          },
          "(k, 4) int32: colliding triangles of two objects, rows (object_first, first, object_second, "
          "second) with object_first < object_second, sorted.")
      .def_property_readonly(
          "toi", [](py::object self) { return toi_column(self.cast<const SceneResult&>().contacts, self); },
          "(k,) float64: each inter-object pair's time of impact.")
      .def_property_readonly(
          "features",
          [](py::object self) {
            return feature_arrays(self.cast<const SceneResult&>().features, &InterObjectFeature::object_first, 4, self);
          },
          "Inter-object feature contacts (sscc.Features), indices rows (object_first, first, "
          "object_second, second): the vertex of object_first against the face of object_second, or "
          "two edges.")
      .def_readonly("geometry", &SceneResult::geometry, py::return_value_policy::reference_internal,
                    "The inter-object features' contact points and normals in the world (sscc.ContactGeometry), "
                    "one row per feature; each object's self contacts have theirs in objects[i].report.geometry.")
      .def_readonly("earliest_toi", &SceneResult::earliest_toi,
                    "The earliest time of impact over everything (1.0 when nothing collided).")
      .def_readonly("collided", &SceneResult::collided, "Whether anything collided.")
      .def_property_readonly(
          "stats", [](const SceneResult& r) { return stats_dict(r.stats); }, "The step's work as a dict.")
      .def("__repr__", [](const SceneResult& r) {
        return "<sscc.SceneReport: " + std::to_string(r.objects.size()) + " objects, " +
               std::to_string(r.contacts.size()) + " inter-object pairs>";
      });

  py::class_<Scene>(m, "Scene",
                    "Several reduced deformable objects, each an instance of a detector (many instances may "
                    "share one), each with its own q and rigid frame (x_world = R x_local + t). Self-collisions "
                    "are found in each object's frame, collisions between objects for world-space linear "
                    "vertex trajectories; objects that did not move or are certified cost O(r).")
      .def(py::init<>(), "An empty scene.")
      .def(
          "add_object",
          [](Scene& scene, const SelfCcd& detector, bool self_collision, bool inter_object,
             const std::string& self_motion) {
            SceneObjectOptions options;
            options.self_collision = self_collision;
            options.inter_object = inter_object;
            if (self_motion == "world_linear") {
              options.self_motion = SelfMotion::kWorldLinear;
            } else if (self_motion != "object_frame") {
              throw py::value_error("self_motion must be 'object_frame' or 'world_linear', got '" + self_motion + "'");
            }
            return scene.add_object(detector, options);
          },
          py::arg("detector"), py::kw_only(), py::arg("self_collision") = true, py::arg("inter_object") = true,
          py::arg("self_motion") = "object_frame",
          "Adds an instance of a detector (the scene holds a copy that shares its hierarchy and "
          "certificates: no copy of them) and returns its index. "
          "self_collision / inter_object switch its tests off. self_motion: the vertex motion of its self "
          "test, 'object_frame' (linear in q in the object's frame, which moves rigidly; steps turning the "
          "frame by more than max_object_frame_rotation are refused) or 'world_linear' (straight lines in "
          "world space, as between objects).")
      .def_property_readonly("object_count", &Scene::object_count, "Number of objects.")
      .def(
          "detector",
          [](const Scene& scene, int object) {
            if (object < 0 || object >= scene.object_count()) {
              throw py::index_error("object " + std::to_string(object) + " out of range");
            }
            return &scene.detector(object);
          },
          py::arg("object"), py::return_value_policy::reference_internal,
          "Object `object`'s detector (the scene's copy, sharing the added detector's hierarchy and "
          "certificates). Raises IndexError for an index out of range.")
      .def("__repr__",
           [](const Scene& scene) { return "<sscc.Scene of " + std::to_string(scene.object_count()) + " objects>"; })
      .def(
          "step",
          [](const Scene& scene, py::object q0, py::object q1, py::object frames0, py::object frames1,
             const std::string& mode, bool use_certificates, double toi_tolerance, double minimum_separation,
             double max_object_frame_rotation) {
            const auto objects = static_cast<std::size_t>(scene.object_count());
            const auto start = per_object(q0, "q0", objects);
            const auto end = per_object(q1, "q1", objects);
            const auto start_frames = per_object(frames0, "frames0", objects);
            const auto end_frames = per_object(frames1, "frames1", objects);
            std::vector<ObjectStep> steps(objects);
            for (std::size_t i = 0; i < objects; ++i) {
              const std::string index = "[" + std::to_string(i) + "]";
              steps[i].q0 = vector_from(start[i], ("q0" + index).c_str());
              steps[i].q1 = vector_from(end[i], ("q1" + index).c_str());
              steps[i].frame0 = frame_from(start_frames[i], "frames0" + index);
              steps[i].frame1 = frame_from(end_frames[i], "frames1" + index);
            }
            SceneOptions options;
            options.mode = parse_mode(mode);
            options.use_certificates = use_certificates;
            options.kernel = kernel_options(toi_tolerance, minimum_separation);
            options.max_object_frame_rotation = max_object_frame_rotation;
            py::gil_scoped_release release;
            return with_geometry(scene, steps, scene.step(steps, options));
          },
          py::arg("q0"), py::arg("q1"), py::arg("frames0") = py::none(), py::arg("frames1") = py::none(), py::kw_only(),
          py::arg("mode") = "all", py::arg("use_certificates") = true,
          py::arg("toi_tolerance") = ccd::kDefaultToiTolerance, py::arg("minimum_separation") = 0.0,
          py::arg("max_object_frame_rotation") = kMaxObjectFrameRotation,
          "One time step. q0, q1: one coordinate vector per object (a list, or an (objects, r) array). "
          "frames0, frames1: None (identity frames) or one frame per object, each None, a 4x4 "
          "homogeneous matrix or a pair (R, t). mode and the kernel options as in SelfCcd.query. Raises "
          "ValueError for a wrong count, q of the wrong size or not finite, a frame that is not rigid, or "
          "an object-frame self test whose frame turns by more than max_object_frame_rotation (radians). "
          "Every feature contact comes with its contact points and normal (the reports' geometry).");
}

}  // namespace sscc::python
