#include <catch2/catch.hpp>

#include <Eigen/QR>

#include <cmath>
#include <random>
#include <string>

#include "basis/pose_fixtures.hpp"
#include "sscc/mesh/mesh_io.hpp"
#include "sscc/mesh/write_off.hpp"

namespace {

/// Round-off of positions of size ~1 after a few thousand operations.
constexpr double kRoundOff = 1e-12;

std::string output_path(const std::string& name) { return std::string(SSCC_TEST_OUTPUT_DIR) + "/" + name; }

}  // namespace

TEST_CASE("PCA with every component reproduces the training poses to round-off", "[pca]") {
  const sscc::TriangleMesh bar = sscc::test::pose_bar();
  const int count = 12;
  const Eigen::MatrixXd poses = sscc::generate_example_poses(bar, sscc::test::bar_pose_options(count, 3));
  const sscc::PoseSubspace pca(bar, poses, sscc::test::pca_fraction(1.0));
  // Nonlinear poses span all P - 1 directions around their mean.
  CHECK(pca.mode_count() == count - 1);
  CHECK(pca.explained_fraction() == Approx(1.0));
  const double diagonal = bar.bounding_box_diagonal();
  for (int p = 0; p < count; ++p) {
    const Eigen::VectorXd x = poses.col(p);
    const sscc::SubspaceResidual residual = pca.residual(x, pca.project(x));
    CHECK(residual.max_vertex <= kRoundOff * diagonal);
    CHECK(residual.norm <= kRoundOff * diagonal * std::sqrt(static_cast<double>(bar.vertex_count())));
  }
  // The model: orthonormal U, the mean shape as rest mesh, weights 1 / variance of the
  // poses' coordinates (so ||q||_M is the Mahalanobis distance).
  const Eigen::MatrixXd gram = pca.basis().transpose() * pca.basis();
  CHECK((gram - Eigen::MatrixXd::Identity(count - 1, count - 1)).cwiseAbs().maxCoeff() < kRoundOff);
  CHECK((pca.mean() - poses.rowwise().mean()).cwiseAbs().maxCoeff() < kRoundOff);
  CHECK(pca.mean_shape().triangles() == bar.triangles());
  CHECK((sscc::stack_positions(pca.mean_shape().vertices()) - pca.mean()).norm() == 0.0);
  Eigen::MatrixXd q(count - 1, count);
  for (int p = 0; p < count; ++p) q.col(p) = pca.project(poses.col(p));
  CHECK(q.rowwise().mean().cwiseAbs().maxCoeff() < kRoundOff);
  const Eigen::VectorXd sample_variance = q.rowwise().squaredNorm() / (count - 1);
  for (int i = 0; i < count - 1; ++i) {
    CHECK(sample_variance[i] == Approx(pca.variances()[i]).epsilon(1e-9));
    CHECK(pca.weights()[i] == Approx(1.0 / pca.variances()[i]));
    if (i > 0) CHECK(pca.variances()[i] <= pca.variances()[i - 1]);
  }
  const sscc::SubspaceModel model = pca.model();
  CHECK(model.weighted_norm(q.col(0)) ==
        Approx(std::sqrt((q.col(0).cwiseAbs2().cwiseQuotient(pca.variances())).sum())));
}

TEST_CASE("PCA with a fraction of 1 keeps components too small to change the variance's sum", "[pca]") {
  // Poses along four orthogonal directions with spreads 1, 1e-3, 1e-6 and 1e-9: the last
  // variance is 1e-18 of the first, below the sum's rounding, and still a component.
  const sscc::TriangleMesh bar = sscc::test::pose_bar();
  std::mt19937_64 rng(17);
  std::normal_distribution<double> normal;
  const Eigen::Index n = 3 * bar.vertex_count();
  Eigen::MatrixXd random(n, 4);
  for (Eigen::Index i = 0; i < random.size(); ++i) random.data()[i] = normal(rng);
  const Eigen::MatrixXd directions =
      Eigen::HouseholderQR<Eigen::MatrixXd>(random).householderQ() * Eigen::MatrixXd::Identity(n, 4);
  Eigen::MatrixXd poses = sscc::stack_positions(bar.vertices()).replicate(1, 6);
  for (int p = 0; p < 6; ++p) {
    for (int i = 0; i < 4; ++i) poses.col(p) += 0.1 * std::pow(1e-3, i) * normal(rng) * directions.col(i);
  }
  const sscc::PoseSubspace pca(bar, poses, sscc::test::pca_fraction(1.0));
  REQUIRE(pca.component_variances().size() == 4);
  CHECK(pca.mode_count() == 4);
  for (int p = 0; p < 6; ++p) {
    const Eigen::VectorXd x = poses.col(p);
    CHECK(pca.residual(x, pca.project(x)).max_vertex <= kRoundOff * bar.bounding_box_diagonal());
  }
}

TEST_CASE("PCA keeps the fewest components reaching the explained variance, or the count given", "[pca]") {
  const sscc::TriangleMesh bar = sscc::test::pose_bar();
  const Eigen::MatrixXd poses = sscc::generate_example_poses(bar, sscc::test::bar_pose_options(20, 5));
  const sscc::PoseSubspace complete(bar, poses, sscc::test::pca_fraction(1.0));
  const Eigen::VectorXd& variances = complete.component_variances();
  const double total = variances.sum();
  int previous = 0;
  for (double fraction : {0.5, 0.9, 0.99, 0.999, 0.99999, 1.0}) {
    const sscc::PoseSubspace pca(bar, poses, sscc::test::pca_fraction(fraction));
    const int r = pca.mode_count();
    INFO("fraction " << fraction << ": " << r << " modes");
    CHECK(variances.head(r).sum() >= fraction * total);
    if (r > 1) CHECK(variances.head(r - 1).sum() < fraction * total);
    CHECK(pca.explained_fraction() == Approx(variances.head(r).sum() / total));
    CHECK(r >= previous);
    previous = r;
  }
  CHECK(previous == complete.mode_count());
  CHECK(complete.mode_count() == complete.component_variances().size());  // 1 keeps every component
  const sscc::PoseSubspace three(bar, poses, sscc::test::pca_modes(3));
  REQUIRE(three.mode_count() == 3);
  CHECK((three.basis() - complete.basis().leftCols(3)).cwiseAbs().maxCoeff() < kRoundOff);
  CHECK_THROWS_WITH(sscc::PoseSubspace(bar, poses, sscc::test::pca_modes(20)), Catch::Contains("components"));
  CHECK_THROWS_WITH(sscc::PoseSubspace(bar, poses, sscc::test::pca_fraction(0.0)), Catch::Contains("fraction"));
  CHECK_THROWS_WITH(sscc::PoseSubspace(bar, poses.leftCols(1)), Catch::Contains("two"));
  const Eigen::MatrixXd same = poses.col(0).replicate(1, 3);
  CHECK_THROWS_WITH(sscc::PoseSubspace(bar, same), Catch::Contains("are the same"));
  CHECK_THROWS_WITH(sscc::PoseSubspace(bar, poses.topRows(9)), Catch::Contains("coordinates"));
}

TEST_CASE("example pose files: read back exactly, mismatched connectivity refused naming the file", "[pca]") {
  const sscc::TriangleMesh bar = sscc::test::pose_bar();
  const Eigen::MatrixXd poses = sscc::generate_example_poses(bar, sscc::test::bar_pose_options(2, 7));
  const std::string good = output_path("pca_pose_good.off");
  sscc::write_off(good, sscc::TriangleMesh(sscc::unstack_positions(poses.col(0)), bar.triangles()));
  const Eigen::MatrixXd read = sscc::read_example_poses(bar, {good});
  CHECK((read.col(0) - poses.col(0)).norm() == 0.0);  // 17 digits: the same doubles

  const std::string fewer = output_path("pca_pose_fewer_vertices.off");
  sscc::write_off(fewer, sscc::test::box_surface({1.0, 0.3, 0.2}, {9, 3, 2}));
  CHECK_THROWS_WITH(sscc::read_example_poses(bar, {good, fewer}),
                    Catch::Contains(fewer) && Catch::Contains("vertices"));

  std::vector<sscc::Triangle> triangles = bar.triangles();
  std::swap(triangles[5][1], triangles[5][2]);  // same vertices, other orientation
  const std::string reordered = output_path("pca_pose_other_triangles.off");
  sscc::write_off(reordered, sscc::TriangleMesh(bar.vertices(), triangles));
  CHECK_THROWS_WITH(sscc::read_example_poses(bar, {reordered, good}),
                    Catch::Contains(reordered) && Catch::Contains("triangle 5"));
  CHECK_THROWS_AS(sscc::read_example_poses(bar, {output_path("pca_no_such_pose.off")}), sscc::MeshFileError);
}

TEST_CASE("the example pose generator is seeded and keeps the connectivity", "[pca]") {
  const sscc::TriangleMesh bar = sscc::test::pose_bar();
  const Eigen::MatrixXd a = sscc::generate_example_poses(bar, sscc::test::bar_pose_options(4, 11));
  const Eigen::MatrixXd b = sscc::generate_example_poses(bar, sscc::test::bar_pose_options(4, 11));
  const Eigen::MatrixXd c = sscc::generate_example_poses(bar, sscc::test::bar_pose_options(4, 12));
  CHECK(a.rows() == 3 * bar.vertex_count());
  CHECK(a.cols() == 4);
  CHECK((a - b).norm() == 0.0);
  CHECK((a - c).norm() > 0.0);
  // With no bend, twist or displacement every pose is the rest mesh.
  sscc::ExamplePoseOptions still = sscc::test::bar_pose_options(2, 1);
  still.twist = still.bend = still.modal_amplitude = 0.0;
  const Eigen::MatrixXd rest = sscc::generate_example_poses(bar, still);
  CHECK((rest.col(1) - sscc::stack_positions(bar.vertices())).cwiseAbs().maxCoeff() < kRoundOff);
  // A pure bend turns each cross-section rigidly: edges within one keep their length.
  sscc::ExamplePoseOptions bent = still;
  bent.bend = 1.0;
  const std::vector<Eigen::Vector3d> x = sscc::unstack_positions(sscc::generate_example_poses(bar, bent).col(0));
  for (const sscc::Edge& e : bar.edges()) {
    const double rest_length = (bar.vertices()[e[0]] - bar.vertices()[e[1]]).norm();
    const bool across = bar.vertices()[e[0]].x() == bar.vertices()[e[1]].x();
    if (across) CHECK((x[e[0]] - x[e[1]]).norm() == Approx(rest_length).epsilon(1e-12));
  }
  sscc::ExamplePoseOptions bad = still;
  bad.twist = -1.0;
  CHECK_THROWS_WITH(sscc::generate_example_poses(bar, bad), Catch::Contains("twist"));
}
