// The normal-cone cull in the traversal against exhaustive testing and an independent brute
// force, on generated meshes with folds, pinches and touching coils moved through keyframes
// (steps that end in contact, folds beyond 90 degrees); and the cull itself refusing a
// patch whose normals stay in a cone but whose contour overlaps itself.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "brute_force.hpp"
#include "query/patch_cull.hpp"
#include "sscc/certificates/certificates.hpp"
#include "sscc/query/self_ccd.hpp"
#include "support/parametric_meshes.hpp"

namespace {

using Eigen::Vector3d;
using sscc::test::Surface;

struct Keyframes {
  std::string name;
  int nu, nv;
  bool wrap_u, wrap_v;
  std::vector<Surface> shapes;  // keyframe k
};

/// A strip [-1, 1] x [0, 0.6] folded about x = 0 by `angle` (its right half turned up and over).
Surface folded_sheet(double angle) {
  return [angle](double u, double v) {
    const double x = -1.0 + 2.0 * u;
    if (x <= 0) return Vector3d(x, 0.6 * v, 0.0);
    return Vector3d(x * std::cos(angle), 0.6 * v, x * std::sin(angle));
  };
}

/// A ramp winding 1.5 turns about z (radii 0.5 to 1), rising `pitch` per turn: its normals
/// stay near the z axis while its projection covers part of the annulus twice.
Surface spiral_ramp(double pitch) {
  return [pitch](double u, double v) {
    const double phi = 3 * M_PI * u, w = 0.5 + 0.5 * v;
    return Vector3d(w * std::cos(phi), w * std::sin(phi), pitch * phi / (2 * M_PI));
  };
}

std::vector<Keyframes> cases() {
  std::vector<Keyframes> all;
  all.push_back({"folding sheet", 16, 5, false, false, {}});
  for (double degrees : {0.0, 45.0, 100.0, 150.0, 175.0, 180.0, 185.0})
    all.back().shapes.push_back(folded_sheet(degrees * M_PI / 180));
  all.push_back({"pinched torus", 40, 10, true, true, {}});
  for (double pinch : {0.0, 0.6, 0.95, 1.0, 1.05}) all.back().shapes.push_back(sscc::test::pinched_torus(pinch));
  all.push_back({"helix tube", 60, 8, false, true, {}});
  for (double pitch : {0.5, 0.3, 0.21, 0.2, 0.19}) all.back().shapes.push_back(sscc::test::helix_tube(pitch));
  all.push_back({"spiral ramp", 36, 3, false, false, {}});
  for (double pitch : {0.3, 0.1, 0.0}) all.back().shapes.push_back(spiral_ramp(pitch));
  return all;
}

/// cases() and a finer fold, for nodes large enough to be tested in pairs (kSmallestUnionPart).
std::vector<Keyframes> cases_with_fine_sheet() {
  std::vector<Keyframes> all = cases();
  all.push_back({"fine folding sheet", 64, 16, false, false, {}});
  for (double degrees : {0.0, 60.0, 120.0, 179.0}) all.back().shapes.push_back(folded_sheet(degrees * M_PI / 180));
  return all;
}

/// The positions of each keyframe.
std::vector<std::vector<Vector3d>> keyframe_positions(const Keyframes& c) {
  std::vector<std::vector<Vector3d>> frames;
  for (const Surface& s : c.shapes) frames.push_back(sscc::test::grid_positions(c.nu, c.nv, c.wrap_u, c.wrap_v, s));
  return frames;
}

/// The model whose modes take the rest shape (the first keyframe) to each keyframe.
sscc::SubspaceModel keyframe_model(const Keyframes& c) {
  return sscc::test::keyframe_model(sscc::test::grid_triangles(c.nu, c.nv, c.wrap_u, c.wrap_v), keyframe_positions(c));
}

/// Every non-adjacent pair through the kernels directly (validation/brute_force.hpp).
std::vector<std::pair<int, int>> brute_force_pairs(const sscc::SubspaceModel& model, const Eigen::VectorXd& q0,
                                                   const Eigen::VectorXd& q1) {
  const std::vector<Vector3d> x0 = model.deformed_positions(q0);
  const std::vector<Vector3d> x1 = model.deformed_positions(q1);
  const sscc::TriangleMesh& mesh = model.mesh();
  std::vector<std::pair<int, int>> pairs;
  for (int a = 0; a < mesh.triangle_count(); ++a) {
    for (int b = a + 1; b < mesh.triangle_count(); ++b) {
      if (mesh.adjacent(a, b)) continue;
      if (sscc::validation::triangle_pair_first_contact(x0, x1, mesh.triangles()[a], mesh.triangles()[b]) <= 1.0) {
        pairs.push_back({a, b});
      }
    }
  }
  return pairs;
}

/// Whether no non-adjacent pair among the triangles at positions [begin, end) and [begin2,
/// end2) of the hierarchy's order (the same range twice for a node alone) touches during the
/// step x0 -> x1, by the kernels on every pair (validation/brute_force.hpp).
bool no_contact(const sscc::SubspaceBvh& bvh, const std::vector<Vector3d>& x0, const std::vector<Vector3d>& x1,
                int begin, int end, int begin2, int end2) {
  const sscc::TriangleMesh& mesh = bvh.model().mesh();
  for (int i = begin; i < end; ++i) {
    for (int j = std::max(begin2, begin == begin2 ? i + 1 : begin2); j < end2; ++j) {
      const int a = bvh.triangle_order()[i], b = bvh.triangle_order()[j];
      if (mesh.adjacent(a, b)) continue;
      if (sscc::validation::triangle_pair_first_contact(x0, x1, mesh.triangles()[a], mesh.triangles()[b]) <= 1.0) {
        return false;
      }
    }
  }
  return true;
}

std::vector<std::pair<int, int>> pairs_of(const sscc::SelfCcdReport& report) {
  std::vector<std::pair<int, int>> pairs;
  for (const auto& p : report.pairs) pairs.push_back({p.first, p.second});
  return pairs;
}

}  // namespace

TEST_CASE("normal cones: the culled traversal reports exactly what exhaustive testing and brute force do",
          "[patch_cull][query]") {
  long culled = 0, culled_with_certificates = 0, plane_culled = 0;
  int colliding_steps = 0, steps = 0;
  for (const Keyframes& c : cases()) {
    const sscc::SubspaceModel model = keyframe_model(c);
    const int frames = static_cast<int>(c.shapes.size());
    const sscc::SubspaceBvh bvh(model);
    const sscc::SelfCcd ccd(bvh);
    const sscc::SelfCcd certified(bvh, sscc::Certificates::precompute(bvh));
    const int modes = model.mode_count();
    // Consecutive keyframes, and the jumps from the first to each (larger folds in one step).
    std::vector<std::pair<int, int>> transitions;
    for (int k = 0; k + 1 < frames; ++k) transitions.push_back({k, k + 1});
    for (int k = 2; k < frames; ++k) transitions.push_back({0, k});
    for (const auto& [from, to] : transitions) {
      const Eigen::VectorXd q0 = sscc::test::keyframe_q(modes, from), q1 = sscc::test::keyframe_q(modes, to);
      INFO(c.name << ": keyframe " << from << " to " << to);
      sscc::SelfCcdOptions cones;  // the cones alone
      sscc::set_traditional(cones);
      cones.use_normal_cones = true;
      const sscc::SelfCcdReport with_cones = ccd.query(q0, q1, cones);
      sscc::SelfCcdOptions plain;
      sscc::set_traditional(plain);
      const sscc::SelfCcdReport traditional = ccd.query(q0, q1, plain);
      const sscc::SelfCcdReport exhaustive = ccd.query_exhaustive(q0, q1);
      REQUIRE(with_cones.pairs == exhaustive.pairs);
      REQUIRE(with_cones.features == exhaustive.features);
      REQUIRE(traditional.pairs == exhaustive.pairs);
      REQUIRE(with_cones.features == traditional.features);
      CHECK(exhaustive.stats.plane_culled == 0);  // the reference culls nothing
      REQUIRE(pairs_of(with_cones) == brute_force_pairs(model, q0, q1));
      // The library's defaults: certificates and cones together.
      const sscc::SelfCcdReport defaults = certified.query(q0, q1);
      REQUIRE(defaults.pairs == exhaustive.pairs);
      REQUIRE(defaults.features == exhaustive.features);
      CHECK(traditional.stats.cone_culled == 0);
      CHECK(traditional.stats.plane_culled == 0);
      culled += with_cones.stats.cone_culled;
      plane_culled += with_cones.stats.plane_culled;
      culled_with_certificates += defaults.stats.cone_culled;
      colliding_steps += with_cones.collided();
      ++steps;
    }
  }
  CHECK(culled > 20);                   // the cones did cull
  CHECK(plane_culled > 20);             // and so did the triangle pairs' separating planes
  CHECK(culled_with_certificates > 0);  // also beside the certificates
  CHECK(colliding_steps >= steps / 3);  // and the steps do collide
}

TEST_CASE("normal cones: query_positions and any-hit mode agree with the unculled query", "[patch_cull][query]") {
  std::vector<std::vector<Vector3d>> frames;
  for (double degrees : {0.0, 120.0, 181.0}) {
    frames.push_back(sscc::test::grid_positions(16, 5, false, false, folded_sheet(degrees * M_PI / 180)));
  }
  const sscc::SubspaceModel model = sscc::test::keyframe_model(sscc::test::grid_triangles(16, 5, false, false), frames);
  const sscc::SubspaceBvh bvh(model);
  const sscc::SelfCcd ccd(bvh);
  sscc::SelfCcdOptions plain;
  sscc::set_traditional(plain);
  for (int k = 0; k < 2; ++k) {
    const Eigen::VectorXd q0 = sscc::test::keyframe_q(2, k), q1 = sscc::test::keyframe_q(2, k + 1);
    const auto x0 = model.deformed_positions(q0), x1 = model.deformed_positions(q1);
    sscc::SelfCcdOptions cones;
    cones.use_normal_cones = true;
    const sscc::SelfCcdReport culled = ccd.query_positions(x0, x1, cones);
    CHECK(culled.pairs == ccd.query_positions(x0, x1, plain).pairs);
    CHECK(culled.stats.cone_culled > 0);
    sscc::SelfCcdOptions any;
    sscc::set_traditional(any);
    any.mode = sscc::SelfCcdMode::kAnyHit;
    any.use_normal_cones = true;
    CHECK(ccd.query(q0, q1, any).collided() == ccd.query_exhaustive(q0, q1).collided());
  }
}

TEST_CASE("normal cones: a ramp whose normals stay in a cone but whose contour overlaps itself is not culled",
          "[patch_cull]") {
  // Reused across the case, as a detector reuses them across queries.
  sscc::detail::PatchCull::Caches caches;
  const int nu = 36, nv = 3;
  const std::vector<sscc::Triangle> triangles = sscc::test::grid_triangles(nu, nv, false, false);
  for (double pitch : {0.1, 0.0}) {
    const std::vector<Vector3d> x = sscc::test::grid_positions(nu, nv, false, false, spiral_ramp(pitch));
    const sscc::SubspaceModel model(sscc::TriangleMesh(x, triangles), Eigen::MatrixXd::Zero(3 * x.size(), 1),
                                    Eigen::VectorXd::Ones(1));
    const sscc::SubspaceBvh bvh(model);
    const sscc::detail::NodeBoundaries boundaries(bvh);
    REQUIRE(boundaries.simple_cycle(0));  // the ramp is one disc
    // Every normal is within a cone about -z (the grid's orientation faces down).
    for (const sscc::Triangle& t : triangles) {
      const auto n = sscc::detail::bernstein_normals(x[t[0]], x[t[1]], x[t[2]], x[t[0]], x[t[1]], x[t[2]]);
      REQUIRE(sscc::detail::certainly_positive(Vector3d(0, 0, -1), n));
    }
    sscc::detail::PatchCull cull(
        bvh, boundaries, x, x, [](int) {}, caches);
    CHECK_FALSE(cull.cannot_self_touch(0));
  }
  // A short piece of the ramp (54 degrees) is a star-shaped disc in projection: culled.
  const int short_nu = 6;
  const Surface short_ramp = [](double u, double v) { return spiral_ramp(0.1)(u * 0.1, v); };
  const std::vector<Vector3d> x = sscc::test::grid_positions(short_nu, nv, false, false, short_ramp);
  const sscc::SubspaceModel model(sscc::TriangleMesh(x, sscc::test::grid_triangles(short_nu, nv, false, false)),
                                  Eigen::MatrixXd::Zero(3 * x.size(), 1), Eigen::VectorXd::Ones(1));
  const sscc::SubspaceBvh bvh(model);
  const sscc::detail::NodeBoundaries boundaries(bvh);
  sscc::detail::PatchCull cull(
      bvh, boundaries, x, x, [](int) {}, caches);
  CHECK(cull.cannot_self_touch(0));
}

TEST_CASE("normal cones: every node and node pair the cull accepts has no touching pair under brute force",
          "[patch_cull]") {
  // Reused across the case, as a detector reuses them across queries.
  sscc::detail::PatchCull::Caches caches;
  int accepted_nodes = 0, accepted_pairs = 0;
  const std::vector<Keyframes> all = cases_with_fine_sheet();
  for (const Keyframes& c : all) {
    const sscc::SubspaceModel model = keyframe_model(c);
    const int frames = static_cast<int>(c.shapes.size());
    const sscc::SubspaceBvh bvh(model);
    const sscc::detail::NodeBoundaries boundaries(bvh);
    const int modes = model.mode_count();
    const auto& nodes = bvh.nodes();
    for (int k = 0; k + 1 < frames; ++k) {
      const auto x0 = model.deformed_positions(sscc::test::keyframe_q(modes, k));
      const auto x1 = model.deformed_positions(sscc::test::keyframe_q(modes, k + 1));
      sscc::detail::PatchCull cull(
          bvh, boundaries, x0, x1, [](int) {}, caches);
      const auto no_contact = [&](int begin, int end, int begin2, int end2) {
        return ::no_contact(bvh, x0, x1, begin, end, begin2, end2);
      };
      INFO(c.name << ": keyframe " << k << " to " << k + 1);
      for (int n = 0; n < static_cast<int>(nodes.size()); ++n) {
        if (!cull.cannot_self_touch(n)) continue;
        ++accepted_nodes;
        REQUIRE(
            no_contact(nodes[n].triangle_begin, nodes[n].triangle_end, nodes[n].triangle_begin, nodes[n].triangle_end));
      }
      for (int a = 0; a < static_cast<int>(nodes.size()); ++a) {
        for (int b = a + 1; b < static_cast<int>(nodes.size()); ++b) {
          const bool disjoint =
              nodes[a].triangle_end <= nodes[b].triangle_begin || nodes[b].triangle_end <= nodes[a].triangle_begin;
          if (!disjoint || !cull.cannot_touch(a, b)) continue;
          ++accepted_pairs;
          // Pairs within each node are the node's own test; here the pairs across.
          REQUIRE(no_contact(nodes[a].triangle_begin, nodes[a].triangle_end, nodes[b].triangle_begin,
                             nodes[b].triangle_end));
        }
      }
    }
  }
  CHECK(accepted_nodes > 10);
  CHECK(accepted_pairs >= 3);  // parts of 32 to 64 triangles (patch_cull.hpp): few in these meshes
}

TEST_CASE(
    "normal cones: with positions times powers of two the cull accepts no node or node pair it refuses at scale 1 "
    "unless brute force finds it free of contact",
    "[patch_cull]") {
  // Scaling by a power of two is exact and changes no contact: away from the absolute
  // allowance (kUnderflowAllowance) the verdicts should be those of scale 1, which the test
  // above holds against brute force on the same steps. A node or pair accepted only at some
  // scale is held against brute force at that scale (norms or products that underflow or
  // overflow would show as such acceptances, or as traps). 2^-450 and 2^450 put the
  // coefficients' entries near 2^-900 and 2^900, where length3 (common/scaled_norm.hpp)
  // changes method; at 2^-500 most coefficients fall below the allowance.
  const std::vector<double> scales{0x1p-280, 0x1p-400, 0x1p-450, 0x1p-500, 0x1p250, 0x1p300, 0x1p450};
  sscc::detail::PatchCull::Caches caches, scaled_caches;
  const std::vector<Keyframes> all = cases_with_fine_sheet();
  long unscaled_nodes = 0, unscaled_pairs = 0;
  std::vector<long> scaled_nodes(scales.size(), 0), scaled_pairs(scales.size(), 0), only_scaled(scales.size(), 0);
  for (const Keyframes& c : all) {
    const sscc::SubspaceModel model = keyframe_model(c);
    const int frames = static_cast<int>(c.shapes.size());
    const sscc::SubspaceBvh bvh(model);
    const sscc::detail::NodeBoundaries boundaries(bvh);
    const auto& nodes = bvh.nodes();
    const int modes = model.mode_count();
    for (int k = 0; k + 1 < frames; ++k) {
      const auto x0 = model.deformed_positions(sscc::test::keyframe_q(modes, k));
      const auto x1 = model.deformed_positions(sscc::test::keyframe_q(modes, k + 1));
      sscc::detail::PatchCull cull(
          bvh, boundaries, x0, x1, [](int) {}, caches);
      std::vector<char> node_verdicts;
      std::vector<std::array<int, 2>> pairs;
      std::vector<char> pair_verdicts;
      for (int n = 0; n < static_cast<int>(nodes.size()); ++n) {
        node_verdicts.push_back(cull.cannot_self_touch(n));
        unscaled_nodes += node_verdicts.back();
      }
      for (int a = 0; a < static_cast<int>(nodes.size()); ++a) {
        for (int b = a + 1; b < static_cast<int>(nodes.size()); ++b) {
          if (nodes[a].triangle_end > nodes[b].triangle_begin && nodes[b].triangle_end > nodes[a].triangle_begin)
            continue;
          pairs.push_back({a, b});
          pair_verdicts.push_back(cull.cannot_touch(a, b));
          unscaled_pairs += pair_verdicts.back();
        }
      }
      for (std::size_t i = 0; i < scales.size(); ++i) {
        INFO(c.name << ": keyframe " << k << " to " << k + 1 << ", positions times " << scales[i]);
        std::vector<Vector3d> y0 = x0, y1 = x1;
        for (Vector3d& p : y0) p *= scales[i];
        for (Vector3d& p : y1) p *= scales[i];
        sscc::detail::PatchCull scaled(
            bvh, boundaries, y0, y1, [](int) {}, scaled_caches);
        const auto no_contact = [&](int begin, int end, int begin2, int end2) {
          return ::no_contact(bvh, y0, y1, begin, end, begin2, end2);
        };
        for (int n = 0; n < static_cast<int>(nodes.size()); ++n) {
          if (!scaled.cannot_self_touch(n)) continue;
          ++scaled_nodes[i];
          if (node_verdicts[n]) continue;
          ++only_scaled[i];
          REQUIRE(no_contact(nodes[n].triangle_begin, nodes[n].triangle_end, nodes[n].triangle_begin,
                             nodes[n].triangle_end));
        }
        for (std::size_t j = 0; j < pairs.size(); ++j) {
          const auto [a, b] = pairs[j];
          if (!scaled.cannot_touch(a, b)) continue;
          ++scaled_pairs[i];
          if (pair_verdicts[j]) continue;
          ++only_scaled[i];
          REQUIRE(no_contact(nodes[a].triangle_begin, nodes[a].triangle_end, nodes[b].triangle_begin,
                             nodes[b].triangle_end));
        }
      }
    }
  }
  REQUIRE(unscaled_nodes > 100);
  REQUIRE(unscaled_pairs >= 3);
  for (std::size_t i = 0; i < scales.size(); ++i) {
    INFO("positions times " << scales[i] << ": nodes " << scaled_nodes[i] << " of " << unscaled_nodes << ", pairs "
                            << scaled_pairs[i] << " of " << unscaled_pairs << ", " << only_scaled[i]
                            << " accepted only scaled");
    // Not vacuous: the cull still accepts (nearly) what it does at scale 1 where the
    // coefficients stay above the allowance.
    if (scales[i] != 0x1p-500) {
      CHECK(scaled_nodes[i] * 10 >= unscaled_nodes * 9);
      CHECK(scaled_pairs[i] * 10 >= unscaled_pairs * 9);
    }
  }
}

TEST_CASE("normal cones: not used on a mesh whose patches at rest are small, used on one whose are large",
          "[patch_cull][query]") {
  // A coarse torus (few triangles per curved patch) pinching, and the fine folding sheet of
  // the tests above folding; both report what exhaustive testing does.
  struct Case {
    Keyframes frames;
    bool expect_cones;
  };
  const std::vector<Case> all = {
      {{"coarse torus", 12, 4, true, true, {sscc::test::pinched_torus(0.0), sscc::test::pinched_torus(0.3)}}, false},
      {{"sheet", 16, 5, false, false, {folded_sheet(0.0), folded_sheet(0.5)}}, true}};
  for (const Case& c : all) {
    const Keyframes& k = c.frames;
    const sscc::SubspaceModel model = keyframe_model(k);
    const sscc::SubspaceBvh bvh(model);
    const sscc::detail::NodeBoundaries boundaries(bvh);
    const double mean = sscc::detail::mean_patch_at_rest(bvh, boundaries);
    INFO(k.name << ": mean patch at rest " << mean);
    CHECK((mean >= sscc::detail::kSmallestMeanRestPatch) == c.expect_cones);
    const sscc::SelfCcd ccd(bvh);
    sscc::SelfCcdOptions cones;
    sscc::set_traditional(cones);
    cones.use_normal_cones = true;
    const int modes = model.mode_count();
    const Eigen::VectorXd q0 = sscc::test::keyframe_q(modes, 0), q1 = sscc::test::keyframe_q(modes, 1);
    const sscc::SelfCcdReport report = ccd.query(q0, q1, cones);
    CHECK(report.pairs == ccd.query_exhaustive(q0, q1).pairs);
    // The cones formed per step, alone in query_positions (no norm bounds the cones there:
    // patch_radius.hpp).
    const sscc::SelfCcdReport positions =
        ccd.query_positions(model.deformed_positions(q0), model.deformed_positions(q1), cones);
    CHECK(positions.pairs == report.pairs);
    CHECK((positions.stats.cone_culled > 0) == c.expect_cones);
  }
}

TEST_CASE("normal cones: formed from positions times powers of two, they report exactly what exhaustive testing does",
          "[patch_cull][query]") {
  // Scaling every position by a power of two is exact, and the kernels decide contact
  // exactly at any finite magnitude: the same pairs must come out at every scale. At 2^-280
  // and 2^-400 the normals' coefficients (products of two coordinates) are near 1e-170 and
  // 1e-242, their squares subnormal or 0; at 2^250 they are near 1e148, their squares near
  // the largest double, and at 2^300 near 1e178, their squares infinite. At 2^-500 they fall
  // near 1e-302, below the certified signs' absolute allowance (kUnderflowAllowance): the
  // cones refuse every patch there, which only loses culls. The meshes whose patches the
  // cones cull at scale 1 (the tests above): the folding sheet and the spiral ramp. The
  // exhaustive reference uses no cull (query_exhaustive), only the kernels.
  const std::vector<double> scales{0x1p-280, 0x1p-400, 0x1p-500, 0x1p250, 0x1p300};
  std::vector<long> culled(scales.size(), 0);
  for (const Keyframes& c : cases()) {
    if (c.name != "folding sheet" && c.name != "spiral ramp") continue;
    const std::vector<std::vector<Vector3d>> frames = keyframe_positions(c);
    const std::vector<sscc::Triangle> triangles = sscc::test::grid_triangles(c.nu, c.nv, c.wrap_u, c.wrap_v);
    const sscc::SubspaceModel model = sscc::test::keyframe_model(triangles, frames);
    const sscc::SelfCcd ccd{sscc::SubspaceBvh(model)};
    const int modes = model.mode_count();
    std::vector<sscc::SubspaceModel> scaled_models;
    std::vector<sscc::SelfCcd> scaled_ccds;
    for (double scale : scales) {
      std::vector<std::vector<Vector3d>> scaled_frames = frames;
      for (auto& frame : scaled_frames) {
        for (Vector3d& p : frame) p *= scale;
      }
      scaled_models.push_back(sscc::test::keyframe_model(triangles, scaled_frames));
      scaled_ccds.emplace_back(sscc::SubspaceBvh(scaled_models.back()));
    }
    // Every pair of keyframes, forward: up to the whole fold in one step.
    for (int from = 0; from < static_cast<int>(frames.size()); ++from) {
      for (int to = from + 1; to < static_cast<int>(frames.size()); ++to) {
        const Eigen::VectorXd q0 = sscc::test::keyframe_q(modes, from), q1 = sscc::test::keyframe_q(modes, to);
        const std::vector<Vector3d> unscaled0 = model.deformed_positions(q0);
        const auto unscaled_pairs = pairs_of(ccd.query_exhaustive(q0, q1));
        for (std::size_t i = 0; i < scales.size(); ++i) {
          INFO(c.name << ": keyframe " << from << " to " << to << ", positions times " << scales[i]);
          const std::vector<Vector3d> x0 = scaled_models[i].deformed_positions(q0);
          const std::vector<Vector3d> x1 = scaled_models[i].deformed_positions(q1);
          // The scaled model's positions are the unscaled ones times the scale, exactly.
          for (std::size_t v = 0; v < x0.size(); ++v) REQUIRE(x0[v] == scales[i] * unscaled0[v]);
          sscc::SelfCcdOptions cones;  // the cones alone, formed from the positions
          sscc::set_traditional(cones);
          cones.use_normal_cones = true;
          cones.threads = 1;
          const sscc::SelfCcdReport with_cones = scaled_ccds[i].query_positions(x0, x1, cones);
          const sscc::SelfCcdReport exhaustive = scaled_ccds[i].query_exhaustive(q0, q1);
          REQUIRE(with_cones.pairs == exhaustive.pairs);
          REQUIRE(with_cones.features == exhaustive.features);
          REQUIRE(pairs_of(with_cones) == unscaled_pairs);  // the same triangle pairs as at scale 1
          culled[i] += with_cones.stats.cone_culled;
        }
      }
    }
  }
  // Not vacuous: the cones cull wherever the coefficients stay above the allowance.
  for (std::size_t i = 0; i < scales.size(); ++i) {
    INFO("positions times " << scales[i]);
    if (scales[i] != 0x1p-500) CHECK(culled[i] > 50);
  }
}
