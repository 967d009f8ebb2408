#include "demo/contact_response.hpp"

#include <algorithm>
#include <array>

#include "demo/contact_geometry.hpp"

namespace sscc::validation {

namespace {

/// One gap constraint: on one object (a self or ground contact) or two.
struct Constraint {
  int bodies = 0;
  std::array<int, 2> body{};
  std::array<Eigen::VectorXd, 2> modal;  ///< d gap / d q of each body
  std::array<Eigen::Vector3d, 2> rigid;  ///< d gap / d translation, times the body's mobility
  double gap = 0.0;                      ///< at the end of the step, before the response
  double target_gap = 0.0;
  double inverse_mass = 0.0;  ///< gap change per unit of lambda (or of impulse)
  double target_velocity = 0.0;
  double impulse = 0.0;  ///< accumulated, >= 0
};

/// The four vertices of a feature contact, in contact_frame's order.
std::array<int, 4> feature_vertices(const TriangleMesh& first_mesh, const TriangleMesh& second_mesh, FeatureKind kind,
                                    int first, int second) {
  if (kind == FeatureKind::kVertexFace) {
    const Triangle& t = second_mesh.triangles()[second];
    return {first, t[0], t[1], t[2]};
  }
  const Edge& a = first_mesh.edges()[first];
  const Edge& b = second_mesh.edges()[second];
  return {a[0], a[1], b[0], b[1]};
}

class ConstraintBuilder {
 public:
  ConstraintBuilder(const std::vector<ObjectStep>& steps, const std::vector<ResponseBody>& bodies,
                    const ContactResponseOptions& options)
      : steps_(steps), bodies_(bodies), options_(options) {
    for (std::size_t o = 0; o < bodies.size(); ++o) {
      const SubspaceModel& model = *bodies[o].model;
      q_hat_start_.push_back(model.scaled_coordinates(steps[o].q0));
      q_hat_end_.push_back(model.scaled_coordinates(steps[o].q1));
    }
  }

  /// A feature contact between `object_first` and `object_second` (equal for a self-contact).
  Constraint feature(FeatureKind kind, int object_first, int first, int object_second, int second, double toi) const {
    const TriangleMesh& first_mesh = bodies_[object_first].model->mesh();
    const std::array<int, 4> vertices =
        feature_vertices(first_mesh, bodies_[object_second].model->mesh(), kind, first, second);
    const bool self = object_first == object_second;
    std::array<Eigen::Vector3d, 4> start, end;
    std::array<int, 4> owner;
    for (int i = 0; i < 4; ++i) {
      owner[i] = i < (kind == FeatureKind::kVertexFace ? 1 : 2) ? object_first : object_second;
      // A self-contact is found in the object's frame; between objects, in the world.
      start[i] = position(owner[i], vertices[i], false, !self);
      end[i] = position(owner[i], vertices[i], true, !self);
    }
    const ContactFrame frame = contact_frame(kind, start, end, toi);
    // The normal in the world: a self-contact's gap is the same in both frames.
    const Eigen::Vector3d normal =
        self ? Eigen::Vector3d(bodies_[object_first].frame->rotation * frame.normal) : frame.normal;
    Constraint c =
        start_constraint(self ? std::vector<int>{object_first} : std::vector<int>{object_first, object_second});
    for (int i = 0; i < 4; ++i) add_point(c, owner[i], vertices[i], frame.weights[i], normal);
    c.gap = contact_gap(frame, end);
    c.target_gap = options_.separation;
    finish(c);
    return c;
  }

  Constraint plane(const PlaneContact& p) const {
    Constraint c = start_constraint({p.object});
    add_point(c, p.object, p.vertex, 1.0, p.normal);
    const Eigen::Vector3d end = position(p.object, p.vertex, true, true);
    c.gap = p.normal.dot(end) - p.offset;
    c.target_gap = 0.0;
    finish(c);
    return c;
  }

 private:
  Eigen::Vector3d position(int object, int vertex, bool at_end, bool world) const {
    const Eigen::Vector3d local =
        bodies_[object].model->position(vertex, at_end ? q_hat_end_[object] : q_hat_start_[object]);
    if (!world) return local;
    const RigidFrame& f = at_end ? steps_[object].frame1 : steps_[object].frame0;
    return f.rotation * local + f.translation;
  }

  Constraint start_constraint(const std::vector<int>& objects) const {
    Constraint c;
    c.bodies = static_cast<int>(objects.size());
    for (int k = 0; k < c.bodies; ++k) {
      c.body[k] = objects[k];
      c.modal[k] = Eigen::VectorXd::Zero(bodies_[objects[k]].model->mode_count());
      c.rigid[k].setZero();
    }
    return c;
  }

  /// Adds the gradient of weight * n . x_world of one vertex.
  void add_point(Constraint& c, int object, int vertex, double weight, const Eigen::Vector3d& normal) const {
    const int k = c.body[0] == object ? 0 : 1;
    const ResponseBody& b = bodies_[object];
    const Eigen::Vector3d local_normal = b.frame->rotation.transpose() * normal;
    c.modal[k] += weight * (b.model->scaled_basis().middleRows<3>(3 * vertex).transpose() * local_normal);
    if (b.velocity != nullptr) c.rigid[k] += weight * b.mobility.cwiseProduct(normal);
  }

  void finish(Constraint& c) const {
    for (int k = 0; k < c.bodies; ++k) {
      const ResponseBody& b = bodies_[c.body[k]];
      // The scaled basis' rows times sqrt(weights) are the mass-normalised modes' rows.
      c.modal[k] = c.modal[k].cwiseProduct(b.model->weights().cwiseSqrt());
      c.inverse_mass += c.modal[k].squaredNorm() + c.rigid[k].squaredNorm() / b.mass;
    }
  }

  const std::vector<ObjectStep>& steps_;
  const std::vector<ResponseBody>& bodies_;
  const ContactResponseOptions& options_;
  std::vector<Eigen::VectorXd> q_hat_start_, q_hat_end_;
};

/// The change of the constraint's gap (or normal velocity) for body changes dq, dt.
double change(const Constraint& c, const std::vector<Eigen::VectorXd>& dq, const std::vector<Eigen::Vector3d>& dt) {
  double d = 0.0;
  for (int k = 0; k < c.bodies; ++k) d += c.modal[k].dot(dq[c.body[k]]) + c.rigid[k].dot(dt[c.body[k]]);
  return d;
}

void apply(const Constraint& c, double amount, const std::vector<ResponseBody>& bodies,
           std::vector<Eigen::VectorXd>& dq, std::vector<Eigen::Vector3d>& dt) {
  for (int k = 0; k < c.bodies; ++k) {
    dq[c.body[k]] += amount * c.modal[k];
    dt[c.body[k]] += amount * c.rigid[k] / bodies[c.body[k]].mass;
  }
}

}  // namespace

int ResponseRecord::constraints() const {
  std::size_t n = inter.size() + static_cast<std::size_t>(ground);
  for (const auto& s : self) n += s.size();
  return static_cast<int>(n);
}

ResponseRecord respond_to_contacts(const SceneReport& report, const std::vector<ObjectStep>& steps,
                                   const std::vector<ResponseBody>& bodies, const std::vector<PlaneContact>& ground,
                                   const ContactResponseOptions& options) {
  const std::size_t n = bodies.size();
  ResponseRecord record;
  record.self.resize(n);
  const ConstraintBuilder build(steps, bodies, options);
  std::vector<Constraint> constraints;
  for (std::size_t o = 0; o < n && o < report.objects.size(); ++o) {
    for (const FeatureContact& f : report.objects[o].report.features) {
      const int object = static_cast<int>(o);
      constraints.push_back(build.feature(f.kind, object, f.first, object, f.second, f.toi));
      record.self[o].push_back(f);
    }
  }
  for (const InterObjectFeature& f : report.features) {
    constraints.push_back(build.feature(f.kind, f.object_first, f.first, f.object_second, f.second, f.toi));
    record.inter.push_back(f);
  }
  for (const PlaneContact& p : ground) {
    constraints.push_back(build.plane(p));
    ++record.ground;
  }
  if (constraints.empty()) return record;

  std::vector<Eigen::VectorXd> dq(n), velocity(n);
  std::vector<Eigen::Vector3d> dt(n, Eigen::Vector3d::Zero()), rigid_velocity(n, Eigen::Vector3d::Zero());
  for (std::size_t o = 0; o < n; ++o) {
    dq[o] = Eigen::VectorXd::Zero(bodies[o].model->mode_count());
    velocity[o] = bodies[o].modes->velocity();
    if (bodies[o].velocity != nullptr) rigid_velocity[o] = *bodies[o].velocity;
  }
  for (const Constraint& c : constraints) record.deepest_penetration = std::max(record.deepest_penetration, -c.gap);

  // 1. Positions: push each gap up to its target (a constraint met is left alone).
  for (int sweep = 0; sweep < options.iterations; ++sweep) {
    for (const Constraint& c : constraints) {
      const double gap = c.gap + change(c, dq, dt);
      if (gap < c.target_gap && c.inverse_mass > 0) apply(c, (c.target_gap - gap) / c.inverse_mass, bodies, dq, dt);
    }
  }
  for (const Constraint& c : constraints) {
    record.residual_penetration = std::max(record.residual_penetration, -(c.gap + change(c, dq, dt)));
  }

  // 2. Velocities: accumulated impulses j >= 0 until each contact point separates at least
  // as fast as restitution times its approach speed.
  std::vector<Eigen::VectorXd> dv(n);
  std::vector<Eigen::Vector3d> dV(n, Eigen::Vector3d::Zero());
  for (std::size_t o = 0; o < n; ++o) dv[o] = Eigen::VectorXd::Zero(velocity[o].size());
  for (Constraint& c : constraints) {
    const double approach = change(c, velocity, rigid_velocity);
    c.target_velocity = approach < 0 ? -options.restitution * approach : 0.0;
  }
  for (int sweep = 0; sweep < options.iterations; ++sweep) {
    for (Constraint& c : constraints) {
      if (!(c.inverse_mass > 0)) continue;
      const double normal_velocity = change(c, velocity, rigid_velocity) + change(c, dv, dV);
      const double accumulated = std::max(0.0, c.impulse + (c.target_velocity - normal_velocity) / c.inverse_mass);
      apply(c, accumulated - c.impulse, bodies, dv, dV);
      c.impulse = accumulated;
    }
  }

  for (std::size_t o = 0; o < n; ++o) {
    bodies[o].modes->displace(dq[o]);
    bodies[o].modes->add_impulse(dv[o]);
    if (bodies[o].velocity != nullptr) {
      bodies[o].frame->translation += dt[o];
      *bodies[o].velocity += dV[o];
    }
  }
  return record;
}

}  // namespace sscc::validation
