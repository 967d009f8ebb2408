#include <catch2/catch.hpp>

#include "basis/pose_fixtures.hpp"
#include "sscc/basis/key_points.hpp"
#include "sscc/ccd/kernels.hpp"
#include "sscc/experimental/cull_validation.hpp"
#include "sscc/experimental/node_collisions.hpp"

namespace {

using sscc::test::CertifiedPoses;

std::vector<Eigen::VectorXd> key_point_coordinates(const sscc::KeyPointMap& keys, const Eigen::MatrixXd& poses) {
  std::vector<Eigen::VectorXd> q;
  for (Eigen::Index p = 0; p < poses.cols(); ++p) q.push_back(keys.coordinates_of_pose(poses.col(p)));
  return q;
}

/// The nodes holding an intersecting non-adjacent pair, by brute force: every pair through
/// the exact triangle test, every node's range checked directly.
std::vector<char> brute_force_colliding_nodes(const sscc::SubspaceBvh& bvh, const Eigen::VectorXd& q) {
  const sscc::TriangleMesh& mesh = bvh.model().mesh();
  const std::vector<Eigen::Vector3d> x = bvh.model().deformed_positions(q);
  std::vector<int> position(mesh.triangle_count());
  for (int i = 0; i < mesh.triangle_count(); ++i) position[bvh.triangle_order()[i]] = i;
  std::vector<char> colliding(bvh.nodes().size(), 0);
  for (int a = 0; a < mesh.triangle_count(); ++a) {
    for (int b = a + 1; b < mesh.triangle_count(); ++b) {
      if (mesh.adjacent(a, b)) continue;
      const sscc::Triangle& s = mesh.triangles()[a];
      const sscc::Triangle& t = mesh.triangles()[b];
      if (!sscc::ccd::triangles_intersect(x[s[0]], x[s[1]], x[s[2]], x[t[0]], x[t[1]], x[t[2]])) continue;
      for (std::size_t n = 0; n < colliding.size(); ++n) {
        const sscc::SubspaceBvh::Node& node = bvh.nodes()[n];
        const auto inside = [&](int triangle) {
          return node.triangle_begin <= position[triangle] && position[triangle] < node.triangle_end;
        };
        if (inside(a) && inside(b)) colliding[n] = 1;
      }
    }
  }
  return colliding;
}

}  // namespace

TEST_CASE("EXPERIMENTAL predicted culling: false culls counted beside the sound certificates', which have none",
          "[pca]") {
  const int training = 30;
  const CertifiedPoses f(45, training, 13, sscc::test::pca_fraction(0.999));
  const Eigen::MatrixXd train = f.poses.leftCols(training);
  const Eigen::MatrixXd held_out = f.poses.rightCols(f.poses.cols() - training);
  const sscc::KeyPointMap keys(f.subspace, sscc::select_key_points(f.subspace, train).vertices);
  const std::vector<Eigen::VectorXd> train_q = key_point_coordinates(keys, train);
  const std::vector<Eigen::VectorXd> held_q = key_point_coordinates(keys, held_out);
  std::vector<std::vector<char>> train_truth;
  for (const Eigen::VectorXd& q : train_q) train_truth.push_back(sscc::experimental::colliding_nodes(f.bvh, q));
  std::vector<std::vector<char>> held_truth;
  for (const Eigen::VectorXd& q : held_q) {
    held_truth.push_back(sscc::experimental::colliding_nodes(f.bvh, q));
    CHECK(held_truth.back() == brute_force_colliding_nodes(f.bvh, q));  // the ground truth itself
  }
  const sscc::experimental::CullingPredictor predictor =
      sscc::experimental::CullingPredictor::fit(f.bvh, train_q, train_truth);
  CHECK(predictor.node_count() == static_cast<int>(f.bvh.nodes().size()));
  CHECK(predictor.feature_count() == 2 * f.model.mode_count() + 1);

  const sscc::experimental::CullValidation on_training =
      sscc::experimental::validate_culling(f.bvh, f.certificates, predictor, train_q, train_truth);
  const sscc::experimental::CullValidation on_held_out =
      sscc::experimental::validate_culling(f.bvh, f.certificates, predictor, held_q, held_truth);
  for (const sscc::experimental::CullValidation* v : {&on_training, &on_held_out}) {
    WARN((v == &on_training ? "training" : "held-out")
         << " poses: " << v->colliding_poses << " of " << v->poses << " collide, " << v->colliding
         << " colliding (pose, node) pairs; sound certificates cull " << v->sound.culled << " with "
         << v->sound.false_culls << " false culls; EXPERIMENTAL (NOT CONSERVATIVE) predictor culls "
         << v->predicted.culled << " with " << v->predicted.false_culls << " false culls, "
         << v->predicted.poses_falsely_free << " colliding poses declared free");
    CHECK(v->colliding > 0);           // there is something to get wrong
    CHECK(v->sound.culled > 0);        // the certificates do cull
    CHECK(v->sound.false_culls == 0);  // and never wrongly
    CHECK(v->sound.poses_falsely_free == 0);
  }
  // Thresholds are set so that no training pose is culled where it collides.
  CHECK(on_training.predicted.false_culls == 0);
  // The held-out counts, recounted from the predictor's decisions.
  long culled = 0;
  long false_culls = 0;
  for (std::size_t p = 0; p < held_q.size(); ++p) {
    const std::vector<char> free = predictor.predicted_free(held_q[p]);
    for (std::size_t n = 0; n < free.size(); ++n) {
      culled += free[n];
      false_culls += free[n] && held_truth[p][n];
    }
  }
  CHECK(on_held_out.predicted.culled == culled);
  CHECK(on_held_out.predicted.false_culls == false_culls);
}

TEST_CASE("the culling predictor and its validation refuse inputs of the wrong shape", "[pca]") {
  const CertifiedPoses f(8, 8, 3, sscc::test::pca_modes(3), 1.0);  // certificates only to be refused
  const std::vector<Eigen::VectorXd> q = {Eigen::VectorXd::Zero(3)};
  const std::vector<std::vector<char>> truth = {std::vector<char>(f.bvh.nodes().size(), 0)};
  CHECK_THROWS_WITH(sscc::experimental::CullingPredictor::fit(f.bvh, {}, {}), Catch::Contains("no training poses"));
  CHECK_THROWS_WITH(sscc::experimental::CullingPredictor::fit(f.bvh, q, {}), Catch::Contains("ground truths"));
  CHECK_THROWS_WITH(sscc::experimental::CullingPredictor::fit(f.bvh, {Eigen::VectorXd::Zero(2)}, truth),
                    Catch::Contains("finite"));
  CHECK_THROWS_WITH(sscc::experimental::CullingPredictor::fit(f.bvh, q, {std::vector<char>(2, 0)}),
                    Catch::Contains("per node"));
  const sscc::experimental::CullingPredictor predictor = sscc::experimental::CullingPredictor::fit(f.bvh, q, truth);
  CHECK_THROWS_WITH(predictor.scores(Eigen::VectorXd::Zero(5)), Catch::Contains("finite coordinates"));
  const sscc::SubspaceBvh other_tree(f.model, 2);  // another k-means seed: another hierarchy
  CHECK_THROWS_WITH(sscc::experimental::validate_culling(other_tree, f.certificates, predictor, q, truth),
                    Catch::Contains("another"));
  CHECK_THROWS_WITH(sscc::experimental::validate_culling(f.bvh, f.certificates, predictor, q, {}),
                    Catch::Contains("ground truths"));
}
