#include "demo/demo_scene.hpp"

namespace sscc::validation {

DemoScene::DemoScene(const SubspaceModel& model, double mass, const SceneMotionOptions& motion,
                     const ContactResponseOptions& response)
    : model_(model),
      mass_(mass),
      motion_(motion),
      response_(response),
      rest_box_(model.mesh().bounding_box()),
      rng_(motion.seed) {}

ModalDynamics DemoScene::modes_at_rest() const {
  return ModalDynamics(2.0 * model_.weights(), motion_.damping_ratio, motion_.dt);
}

ResponseRecord DemoScene::respond(const SceneReport& report, const std::vector<ObjectStep>& steps) {
  const std::vector<ResponseBody> bodies = response_bodies();
  double before = 0.0;
  for (const ResponseBody& b : bodies) before += b.modes->velocity().sum();
  ResponseRecord record = respond_to_contacts(report, steps, bodies, ground_contacts(), response_);
  double after = 0.0;
  for (const ResponseBody& b : bodies) after += b.modes->velocity().sum();
  contact_acceleration_ = (after - before) / motion_.dt;  // the step's mean contact force, per unit modal mass
  return record;
}

std::vector<Eigen::VectorXd> DemoScene::configurations() {
  std::vector<Eigen::VectorXd> q;
  for (const ResponseBody& b : response_bodies()) q.push_back(b.modes->q());
  return q;
}

double DemoScene::modal_sound() {
  double pressure = contact_acceleration_;
  for (const ResponseBody& b : response_bodies()) pressure += b.modes->acceleration().sum();
  return pressure;
}

}  // namespace sscc::validation
