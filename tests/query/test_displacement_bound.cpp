// The displacement cull: its rest clearances against a brute-force minimum over every
// considered triangle pair, and the culled query against exhaustive testing and an
// independent brute force on steps scaled to just before, at and just after the first
// contact (where a bound that is too generous would show), with global and local modes.
#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "query/displacement_bound.hpp"
#include "sscc/ccd/kernels.hpp"
#include "sscc/geometry/triangle_distance.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "sscc/query/self_ccd.hpp"
#include "support/pair_reference.hpp"
#include "support/parametric_meshes.hpp"
#include "support/test_meshes.hpp"

namespace {

using Eigen::Vector3d;

/// The helix tube of parametric_meshes.hpp as a mesh: its coils' surfaces are pitch - 0.2
/// apart (close at pitch 0.25).
sscc::TriangleMesh helix_tube(double pitch) {
  return sscc::TriangleMesh(sscc::test::grid_positions(60, 8, false, true, sscc::test::helix_tube(pitch)),
                            sscc::test::grid_triangles(60, 8, false, true));
}

/// The first `polynomial` polynomial modes and `bumps` local ones (a random direction times a
/// Gaussian of width 0.15 about a random vertex): deformations that are global and ones that
/// are large in one place only.
sscc::SubspaceModel mixed_model(const sscc::TriangleMesh& mesh, int polynomial, int bumps, std::uint64_t seed) {
  const Eigen::MatrixXd global = sscc::polynomial_basis(mesh, polynomial);
  Eigen::MatrixXd basis(global.rows(), polynomial + bumps);
  basis.leftCols(polynomial) = global;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  std::uniform_int_distribution<int> vertex(0, mesh.vertex_count() - 1);
  for (int b = 0; b < bumps; ++b) {
    const Vector3d centre = mesh.vertices()[vertex(rng)];
    const Vector3d direction = Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    for (int v = 0; v < mesh.vertex_count(); ++v) {
      const double d2 = (mesh.vertices()[v] - centre).squaredNorm();
      basis.block<3, 1>(3 * v, polynomial + b) = std::exp(-d2 / (2 * 0.15 * 0.15)) * direction;
    }
  }
  return sscc::SubspaceModel(mesh, basis, Eigen::VectorXd::Ones(polynomial + bumps));
}

/// The rest distance of two triangles: 0 when they intersect (exactly decided), else the
/// closest points' distance.
double rest_distance(const sscc::TriangleMesh& mesh, int a, int b) {
  const auto& x = mesh.vertices();
  const sscc::Triangle& ta = mesh.triangles()[a];
  const sscc::Triangle& tb = mesh.triangles()[b];
  if (sscc::ccd::triangles_intersect(x[ta[0]], x[ta[1]], x[ta[2]], x[tb[0]], x[tb[1]], x[tb[2]])) return 0.0;
  return sscc::closest_points_disjoint_triangles({x[ta[0]], x[ta[1]], x[ta[2]]}, {x[tb[0]], x[tb[1]], x[tb[2]]})
      .distance;
}

std::vector<std::pair<std::string, sscc::SubspaceModel>> models() {
  std::vector<std::pair<std::string, sscc::SubspaceModel>> all;
  all.emplace_back("parallel sheets", mixed_model(sscc::test::parallel_sheets(8, 0.03), 27, 4, 1));
  all.emplace_back("helix tube", mixed_model(helix_tube(0.25), 27, 4, 2));
  all.emplace_back("sphere", mixed_model(sscc::test::uv_sphere(12, 18), 27, 4, 3));
  return all;
}

bool same_reports(const sscc::SelfCcdReport& a, const sscc::SelfCcdReport& b) {
  return a.pairs == b.pairs && a.features == b.features;
}

}  // namespace

TEST_CASE("displacement bounds: every node's clearance is a lower bound of its triangles' rest distances",
          "[displacement][query]") {
  for (const auto& [name, model] : models()) {
    INFO(name);
    const sscc::SubspaceBvh bvh(model);
    const sscc::detail::DisplacementBounds bounds(bvh);
    const sscc::TriangleMesh& mesh = model.mesh();
    std::vector<double> nearest(mesh.triangle_count(), std::numeric_limits<double>::infinity());
    for (int a = 0; a < mesh.triangle_count(); ++a) {
      for (int b = 0; b < mesh.triangle_count(); ++b) {
        if (model.considers(a, b)) nearest[a] = std::min(nearest[a], rest_distance(mesh, a, b));
      }
    }
    int tight = 0, leaves = 0;
    for (int n = 0; n < static_cast<int>(bvh.nodes().size()); ++n) {
      const sscc::SubspaceBvh::Node& node = bvh.nodes()[n];
      double least = std::numeric_limits<double>::infinity();
      for (int i = node.triangle_begin; i < node.triangle_end; ++i) {
        least = std::min(least, nearest[bvh.triangle_order()[i]]);
      }
      REQUIRE(bounds.clearance(n) <= least);
      if (node.is_leaf()) {
        ++leaves;
        tight += bounds.clearance(n) >= 0.999 * least;
      }
    }
    CHECK(tight >= 0.95 * leaves);  // not a bound that merely holds: nearly the distance itself
  }
}

TEST_CASE("displacement bounds: at rest, a touching pair makes its nodes' clearance zero", "[displacement][query]") {
  // Two sheets in one plane overlapping along a strip: triangles of different sheets cross.
  sscc::TriangleMesh sheets = sscc::test::parallel_sheets(4, 0.0);
  const sscc::SubspaceModel model = mixed_model(sheets, 4, 0, 1);
  const sscc::SubspaceBvh bvh(model);
  const sscc::detail::DisplacementBounds bounds(bvh);
  CHECK(bounds.clearance(0) == 0.0);
}

TEST_CASE(
    "displacement bounds: the culled query reports what exhaustive testing and brute force do, up to and "
    "past the first contact",
    "[displacement][query]") {
  long culled = 0, steps = 0, colliding = 0;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  for (const auto& [name, model] : models()) {
    const sscc::SubspaceBvh bvh(model);
    const sscc::SelfCcd ccd(bvh);
    const int r = model.mode_count();
    sscc::SelfCcdOptions bounded;
    bounded.use_certificates = false;
    REQUIRE(bounded.use_displacement_bounds);  // the library's default
    sscc::SelfCcdOptions parallel = bounded;
    parallel.threads = 2;
    for (int trial = 0; trial < 4; ++trial) {
      Eigen::VectorXd start(r), direction(r);
      for (int k = 0; k < r; ++k) start[k] = 0.002 * normal(rng), direction[k] = normal(rng);
      if (trial % 2 == 1) direction.head(r - 4).setZero();  // only the local modes move
      // The smallest scale whose step reaches a contact, to within 1e-3 (bisection on the
      // exhaustive query; the start has none).
      const auto collides = [&](double scale) {
        return ccd.query_exhaustive(start, start + scale * direction).collided();
      };
      INFO(name << " trial " << trial);
      REQUIRE_FALSE(collides(0.0));
      double lo = 0.0, hi = 1e-3;
      while (!collides(hi) && hi < 1e3) lo = hi, hi *= 2;
      REQUIRE(collides(hi));
      for (int i = 0; i < 30 && hi - lo > 1e-3 * hi; ++i) (collides(0.5 * (lo + hi)) ? hi : lo) = 0.5 * (lo + hi);
      for (double fraction : {0.01, 0.1, 0.5, 0.9, 0.99, 1.0, 1.001, 1.01, 1.2}) {
        const Eigen::VectorXd q1 = start + fraction * hi * direction;
        INFO(name << " trial " << trial << " at " << fraction << " of the first contact's scale");
        const sscc::SelfCcdReport exhaustive = ccd.query_exhaustive(start, q1);
        const sscc::SelfCcdReport report = ccd.query(start, q1, bounded);
        REQUIRE(same_reports(report, exhaustive));
        REQUIRE(same_reports(ccd.query(start, q1, parallel), exhaustive));
        sscc::test::require_same_pairs(
            report.pairs,
            sscc::test::brute_force_pairs(model.mesh(), model.deformed_positions(start), model.deformed_positions(q1)));
        culled += report.stats.displacement_culled;
        colliding += report.collided();
        ++steps;
      }
    }
  }
  CHECK(culled > 100);            // the bounds did cull
  CHECK(colliding >= steps / 3);  // and the steps do collide
}

TEST_CASE("displacement bounds: a linear deformation short of collapsing the mesh is culled at the root",
          "[displacement][query]") {
  // Modes that are linear fields x -> B x: their affine fits leave no residual, so any step
  // whose map stays within ||A||_F < 1 of the identity is decided at the root, and a step
  // that flattens the sphere through itself is not culled.
  const sscc::TriangleMesh sphere = sscc::test::uv_sphere(10, 16);
  const Eigen::MatrixXd linear = sscc::polynomial_basis(sphere, 9);
  const sscc::SubspaceModel model(sphere, linear, Eigen::VectorXd::Ones(9));
  const sscc::SubspaceBvh bvh(model);
  const sscc::SelfCcd ccd(bvh);
  REQUIRE(bvh.nodes()[0].triangle_end >= sscc::detail::kSmallestAffineNode);
  sscc::SelfCcdOptions bounded;
  bounded.use_certificates = false;
  std::mt19937_64 rng(3);
  std::normal_distribution<double> normal;
  Eigen::VectorXd direction(9);
  for (int k = 0; k < 9; ++k) direction[k] = normal(rng);
  // The stretch a_n of the root grows linearly with the step's scale: find where it reaches 1.
  int culled_at_root = 0;
  for (double scale : {1e-3, 1e-2, 0.05, 0.1}) {
    const Eigen::VectorXd q1 = scale * direction / direction.norm();
    const sscc::SelfCcdReport report = ccd.query(Eigen::VectorXd::Zero(9), q1, bounded);
    CHECK(report.pairs == ccd.query_exhaustive(Eigen::VectorXd::Zero(9), q1).pairs);
    culled_at_root += report.stats.box_tests == 0 && report.stats.displacement_culled == 1;
  }
  CHECK(culled_at_root >= 2);
}

TEST_CASE("displacement bounds: not applied with certificates, nor when switched off", "[displacement][query]") {
  const sscc::SubspaceModel model = mixed_model(sscc::test::parallel_sheets(6, 0.05), 9, 2, 4);
  const sscc::SubspaceBvh bvh(model);
  const sscc::SelfCcd ccd(bvh);
  Eigen::VectorXd q1 = Eigen::VectorXd::Zero(model.mode_count());
  q1[0] = 1e-4;
  sscc::SelfCcdOptions off;
  sscc::set_traditional(off);
  CHECK(ccd.query(Eigen::VectorXd::Zero(model.mode_count()), q1, off).stats.displacement_culled == 0);
  sscc::SelfCcdOptions on;
  on.use_certificates = false;
  CHECK(ccd.query(Eigen::VectorXd::Zero(model.mode_count()), q1, on).stats.displacement_culled > 0);
}

TEST_CASE("displacement bounds: gaps too large to square and spreads too small to square are still bounded",
          "[displacement][query]") {
  // Two triangles `gap` apart along z, one mode of size `size` moving the second onto the
  // first over the step: rest gaps above 1e154 overflowed a squared box distance (and the
  // search then skipped every partner), spreads below 1e-154 underflowed their squares.
  const auto reports_agree = [](double gap, double size) {
    const std::vector<Vector3d> x{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.2, gap}, {1.2, 0.2, gap}, {0.2, 1.2, gap}};
    Eigen::MatrixXd u = Eigen::MatrixXd::Zero(18, 1);
    for (int v = 3; v < 6; ++v) u(3 * v + 2, 0) = -size;
    const sscc::SubspaceModel model(sscc::TriangleMesh(x, {{0, 1, 2}, {3, 4, 5}}), u, Eigen::VectorXd::Ones(1));
    const sscc::SelfCcd ccd{sscc::SubspaceBvh(model)};
    const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(1), q1 = Eigen::VectorXd::Constant(1, 2 * gap / size);
    sscc::SelfCcdOptions bounded;
    bounded.use_certificates = false;
    const sscc::SelfCcdReport exhaustive = ccd.query_exhaustive(q0, q1);
    INFO("gap " << gap << ", mode size " << size);
    CHECK(exhaustive.collided());
    CHECK(same_reports(ccd.query(q0, q1, bounded), exhaustive));
  };
  for (double size : {1e-150, 1e-160, 1e-162, 1e-170}) reports_agree(0.5, size);
  for (double gap : {1e150, 1e155, 1e160}) reports_agree(gap, 1.0);
}
