// A simulator loop around the library, for a newcomer: one rubber bunny, fixed in place,
// vibrating in its lowest modes after strikes on an ear; its self-collisions are detected
// every time step and answered, so that it never passes through itself.
//
//   simulator_loop MESH.off [STEPS [STRIKE]]    (STRIKE: the impulse in N s, default kStrikeImpulse)
//
// The steps every simulator of reduced (subspace) objects takes:
//   1. once: load the mesh, compute its basis U (modal analysis), build the detector and its
//      certificates (precomputed once; a real program writes them to a file and reads them
//      back on later runs, Certificates::write / read);
//   2. every time step: integrate q0 -> q1, call the scene's CCD for the straight-line step
//      q0 -> q1, respond to what it reports, and go on from the state the response left.
//
// The response here is the simplest honest one: a step that would collide is cut short
// just before its earliest time of impact (the library's toi is never later than the true
// first contact, so the shortened step is free of contact), and the deformation velocity
// is reversed and damped (a restitution of kRestitution), so the parts that met move
// apart. It is global, not local: a simulator that wants local impulses uses the reported
// features (vertex-face and edge-edge pairs, with their toi) to apply forces at the contact
// points and maps them into the modes with U^T f, as the strike below does.
//
// The program checks itself: every step it takes is queried again and must be free of
// contact, and the final shape must not intersect itself (exact discrete test). It exits
// with status 1 otherwise.
#include <Eigen/Core>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "sscc/sscc.hpp"

namespace {

constexpr double kTimeStep = 0.001;       // s; the stiffest mode (~90 Hz on the 1k bunny, printed) spans 11 steps;
                                          // semi-implicit Euler needs omega dt < 2
constexpr int kModes = 12;                // modal coordinates simulated (and in the basis)
constexpr double kDampingRatio = 0.02;    // per mode: rubber rings for a few hundred steps
constexpr double kRestitution = 0.5;      // fraction of the deformation velocity kept, reversed, at a contact
constexpr double kBackoff = 0.9;          // a colliding step is cut at this fraction of its toi
constexpr int kStrikeEvery = 250;         // steps between strikes
constexpr double kStrikeImpulse = 200.0;  // N s, at the top vertex of an ear: the ears meet now and then

/// Modal coordinates and their velocities: q'' + 2 zeta omega q' + omega^2 q = U^T f, since
/// the modes are mass-normalised (U^T M U = I).
struct ModalState {
  Eigen::VectorXd q, v;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: simulator_loop MESH.off [STEPS [STRIKE]]\n";
    return 2;
  }
  const int steps = argc > 2 ? std::atoi(argv[2]) : 1000;
  const double strike_impulse = argc > 3 ? std::atof(argv[3]) : kStrikeImpulse;

  // 1. Once: the mesh, its modal basis, the detector with its certificates, a scene.
  sscc::TriangleMesh mesh = sscc::read_mesh(argv[1]);
  sscc::ElasticBasisOptions basis_options;
  basis_options.modes = kModes;
  basis_options.material = {2.0e7, 0.4, 1100.0};  // stiff rubber: Young's modulus (Pa), Poisson ratio, kg/m^3
  const sscc::ElasticBasis modal = sscc::modal_basis(mesh, basis_options);
  const Eigen::VectorXd omega = 2.0 * M_PI * modal.frequencies_hz;  // rad/s per mode
  // Weights omega^2 / 2: ||q||_M^2 is the strain energy, the norm the certificates bound.
  const sscc::SubspaceModel model(mesh, modal.basis, modal.weights);
  const sscc::SubspaceBvh bvh(model);
  const sscc::Certificates certificates = sscc::Certificates::precompute(bvh);
  const sscc::SelfCcd detector(bvh, certificates);
  sscc::Scene scene;
  scene.add_object(detector);  // more objects: add_object again, with their own frames
  std::cout << "bunny: " << mesh.triangle_count() << " triangles, " << model.mode_count() << " modes ("
            << modal.frequencies_hz[0] << " to " << modal.frequencies_hz[kModes - 1]
            << " Hz); certified free of self-contact while ||q||_M < " << certificates.node_radius(0) << "\n";

  // The strike: an impulse J at the ear's top vertex, towards the other ear, becomes the
  // modal velocity change U_v^T J (v the vertex; U_v its three rows of the basis).
  int top = 0;
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    if (mesh.vertices()[v].y() > mesh.vertices()[top].y()) top = v;
  }
  const Eigen::Vector3d impulse(-strike_impulse, 0.0, 0.0);
  const Eigen::VectorXd strike = modal.basis.middleRows<3>(3 * top).transpose() * impulse;

  ModalState state{Eigen::VectorXd::Zero(kModes), Eigen::VectorXd::Zero(kModes)};
  int colliding_steps = 0, certified_steps = 0, failures = 0;
  for (int step = 0; step < steps; ++step) {
    // 2a. Integrate (semi-implicit Euler, per mode): the end of the step, q1.
    if (step % kStrikeEvery == 0) state.v += (step / kStrikeEvery % 2 == 0 ? 1.0 : -1.0) * strike;
    const Eigen::VectorXd acceleration =
        -omega.cwiseAbs2().cwiseProduct(state.q) - 2.0 * kDampingRatio * omega.cwiseProduct(state.v);
    Eigen::VectorXd v1 = state.v + kTimeStep * acceleration;
    Eigen::VectorXd q1 = state.q + kTimeStep * v1;

    // 2b. The scene's CCD for the straight-line step q0 -> q1 (the frames stay the identity:
    // the bunny is fixed; a moving object gives frame0 and frame1).
    sscc::ObjectStep motion;
    motion.q0 = state.q;
    motion.q1 = q1;
    const sscc::SceneReport report = scene.step({motion});
    certified_steps += report.objects[0].outcome == sscc::SelfTestOutcome::kCertified;

    // 2c. Respond: stop just before the first contact, and send the parts apart.
    if (report.collided()) {
      ++colliding_steps;
      const double t = kBackoff * report.earliest_toi;
      q1 = state.q + t * (q1 - state.q);
      v1 = -kRestitution * v1;
      // The step actually taken must be free of contact (see the top of the file).
      motion.q1 = q1;
      if (scene.step({motion}).collided()) {
        std::cerr << "step " << step << ": the shortened step still collides\n";
        ++failures;
      }
    }
    state = {q1, v1};
  }

  // The final shape: no two non-adjacent triangles intersect (exact test, no certificates).
  sscc::SelfCcdOptions exact;
  exact.use_certificates = false;
  const bool intersects = detector.query_discrete(state.q, exact).collided();
  std::cout << steps << " steps of " << kTimeStep << " s: " << colliding_steps << " with self-contact (answered), "
            << certified_steps << " certified by the root in O(r); final shape "
            << (intersects ? "INTERSECTS itself" : "free of self-intersection") << "\n";
  return failures == 0 && !intersects ? 0 : 1;
}
