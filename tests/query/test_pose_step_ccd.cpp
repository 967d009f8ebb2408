#include <catch2/catch.hpp>

#include <random>

#include "basis/pose_fixtures.hpp"
#include "sscc/query/pose_step_ccd.hpp"

namespace {

using sscc::test::CertifiedPoses;

/// A pose the traditional query finds colliding on the step from the mean shape: its ends
/// have met. Returns its index among the fixture's poses.
int colliding_pose(const CertifiedPoses& f, const sscc::SelfCcd& ccd) {
  const std::vector<Eigen::Vector3d> mean = f.subspace.mean_shape().vertices();
  for (int p = 0; p < f.poses.cols(); ++p) {
    if (ccd.query_positions(mean, sscc::unstack_positions(f.poses.col(p))).collided()) return p;
  }
  return -1;
}

sscc::PoseStepOptions tolerance_of(double length, const CertifiedPoses& f) {
  sscc::PoseStepOptions options;
  options.residual_fraction = length / f.subspace.mean_shape().bounding_box_diagonal();
  return options;
}

}  // namespace

TEST_CASE("pose steps fall back to the traditional query exactly when a residual exceeds the tolerance", "[pca]") {
  const CertifiedPoses f(30, 30, 9, sscc::test::pca_modes(6));
  const sscc::PoseStepCcd steps(f.subspace, f.bvh, &f.certificates);
  const sscc::SelfCcd& ccd = steps.ccd();
  const int p = colliding_pose(f, ccd);
  REQUIRE(p >= 0);
  // Poses in the subspace: the mean shape, and pose p's projection (so the step collides).
  const Eigen::VectorXd q_p = f.subspace.project(f.poses.col(p));
  const std::vector<Eigen::Vector3d> x0 = f.subspace.mean_shape().vertices();
  const std::vector<Eigen::Vector3d> inside = sscc::unstack_positions(f.subspace.reconstruct(q_p));
  const sscc::PoseStepReport certified = steps.query(x0, inside);
  CHECK_FALSE(certified.fell_back);
  CHECK(certified.residual0.max_vertex == 0.0);
  CHECK(certified.residual1.max_vertex <= certified.tolerance);
  CHECK((certified.q1 - q_p).norm() <= 1e-12 * q_p.norm());
  const sscc::SelfCcdReport subspace_step = ccd.query(certified.q0, certified.q1);
  CHECK(certified.ccd.pairs == subspace_step.pairs);
  CHECK(certified.ccd.features == subspace_step.features);

  // Off the subspace by delta at the end, then at the start of the step.
  std::mt19937_64 rng(2);
  const double delta = 1e-4 * f.bar.bounding_box_diagonal();
  const Eigen::VectorXd offset = sscc::test::orthogonal_displacement(f.subspace, rng, delta);
  const std::vector<Eigen::Vector3d> outside = sscc::unstack_positions(f.subspace.reconstruct(q_p) + offset);
  for (const bool at_end : {true, false}) {
    INFO((at_end ? "the end pose is off the subspace" : "the start pose is off the subspace"));
    const std::vector<Eigen::Vector3d>& from = at_end ? x0 : outside;
    const std::vector<Eigen::Vector3d>& to = at_end ? outside : x0;
    const sscc::PoseStepReport measured = steps.query(from, to);  // default tolerance: 1e-10 diagonals
    const double residual = (at_end ? measured.residual1 : measured.residual0).max_vertex;
    CHECK(residual == Approx(delta).epsilon(1e-9));
    CHECK((at_end ? measured.residual0 : measured.residual1).max_vertex == 0.0);
    CHECK(measured.fell_back);

    const sscc::PoseStepReport accepted = steps.query(from, to, tolerance_of(residual * (1 + 1e-9), f));
    CHECK_FALSE(accepted.fell_back);
    const sscc::SelfCcdReport projected = ccd.query(accepted.q0, accepted.q1);
    CHECK(accepted.ccd.pairs == projected.pairs);
    CHECK(accepted.ccd.features == projected.features);

    const sscc::PoseStepReport refused = steps.query(from, to, tolerance_of(residual * (1 - 1e-9), f));
    CHECK(refused.fell_back);
    const sscc::SelfCcdReport given = ccd.query_positions(from, to);
    CHECK(given.collided());
    CHECK(refused.ccd.pairs == given.pairs);
    CHECK(refused.ccd.features == given.features);
    CHECK(refused.ccd.earliest_toi == given.earliest_toi);
    CHECK(refused.ccd.stats.certified == 0);
  }
}

TEST_CASE("pose steps refuse a model that is not the subspace's, and bad poses", "[pca]") {
  const sscc::test::PosePca f(12, 12, 4, sscc::test::pca_modes(3));
  const sscc::test::PosePca other(12, 12, 5, sscc::test::pca_modes(3));
  CHECK_THROWS_WITH(sscc::PoseStepCcd(f.subspace, other.bvh), Catch::Contains("mean shape"));
  const sscc::PoseSubspace fewer(f.bar, f.poses, sscc::test::pca_modes(2));
  CHECK_THROWS_WITH(sscc::PoseStepCcd(fewer, f.bvh), Catch::Contains("modes"));
  const sscc::PoseStepCcd steps(f.subspace, f.bvh);
  const std::vector<Eigen::Vector3d> x = f.subspace.mean_shape().vertices();
  std::vector<Eigen::Vector3d> bad = x;
  bad[3].y() = INFINITY;
  CHECK_THROWS_WITH(steps.query(x, bad), Catch::Contains("infinite"));
  CHECK_THROWS_WITH(steps.query(x, {x.begin(), x.end() - 1}), Catch::Contains("coordinates"));
  sscc::PoseStepOptions negative;
  negative.residual_fraction = -1.0;
  CHECK_THROWS_WITH(steps.query(x, x, negative), Catch::Contains("residual fraction"));
}
