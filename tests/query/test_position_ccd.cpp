// The detector for simulators without a subspace: built from the mesh alone, it answers a
// step given by vertex positions exactly as exhaustive testing does.
#include <catch2/catch.hpp>

#include <random>

#include "sscc/model/polynomial_basis.hpp"
#include "sscc/query/position_ccd.hpp"
#include "support/pair_reference.hpp"
#include "support/test_meshes.hpp"

namespace {

/// Positions moved from `from` by independent Gaussian offsets of `amplitude` per
/// coordinate: full-space motion no basis holds.
std::vector<Eigen::Vector3d> jittered(const std::vector<Eigen::Vector3d>& from, double amplitude,
                                      std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  std::vector<Eigen::Vector3d> x = from;
  for (Eigen::Vector3d& p : x) p += amplitude * Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
  return x;
}

}  // namespace

TEST_CASE("position CCD: a detector from the mesh alone equals exhaustive testing on random trajectories", "[query]") {
  const sscc::TriangleMesh mesh = sscc::test::uv_sphere(8, 16);
  const sscc::PositionCcd ccd(mesh);
  std::mt19937_64 rng(31);
  int colliding = 0, quiet = 0;
  for (double amplitude : {0.01, 0.05, 0.1, 0.2}) {
    // A trajectory of four steps: each step's end is the next one's start.
    std::vector<Eigen::Vector3d> x = jittered(mesh.vertices(), amplitude, rng);
    for (int step = 0; step < 4; ++step) {
      const std::vector<Eigen::Vector3d> next = jittered(x, amplitude, rng);
      INFO("amplitude " << amplitude << " step " << step);
      const sscc::SelfCcdReport report = ccd.query(x, next);
      sscc::test::require_same_pairs(report.pairs, sscc::test::brute_force_pairs(mesh, x, next));
      (report.collided() ? colliding : quiet) += 1;
      x = next;
    }
  }
  CHECK(colliding >= 3);
  CHECK(quiet >= 3);
}

TEST_CASE("position CCD: the same report as a subspace detector's query_positions, exclusions honoured", "[query]") {
  const sscc::TriangleMesh mesh = sscc::test::two_spheres(6, 12, sscc::test::kTwoSpheresOffset);
  const sscc::ExcludedPairs excluded = sscc::ExcludedPairs::touching_at_rest(mesh);
  REQUIRE_FALSE(excluded.empty());
  const sscc::PositionCcd ccd(mesh, excluded);
  CHECK(ccd.excluded_pairs().pairs() == excluded.pairs());
  const sscc::SubspaceModel model =
      sscc::SubspaceModel(mesh, sscc::polynomial_basis(mesh, 10), Eigen::VectorXd::Ones(10)).excluding(excluded);
  const sscc::SelfCcd subspace{sscc::SubspaceBvh(model)};
  std::mt19937_64 rng(37);
  sscc::SelfCcdOptions one_thread, plain;  // the defaults have the cones
  one_thread.threads = 1;
  plain.use_normal_cones = false;
  int colliding = 0;
  for (double amplitude : {0.02, 0.08}) {
    for (int step = 0; step < 4; ++step) {
      const std::vector<Eigen::Vector3d> x0 = jittered(mesh.vertices(), amplitude, rng);
      const std::vector<Eigen::Vector3d> x1 = jittered(x0, amplitude, rng);
      const sscc::SelfCcdReport report = ccd.query(x0, x1);
      const sscc::SelfCcdReport reference = subspace.query_positions(x0, x1);
      CHECK(report.pairs == reference.pairs);
      CHECK(report.features == reference.features);
      for (const sscc::SelfCcdOptions& options : {one_thread, plain}) {
        const sscc::SelfCcdReport other = ccd.query(x0, x1, options);
        CHECK(other.pairs == report.pairs);
        CHECK(other.features == report.features);
      }
      sscc::test::require_same_pairs(report.pairs, sscc::test::brute_force_pairs(mesh, x0, x1, excluded));
      for (const auto& p : report.pairs) CHECK_FALSE(excluded.contains(p.first, p.second));
      colliding += report.collided();
    }
  }
  CHECK(colliding >= 2);
}

TEST_CASE("position CCD: wrong position counts and NaN are refused", "[query]") {
  const sscc::TriangleMesh mesh = sscc::test::uv_sphere(4, 8);
  const sscc::PositionCcd ccd(mesh);
  std::vector<Eigen::Vector3d> x = mesh.vertices();
  CHECK_THROWS_AS(ccd.query(x, std::vector<Eigen::Vector3d>(x.begin(), x.end() - 1)), std::invalid_argument);
  x[2].y() = std::nan("");
  CHECK_THROWS_AS(ccd.query(mesh.vertices(), x), std::invalid_argument);
}
