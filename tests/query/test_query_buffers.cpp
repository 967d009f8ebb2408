// A detector lends each query the buffers (positions, their query numbers, the box and cone caches)
// of a finished one (step_buffers.hpp). Whatever ran before on the detector, a query reports
// what the same query reports on a fresh detector: steps of very different norms, with and
// without certificates, every query kind, one thread and several, in turn and from two
// threads at once. One-thread queries match the fresh ones' counters too (a box, cone,
// verdict or position left known by an earlier step would change them even when the contacts
// happened to agree).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "certificates/certificate_fixtures.hpp"
#include "sscc/query/self_ccd.hpp"
#include "support/parametric_meshes.hpp"

namespace {

using Eigen::Vector3d;

struct Step {
  Eigen::VectorXd q0, q1;
  std::vector<Vector3d> x0, x1;  // the positions at both ends, for query_positions
};

/// One query kind with its options. `serial`: on one thread, whose counters are deterministic.
struct Call {
  std::string name;
  bool serial;
  std::function<sscc::SelfCcdReport(const sscc::SelfCcd&, const Step&)> run;
};

sscc::SelfCcdOptions on_threads(int threads, sscc::SelfCcdMode mode = sscc::SelfCcdMode::kAllContacts) {
  sscc::SelfCcdOptions options;
  options.threads = threads;
  options.mode = mode;
  return options;
}

/// Every kind of context a detector lends buffers to: query with certificates (lazy vertices
/// near the root's radius) and without (the cones and the displacement bounds), on one
/// thread and on several (shared positions), the traditional query on subspace boxes,
/// query_positions, query_exhaustive.
std::vector<Call> calls() {
  std::vector<Call> all;
  const auto query = [](sscc::SelfCcdOptions options) {
    return [options](const sscc::SelfCcd& ccd, const Step& s) { return ccd.query(s.q0, s.q1, options); };
  };
  all.push_back({"defaults, 1 thread", true, query(on_threads(1))});
  all.push_back({"defaults, 3 threads", false, query(on_threads(3))});
  sscc::SelfCcdOptions uncertified = on_threads(1, sscc::SelfCcdMode::kEarliest);
  uncertified.use_certificates = false;
  all.push_back({"cones and bounds, earliest, 1 thread", true, query(uncertified)});
  uncertified.threads = 2;
  uncertified.mode = sscc::SelfCcdMode::kAllContacts;
  all.push_back({"cones and bounds, 2 threads", false, query(uncertified)});
  sscc::SelfCcdOptions cones = on_threads(1);
  sscc::set_traditional(cones);
  cones.use_normal_cones = true;
  cones.bounds = sscc::NodeBounds::kRefit;
  all.push_back({"cones on refitted boxes, 1 thread", true, query(cones)});
  sscc::SelfCcdOptions subspace = on_threads(2, sscc::SelfCcdMode::kAnyHit);
  sscc::set_traditional(subspace);
  subspace.bounds = sscc::NodeBounds::kSubspace;
  all.push_back({"traditional on subspace boxes, any hit, 2 threads", false, query(subspace)});
  const auto positions = [](sscc::SelfCcdOptions options) {
    return [options](const sscc::SelfCcd& ccd, const Step& s) { return ccd.query_positions(s.x0, s.x1, options); };
  };
  all.push_back({"positions with cones, 1 thread", true, positions(on_threads(1))});
  all.push_back({"positions, earliest, 2 threads", false, positions(on_threads(2, sscc::SelfCcdMode::kEarliest))});
  all.push_back(
      {"exhaustive", true, [](const sscc::SelfCcd& ccd, const Step& s) { return ccd.query_exhaustive(s.q0, s.q1); }});
  return all;
}

/// `chained`: `reused` continued the detector's last query (its boxes moved from that
/// query's cull node pairs sooner; its nodes merge their children's moved boxes instead of
/// refitting down to the triangles, so it may visit more nodes and compute vertices a fresh
/// query does not): the same triangle pairs and kernels.
void require_same_report(const sscc::SelfCcdReport& reused, const sscc::SelfCcdReport& fresh, bool serial,
                         bool chained = false) {
  REQUIRE(reused.pairs == fresh.pairs);
  REQUIRE(reused.features == fresh.features);
  REQUIRE(reused.earliest_toi == fresh.earliest_toi);
  REQUIRE(reused.stats.root_certified == fresh.stats.root_certified);
  if (!serial) return;  // the threads' shares, hence their counters, vary from run to run
  REQUIRE(fresh.stats.moved_box_culled == 0);
  if (chained) {
    REQUIRE(reused.stats.triangle_pairs == fresh.stats.triangle_pairs);
    REQUIRE(reused.stats.kernel_calls == fresh.stats.kernel_calls);
    return;
  }
  REQUIRE(reused.stats.moved_box_culled == 0);
  REQUIRE(reused.stats.nodes_visited == fresh.stats.nodes_visited);
  REQUIRE(reused.stats.box_tests == fresh.stats.box_tests);
  REQUIRE(reused.stats.triangle_pairs == fresh.stats.triangle_pairs);
  REQUIRE(reused.stats.kernel_calls == fresh.stats.kernel_calls);
  REQUIRE(reused.stats.vertices_computed == fresh.stats.vertices_computed);
  REQUIRE(reused.stats.certified == fresh.stats.certified);
  REQUIRE(reused.stats.cone_culled == fresh.stats.cone_culled);
  REQUIRE(reused.stats.cone_radius_culled == fresh.stats.cone_radius_culled);
  REQUIRE(reused.stats.displacement_culled == fresh.stats.displacement_culled);
}

/// What the culls did over a run, so that the test shows the caches were exercised.
struct Tally {
  long radius_culled = 0, formed_cone_culled = 0, displacement_culled = 0, certified = 0;
  int colliding = 0, clear = 0;
  void add(const sscc::SelfCcdReport& report) {
    radius_culled += report.stats.cone_radius_culled;
    formed_cone_culled += report.stats.cone_culled - report.stats.cone_radius_culled;
    displacement_culled += report.stats.displacement_culled;
    certified += report.stats.certified;
    (report.collided() ? colliding : clear) += 1;
  }
};

/// Runs every call on every step on `reused`, each call kind after every other (the order
/// rotates with the step), against a fresh detector per call; then the same calls from two
/// threads at once, one on `reused` and one on a copy of it (copies share the buffers), each
/// in its own order, against the fresh reports.
Tally check_reuse(const sscc::SelfCcd& reused, const std::vector<Step>& steps) {
  const std::vector<Call> kinds = calls();
  const int count = static_cast<int>(kinds.size());
  const auto fresh_detector = [&] {
    return sscc::SelfCcd(
        std::make_shared<const sscc::SubspaceBvh>(reused.bvh()),
        reused.certificates() ? std::make_shared<const sscc::Certificates>(*reused.certificates()) : nullptr);
  };
  Tally tally;
  std::vector<std::vector<sscc::SelfCcdReport>> fresh(steps.size(), std::vector<sscc::SelfCcdReport>(kinds.size()));
  for (std::size_t i = 0; i < steps.size(); ++i) {
    for (int k = 0; k < count; ++k) {
      const int c = (k + static_cast<int>(i)) % count;
      const Call& call = kinds[c];
      INFO("step " << i << ", " << call.name);
      fresh[i][c] = call.run(fresh_detector(), steps[i]);
      const sscc::SelfCcdReport report = call.run(reused, steps[i]);
      require_same_report(report, fresh[i][c], call.serial);
      REQUIRE(report.stats.vertex_starts_reused == 0);  // no query here starts where the one before ended
      tally.add(report);
    }
    // A rejected query in between: it throws before borrowing anything.
    REQUIRE_THROWS_AS(reused.query_positions(steps[i].x0, {}, on_threads(1)), std::invalid_argument);
  }
  const sscc::SelfCcd copy = reused;
  std::vector<std::vector<sscc::SelfCcdReport>> first(steps.size(), std::vector<sscc::SelfCcdReport>(kinds.size()));
  std::vector<std::vector<sscc::SelfCcdReport>> second = first;
  const auto worker = [&](const sscc::SelfCcd& ccd, std::vector<std::vector<sscc::SelfCcdReport>>& out, int stride) {
    for (std::size_t i = 0; i < steps.size(); ++i) {
      for (int k = 0; k < count; ++k) {
        const int c = (stride * k + static_cast<int>(i)) % count;
        out[i][c] = kinds[c].run(ccd, steps[i]);
      }
    }
  };
  // Strides 1 and 2 (count is odd: both visit every kind) put different kinds side by side.
  REQUIRE(count % 2 == 1);
  std::thread other(worker, std::cref(copy), std::ref(second), 2);
  worker(reused, first, 1);
  other.join();
  for (std::size_t i = 0; i < steps.size(); ++i) {
    for (int c = 0; c < count; ++c) {
      INFO("concurrent, step " << i << ", " << kinds[c].name);
      // Two threads may interleave so that a query starts where the other thread's last one on
      // the same buffers ended (the torus's steps share keyframes): it then continues it.
      for (const sscc::SelfCcdReport* report : {&first[i][c], &second[i][c]}) {
        const bool continued = report->stats.vertex_starts_reused > 0 || report->stats.moved_box_culled > 0;
        require_same_report(*report, fresh[i][c], kinds[c].serial, continued);
      }
    }
  }
  return tally;
}

Step step_of(const sscc::SubspaceModel& model, Eigen::VectorXd q0, Eigen::VectorXd q1) {
  Step s{std::move(q0), std::move(q1), {}, {}};
  s.x0 = model.deformed_positions(s.q0);
  s.x1 = model.deformed_positions(s.q1);
  return s;
}

}  // namespace

TEST_CASE(
    "query buffers: a certified sphere's steps from inside the root's radius to far past it (certificates, "
    "formed cones), any order",
    "[query][parallel]") {
  const auto sphere = sscc::test::certified_sphere();
  const sscc::SelfCcd ccd(sphere->bvh, sphere->certificates);
  const double root = sphere->certificates.node_radius(0);
  std::mt19937_64 rng(41);
  std::vector<Step> steps;
  // Mixed so that each step follows one of a very different norm: the caches of a step that
  // collides before one that does not, lazy vertices (near the root) after shared ones.
  for (double factor : {20.0, 1.5, 0.5, 8.0, 1.2, 40.0, 3.0, 1.8}) {
    const Eigen::VectorXd q0 = sscc::test::random_scaled_coordinates(rng, 27, factor * root);
    const Eigen::VectorXd q1 = sscc::test::random_scaled_coordinates(rng, 27, factor * root);
    steps.push_back(step_of(sphere->model, q0, q1));
  }
  const Tally tally = check_reuse(ccd, steps);
  CHECK(tally.colliding >= 10);
  CHECK(tally.clear >= 10);
  CHECK(tally.certified > 0);
  CHECK(tally.formed_cone_culled > 0);
}

TEST_CASE("query buffers: a pinched torus's keyframes (displacement bounds, the cones' radii), any order",
          "[query][parallel]") {
  std::vector<std::vector<Vector3d>> frames;
  for (double pinch : {0.0, 0.6, 0.95, 1.0, 1.05}) {
    frames.push_back(sscc::test::grid_positions(40, 10, true, true, sscc::test::pinched_torus(pinch)));
  }
  const sscc::SubspaceModel model = sscc::test::keyframe_model(sscc::test::grid_triangles(40, 10, true, true), frames);
  const sscc::SubspaceBvh bvh(model);
  const sscc::SelfCcd ccd(bvh, sscc::Certificates::precompute(bvh));
  const int modes = model.mode_count();
  std::vector<Step> steps;
  // Shut, open, small and large steps in turn, two scaled down.
  for (const auto& [from, to, scale] : std::vector<std::tuple<int, int, double>>{
           {3, 4, 1.0}, {0, 1, 1.0}, {0, 4, 1.0}, {1, 2, 1.0}, {0, 3, 1.0}, {0, 2, 0.05}, {2, 3, 1.0}, {0, 1, 0.01}}) {
    steps.push_back(
        step_of(model, scale * sscc::test::keyframe_q(modes, from), scale * sscc::test::keyframe_q(modes, to)));
  }
  const Tally tally = check_reuse(ccd, steps);
  CHECK(tally.colliding >= 10);
  CHECK(tally.clear >= 10);
  CHECK(tally.displacement_culled > 0);
  CHECK(tally.radius_culled > 0);
}

TEST_CASE(
    "query buffers: a simulator's consecutive steps start from the previous step's end positions, reporting what "
    "fresh detectors and exhaustive testing do",
    "[query]") {
  const auto sphere = sscc::test::certified_sphere();
  const sscc::SelfCcd ccd(sphere->bvh, sphere->certificates);
  const double root = sphere->certificates.node_radius(0);
  std::mt19937_64 rng(43);
  // A closed path in q_hat between 1 and about 2.6 root radii (the steps computing vertices
  // on demand, some colliding), in small steps; a jump to an unrelated pose in the middle,
  // whose start is not the previous end.
  const Eigen::VectorXd centre = sscc::test::random_scaled_coordinates(rng, 27, 1.8 * root);
  const Eigen::VectorXd u = sscc::test::random_scaled_coordinates(rng, 27, 0.8 * root);
  const Eigen::VectorXd w = sscc::test::random_scaled_coordinates(rng, 27, 0.8 * root);
  const int count = 40;
  std::vector<Step> steps;
  for (int k = 0; k < count; ++k) {
    const auto at = [&](int i) {
      const double angle = 2.0 * M_PI * i / count;
      return Eigen::VectorXd(centre + std::cos(angle) * u + std::sin(angle) * w);
    };
    if (k == count / 2) {
      steps.push_back(step_of(sphere->model, at(k + 7), at(k + 1)));  // a jump
      continue;
    }
    steps.push_back(step_of(sphere->model, at(k), at(k + 1)));
  }
  // Exhaustive testing on another detector, so that each query of the chain follows the last.
  const sscc::SelfCcd reference(std::make_shared<const sscc::SubspaceBvh>(ccd.bvh()), nullptr);
  sscc::SelfCcdOptions options = on_threads(1);
  long reused = 0, computed = 0, moved_box_culled = 0;
  int colliding = 0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    INFO("step " << i);
    const sscc::SelfCcdReport report = ccd.query(steps[i].q0, steps[i].q1, options);
    const sscc::SelfCcd fresh(std::make_shared<const sscc::SubspaceBvh>(ccd.bvh()),
                              std::make_shared<const sscc::Certificates>(*ccd.certificates()));
    const sscc::SelfCcdReport expected = fresh.query(steps[i].q0, steps[i].q1, options);
    require_same_report(report, expected, true, true);
    REQUIRE(expected.stats.vertex_starts_reused == 0);
    REQUIRE(report.stats.vertex_starts_reused <= report.stats.vertices_computed);
    if (i == 0 || static_cast<int>(i) == count / 2) REQUIRE(report.stats.vertex_starts_reused == 0);
    REQUIRE(report.pairs == reference.query_exhaustive(steps[i].q0, steps[i].q1).pairs);
    if (i == 0 || static_cast<int>(i) == count / 2) REQUIRE(report.stats.moved_box_culled == 0);
    reused += report.stats.vertex_starts_reused;
    computed += report.stats.vertices_computed;
    moved_box_culled += report.stats.moved_box_culled;
    colliding += report.collided() ? 1 : 0;
  }
  CHECK(colliding >= 3);
  CHECK(colliding < count);
  // Most vertices a step reaches were reached by the previous one too.
  CHECK(reused > computed / 2);
  CHECK(moved_box_culled > 0);
}

TEST_CASE("query buffers: chained steps hand their end positions on, lazy to lazy, shared to lazy, partially",
          "[query]") {
  // A sphere whose modes move only its upper part (zero below z = 0.2): near the root's
  // radius a step reaches part of the mesh, a different part at each norm, so vertices are
  // known at one step's end and not the next's, then reached again.
  const sscc::TriangleMesh mesh = sscc::test::uv_sphere(16, 32);
  Eigen::MatrixXd basis = sscc::polynomial_basis(mesh, 27);
  for (int v = 0; v < mesh.vertex_count(); ++v)
    basis.middleRows(3 * v, 3) *= std::max(0.0, mesh.vertices()[v].z() - 0.2);
  const auto model = std::make_unique<sscc::test::CertifiedModel>(mesh, basis, Eigen::VectorXd::Ones(27));
  const sscc::SelfCcd ccd(model->bvh, model->certificates);
  const auto fresh_detector = [&] {
    return sscc::SelfCcd(std::make_shared<const sscc::SubspaceBvh>(ccd.bvh()),
                         std::make_shared<const sscc::Certificates>(*ccd.certificates()));
  };
  const sscc::SelfCcd reference = fresh_detector();  // exhaustive testing off the chain's buffers
  const double root = model->certificates.node_radius(0);
  std::mt19937_64 rng(43);
  const Eigen::VectorXd d = sscc::test::random_scaled_coordinates(rng, 27, 1.0).normalized();
  const Eigen::VectorXd u = sscc::test::random_scaled_coordinates(rng, 27, 1.0).normalized();
  const int count = 60;
  // Norms from just past the root's radius to 2.0005 of it and back, three times: lazy steps
  // near the root, shared positions on two threads past twice its radius.
  const auto at = [&](int i) {
    const double a = 2.0 * M_PI * i / count;
    const Eigen::VectorXd q_hat =
        (std::cos(a) * d + std::sin(a) * u).normalized() * root * (1.0005 + 0.5 * (1.0 - std::cos(3.0 * a)));
    return Eigen::VectorXd(q_hat.cwiseQuotient(model->model.weights().cwiseSqrt()));
  };
  sscc::SelfCcdOptions options = on_threads(2);
  long previous_computed = 0;
  int partial = 0;
  for (int k = 0; k < count; ++k) {
    INFO("step " << k);
    const Eigen::VectorXd q0 = at(k), q1 = at(k + 1);
    const sscc::SelfCcdReport report = ccd.query(q0, q1, options);
    const sscc::SelfCcdReport expected = fresh_detector().query(q0, q1, options);
    // Counters compared on the steps that run on one thread (the others' shares vary).
    require_same_report(report, expected, ccd.query_threads(q0, q1, options) == 1, true);
    REQUIRE(report.pairs == reference.query_exhaustive(q0, q1).pairs);
    // Only what the previous step (on the same buffers: one thread, nothing in between) computed.
    REQUIRE(report.stats.vertex_starts_reused <= previous_computed);
    previous_computed = report.stats.vertices_computed;
    partial +=
        report.stats.vertex_starts_reused > 0 && report.stats.vertex_starts_reused < report.stats.vertices_computed;
  }
  CHECK(partial > 0);
}

TEST_CASE(
    "query buffers: steps far past the certificates, every vertex up front on two threads, start from the previous "
    "step's end; given positions in between break the chain",
    "[query]") {
  const auto sphere = sscc::test::certified_sphere();
  const sscc::SelfCcd ccd(sphere->bvh, sphere->certificates);
  const sscc::SelfCcd reference(std::make_shared<const sscc::SubspaceBvh>(ccd.bvh()), nullptr);
  const double root = sphere->certificates.node_radius(0);
  const int vertices = sphere->model.mesh().vertex_count();
  std::mt19937_64 rng(47);
  // A closed path between about 3 and 5 root radii: past twice the root's (kFarPastCertificateRatio).
  const Eigen::VectorXd centre = sscc::test::random_scaled_coordinates(rng, 27, 4.0 * root);
  const Eigen::VectorXd u = sscc::test::random_scaled_coordinates(rng, 27, 0.7 * root);
  const Eigen::VectorXd w = sscc::test::random_scaled_coordinates(rng, 27, 0.7 * root);
  const int count = 12;
  const auto at = [&](int i) {
    const double angle = 2.0 * M_PI * i / count;
    return Eigen::VectorXd(centre + std::cos(angle) * u + std::sin(angle) * w);
  };
  const sscc::SelfCcdOptions options = on_threads(2);
  int colliding = 0;
  for (int k = 0; k < count; ++k) {
    INFO("step " << k);
    const Step step = step_of(sphere->model, at(k), at(k + 1));
    REQUIRE(ccd.query_threads(step.q0, step.q1, options) == 2);
    const sscc::SelfCcdReport report = ccd.query(step.q0, step.q1, options);
    const sscc::SelfCcd fresh(std::make_shared<const sscc::SubspaceBvh>(ccd.bvh()),
                              std::make_shared<const sscc::Certificates>(*ccd.certificates()));
    require_same_report(report, fresh.query(step.q0, step.q1, on_threads(1)), false);
    REQUIRE(report.pairs == reference.query_exhaustive(step.q0, step.q1).pairs);
    // Every vertex computed once, up front, whatever the threads; its start reused from the
    // second step on, except after the positions query.
    REQUIRE(report.stats.vertices_computed == vertices);
    const bool continues = k > 0 && k != count / 2 + 1;
    REQUIRE(report.stats.vertex_starts_reused == (continues ? vertices : 0));
    if (k == count / 2) {
      const sscc::SelfCcdReport given = ccd.query_positions(step.x0, step.x1, options);
      REQUIRE(given.pairs == report.pairs);
    }
    colliding += report.collided() ? 1 : 0;
  }
  CHECK(colliding > 0);
}
