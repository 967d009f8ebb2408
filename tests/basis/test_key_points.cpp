#include <catch2/catch.hpp>

#include <Eigen/SVD>

#include <algorithm>
#include <random>

#include "basis/pose_fixtures.hpp"
#include "sscc/basis/key_points.hpp"

namespace {

/// Round-off of coordinates of size ~1 after a few hundred operations.
constexpr double kRoundOff = 1e-11;

struct PoseSet {
  sscc::TriangleMesh bar = sscc::test::pose_bar();
  Eigen::MatrixXd training = sscc::generate_example_poses(bar, sscc::test::bar_pose_options(30, 21));
};

/// Root mean square vertex distance of the training poses from m + U q, q from the key points.
double key_point_rms(const sscc::PoseSubspace& subspace, const sscc::KeyPointMap& keys, const Eigen::MatrixXd& poses) {
  double squared = 0.0;
  for (Eigen::Index p = 0; p < poses.cols(); ++p) {
    const Eigen::VectorXd x = poses.col(p);
    const double norm = subspace.residual(x, keys.coordinates_of_pose(x)).norm;
    squared += norm * norm;
  }
  return std::sqrt(squared / static_cast<double>(poses.size() / 3));
}

}  // namespace

TEST_CASE("uniform key point sampling covers the mesh and keeps points a radius apart", "[pca]") {
  const sscc::TriangleMesh bar = sscc::test::pose_bar();
  for (double radius : {0.05, 0.15, 0.4}) {
    const std::vector<int> keys = sscc::uniform_key_points(bar.vertices(), radius);
    INFO("radius " << radius << ": " << keys.size() << " key points");
    CHECK(keys.front() == 0);
    for (std::size_t i = 0; i < keys.size(); ++i) {
      for (std::size_t j = i + 1; j < keys.size(); ++j) {
        CHECK((bar.vertices()[keys[i]] - bar.vertices()[keys[j]]).norm() > radius);
      }
    }
    for (const Eigen::Vector3d& p : bar.vertices()) {
      double nearest = INFINITY;
      for (int k : keys) nearest = std::min(nearest, (bar.vertices()[k] - p).norm());
      CHECK(nearest <= radius);
    }
  }
  CHECK(sscc::uniform_key_points(bar.vertices(), 10.0) == std::vector<int>{0});
  CHECK_THROWS_WITH(sscc::uniform_key_points(bar.vertices(), 0.0), Catch::Contains("radius"));
}

TEST_CASE("key points give back q of poses in the subspace to round-off, and near it within a bound", "[pca]") {
  const PoseSet set;
  const sscc::PoseSubspace subspace(set.bar, set.training, sscc::test::pca_fraction(0.999));
  const sscc::KeyPointSelection selection = sscc::select_key_points(subspace, set.training);
  const sscc::KeyPointMap keys(subspace, selection.vertices);
  INFO(subspace.mode_count() << " modes, " << keys.vertices().size() << " key points, condition "
                             << keys.condition_number());
  REQUIRE(subspace.mode_count() >= 4);
  CHECK(keys.matrix().rows() == subspace.mode_count());
  CHECK(keys.matrix().cols() == 3 * static_cast<int>(keys.vertices().size()));
  const double amplification = Eigen::JacobiSVD<Eigen::MatrixXd>(keys.matrix()).singularValues()[0];
  std::mt19937_64 rng(5);
  const double diagonal = set.bar.bounding_box_diagonal();
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::VectorXd q = sscc::test::random_subspace_coordinates(subspace, rng);
    const Eigen::VectorXd inside = subspace.reconstruct(q);
    // Held out (not a training pose) but in the span: recovered to round-off.
    CHECK((keys.coordinates_of_pose(inside) - q).norm() <= kRoundOff * keys.condition_number() * diagonal);
    std::vector<Eigen::Vector3d> key_positions;
    for (int v : keys.vertices()) key_positions.push_back(inside.segment<3>(3 * v));
    CHECK((keys.coordinates(key_positions) - keys.coordinates_of_pose(inside)).norm() == 0.0);

    // Off the subspace by at most delta per vertex: the error in q is the map applied to the
    // key points' share of the displacement, and the residual grows by at most that.
    const double delta = 1e-3 * diagonal;
    const Eigen::VectorXd offset = sscc::test::orthogonal_displacement(subspace, rng, delta);
    const Eigen::VectorXd near = inside + offset;
    const Eigen::VectorXd from_keys = keys.coordinates_of_pose(near);
    double key_offset = 0.0;
    for (int v : keys.vertices()) key_offset += offset.segment<3>(3 * v).squaredNorm();
    const double q_error = (from_keys - q).norm();
    CHECK(q_error <= amplification * std::sqrt(key_offset) * (1 + 1e-9) + kRoundOff);
    const sscc::SubspaceResidual projected = subspace.residual(near, subspace.project(near));
    const sscc::SubspaceResidual keyed = subspace.residual(near, from_keys);
    CHECK(projected.max_vertex == Approx(delta).epsilon(1e-9));
    CHECK(keyed.max_vertex <= delta + q_error + kRoundOff);
    CHECK(keyed.norm >= projected.norm * (1 - 1e-12));  // the projection is the best fit
  }
  CHECK_THROWS_WITH(keys.coordinates({Eigen::Vector3d::Zero()}), Catch::Contains("positions for"));
}

TEST_CASE("greedy key points each reduce the training residual most, as a direct fit measures it", "[pca]") {
  const PoseSet set;
  // Four components of a dozen: the training poses are off the subspace, so key points
  // matter beyond the rank.
  const sscc::PoseSubspace subspace(set.bar, set.training, sscc::test::pca_modes(4));
  sscc::KeyPointOptions options;
  options.radius_fraction = 0.3;
  options.greedy_additions = 4;
  const sscc::KeyPointSelection selection = sscc::select_key_points(subspace, set.training, options);
  INFO(selection.sampled << " sampled, " << selection.vertices.size() << " in all");
  const int added = static_cast<int>(selection.vertices.size()) - selection.sampled;
  REQUIRE(added > 0);
  REQUIRE(static_cast<int>(selection.training_residual.size()) == added + 1);
  for (std::size_t i = 1; i < selection.training_residual.size(); ++i) {
    CHECK(selection.training_residual[i] < selection.training_residual[i - 1]);
  }
  const std::vector<int> sampled(selection.vertices.begin(), selection.vertices.begin() + selection.sampled);
  CHECK(key_point_rms(subspace, sscc::KeyPointMap(subspace, sampled), set.training) ==
        Approx(selection.training_residual.front()).epsilon(1e-9));
  CHECK(key_point_rms(subspace, sscc::KeyPointMap(subspace, selection.vertices), set.training) ==
        Approx(selection.training_residual.back()).epsilon(1e-9));
  // The first addition is the best single vertex, by brute force.
  double best = INFINITY;
  for (int v = 0; v < set.bar.vertex_count(); ++v) {
    if (std::find(sampled.begin(), sampled.end(), v) != sampled.end()) continue;
    std::vector<int> candidate = sampled;
    candidate.push_back(v);
    best = std::min(best, key_point_rms(subspace, sscc::KeyPointMap(subspace, candidate), set.training));
  }
  CHECK(selection.training_residual[1] == Approx(best).epsilon(1e-9));
}

TEST_CASE("too few key points, or points that do not see every mode, are refused", "[pca]") {
  PoseSet set;
  const sscc::PoseSubspace four(set.bar, set.training, sscc::test::pca_modes(4));
  CHECK_THROWS_WITH(sscc::KeyPointMap(four, {0}),
                    Catch::Contains("full column rank") && Catch::Contains("at least 2 points"));
  CHECK_THROWS_WITH(sscc::KeyPointMap(four, {0, 0}), Catch::Contains("twice"));
  CHECK_THROWS_WITH(sscc::KeyPointMap(four, {0, set.bar.vertex_count()}), Catch::Contains("out of range"));
  // Hold the half x < 0.5 of the bar still in every pose: the modes vanish there, so key
  // points in that half determine nothing.
  std::vector<int> still;
  for (int v = 0; v < set.bar.vertex_count(); ++v) {
    if (set.bar.vertices()[v].x() < 0.5) {
      still.push_back(v);
      set.training.middleRows<3>(3 * v).colwise() = set.bar.vertices()[v];
    }
  }
  const sscc::PoseSubspace half(set.bar, set.training, sscc::test::pca_modes(4));
  CHECK_THROWS_WITH(sscc::KeyPointMap(half, still), Catch::Contains("rank 0") && Catch::Contains("full column rank"));
}
