#include "demo/demo_scene.hpp"

namespace sscc::validation {

DemoScene::DemoScene(const SubspaceModel& model, double mass, const SceneMotionOptions& motion)
    : model_(model), mass_(mass), motion_(motion), rest_box_(model.mesh().bounding_box()), rng_(motion.seed) {}

ModalDynamics DemoScene::modes_at_rest() const {
  return ModalDynamics(2.0 * model_.weights(), motion_.damping_ratio, motion_.dt);
}

}  // namespace sscc::validation
