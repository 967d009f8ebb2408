#include <catch2/catch.hpp>

#include <limits>
#include <random>
#include <thread>

#include "brute_force.hpp"
#include "sscc/ccd/kernels.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "sscc/query/self_ccd.hpp"
#include "support/test_meshes.hpp"

namespace {

struct Fixture {
  explicit Fixture(int rings = 10, int segments = 20) : mesh(sscc::test::uv_sphere(rings, segments)) {}
  sscc::TriangleMesh mesh;
  sscc::SubspaceModel model{mesh, sscc::polynomial_basis(mesh, 27), Eigen::VectorXd::Ones(27)};
  sscc::SubspaceBvh bvh{model};
  sscc::SelfCcd ccd{bvh};
};

Eigen::VectorXd random_q(std::mt19937_64& rng, double amplitude) {
  std::normal_distribution<double> normal;
  Eigen::VectorXd q(27);
  for (int j = 0; j < 27; ++j) q[j] = amplitude * normal(rng) / std::sqrt(27.0);
  return q;
}

/// Independent of the library's leaf code: every non-adjacent triangle pair, all 15 features
/// through the kernels directly, the earliest time per pair.
std::vector<sscc::TrianglePairContact> brute_force(const Fixture& f, const Eigen::VectorXd& q0,
                                                   const Eigen::VectorXd& q1,
                                                   const sscc::ccd::CcdOptions& options = {}) {
  const std::vector<Eigen::Vector3d> x0 = f.model.deformed_positions(q0);
  const std::vector<Eigen::Vector3d> x1 = f.model.deformed_positions(q1);
  std::vector<sscc::TrianglePairContact> pairs;
  for (int a = 0; a < f.mesh.triangle_count(); ++a) {
    for (int b = a + 1; b < f.mesh.triangle_count(); ++b) {
      if (f.mesh.adjacent(a, b)) continue;
      const double earliest =
          sscc::validation::triangle_pair_first_contact(x0, x1, f.mesh.triangles()[a], f.mesh.triangles()[b], options);
      if (earliest <= 1.0) pairs.push_back({a, b, earliest});
    }
  }
  return pairs;
}

}  // namespace

TEST_CASE("self-CCD: the traversal finds exactly the pairs brute force does", "[query]") {
  const Fixture f;
  std::mt19937_64 rng(23);
  int colliding = 0;
  for (double amplitude : {0.1, 0.4, 0.8}) {
    for (int step = 0; step < 3; ++step) {
      const Eigen::VectorXd q0 = random_q(rng, amplitude);
      const Eigen::VectorXd q1 = q0 + random_q(rng, amplitude);
      INFO("amplitude " << amplitude << " step " << step);
      const auto expected = brute_force(f, q0, q1);
      const auto found = f.ccd.query(q0, q1).pairs;
      REQUIRE(found.size() == expected.size());
      for (std::size_t i = 0; i < found.size(); ++i) {
        CHECK(found[i].first == expected[i].first);
        CHECK(found[i].second == expected[i].second);
        // Both times are within the tolerance below the first contact; the kernels see
        // the edges' end points in another order here, so the last digits may differ.
        CHECK(std::abs(found[i].toi - expected[i].toi) <= sscc::ccd::kDefaultToiTolerance);
      }
      colliding += !expected.empty();
    }
  }
  CHECK(colliding >= 3);
}

TEST_CASE("self-CCD: the traversal reports exactly what exhaustive testing does", "[query]") {
  const Fixture f;
  std::mt19937_64 rng(21);
  int colliding = 0;
  int quiet = 0;
  for (double amplitude : {0.02, 0.15, 0.4, 0.8}) {
    for (int step = 0; step < 6; ++step) {
      const Eigen::VectorXd q0 = random_q(rng, amplitude);
      const Eigen::VectorXd q1 = q0 + random_q(rng, amplitude);
      const sscc::SelfCcdReport fast = f.ccd.query(q0, q1);
      const sscc::SelfCcdReport all = f.ccd.query_exhaustive(q0, q1);
      sscc::SelfCcdOptions subspace;
      subspace.bounds = sscc::NodeBounds::kSubspace;
      const sscc::SelfCcdReport lazy = f.ccd.query(q0, q1, subspace);
      sscc::SelfCcdOptions refit;
      refit.bounds = sscc::NodeBounds::kRefit;
      const sscc::SelfCcdReport refitted = f.ccd.query(q0, q1, refit);
      CHECK(refitted.pairs == all.pairs);
      CHECK(refitted.features == all.features);
      const sscc::SelfCcdReport given =
          f.ccd.query_positions(f.model.deformed_positions(q0), f.model.deformed_positions(q1));
      INFO("amplitude " << amplitude << " step " << step);
      CHECK(given.pairs == all.pairs);
      CHECK(given.features == all.features);
      CHECK(fast.pairs == all.pairs);
      CHECK(fast.features == all.features);
      CHECK(fast.earliest_toi == all.earliest_toi);
      CHECK(lazy.pairs == all.pairs);
      CHECK(lazy.features == all.features);
      CHECK(fast.stats.triangle_pairs <= all.stats.triangle_pairs);
      (fast.collided() ? colliding : quiet) += 1;
      for (const auto& p : fast.pairs) CHECK_FALSE(f.mesh.adjacent(p.first, p.second));
      // Any-hit agrees on whether the step collides, and reports one of the pairs.
      sscc::SelfCcdOptions any;
      any.mode = sscc::SelfCcdMode::kAnyHit;
      const sscc::SelfCcdReport first = f.ccd.query(q0, q1, any);
      CHECK(first.collided() == fast.collided());
      if (first.collided()) {
        REQUIRE(first.features.size() == 1);
        CHECK(std::find(fast.features.begin(), fast.features.end(), first.features[0]) != fast.features.end());
        for (const auto& p : first.pairs) {
          CHECK(std::find_if(fast.pairs.begin(), fast.pairs.end(), [&](const auto& q) {
                  return p.first == q.first && p.second == q.second;
                }) != fast.pairs.end());
        }
      }
    }
  }
  CHECK(colliding >= 4);
  CHECK(quiet >= 4);
}

TEST_CASE("self-CCD: earliest-only mode and concurrent queries", "[query]") {
  const Fixture f;
  std::mt19937_64 rng(24);
  std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> steps;
  for (int i = 0; i < 8; ++i) {
    const Eigen::VectorXd q0 = random_q(rng, 0.5);
    steps.emplace_back(q0, q0 + random_q(rng, 0.5));
  }
  std::vector<sscc::SelfCcdReport> serial;
  for (const auto& [q0, q1] : steps) serial.push_back(f.ccd.query(q0, q1));
  int collided = 0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    sscc::SelfCcdOptions earliest;
    earliest.mode = sscc::SelfCcdMode::kEarliest;
    const sscc::SelfCcdReport first = f.ccd.query(steps[i].first, steps[i].second, earliest);
    REQUIRE(first.collided() == serial[i].collided());
    if (!first.collided()) continue;
    ++collided;
    CHECK(first.earliest_toi == serial[i].earliest_toi);
    for (const auto& c : first.features) CHECK(c.toi == serial[i].earliest_toi);
    for (const auto& p : first.pairs) CHECK(p.toi == serial[i].earliest_toi);
  }
  CHECK(collided >= 2);
  // Two threads querying the same detector get the serial answers.
  std::vector<sscc::SelfCcdReport> parallel(steps.size());
  const auto worker = [&](std::size_t begin) {
    for (std::size_t i = begin; i < steps.size(); i += 2) parallel[i] = f.ccd.query(steps[i].first, steps[i].second);
  };
  std::thread other(worker, 1);
  worker(0);
  other.join();
  for (std::size_t i = 0; i < steps.size(); ++i) {
    CHECK(parallel[i].pairs == serial[i].pairs);
    CHECK(parallel[i].features == serial[i].features);
  }
}

TEST_CASE("self-CCD: discrete query against all pairs", "[query]") {
  const Fixture f;
  std::mt19937_64 rng(22);
  int intersecting = 0;
  for (double amplitude : {0.05, 0.5, 1.0}) {
    for (int sample = 0; sample < 4; ++sample) {
      const Eigen::VectorXd q = random_q(rng, amplitude);
      const std::vector<Eigen::Vector3d> x = f.model.deformed_positions(q);
      std::vector<std::pair<int, int>> expected;
      for (int a = 0; a < f.mesh.triangle_count(); ++a) {
        for (int b = a + 1; b < f.mesh.triangle_count(); ++b) {
          if (f.mesh.adjacent(a, b)) continue;
          const auto& ta = f.mesh.triangles()[a];
          const auto& tb = f.mesh.triangles()[b];
          if (sscc::ccd::triangles_intersect(x[ta[0]], x[ta[1]], x[ta[2]], x[tb[0]], x[tb[1]], x[tb[2]])) {
            expected.emplace_back(a, b);
          }
        }
      }
      const sscc::SelfCcdReport report = f.ccd.query_discrete(q);
      std::vector<std::pair<int, int>> found;
      for (const auto& p : report.pairs) found.emplace_back(p.first, p.second);
      CHECK(found == expected);
      intersecting += !expected.empty();
    }
  }
  CHECK(intersecting >= 2);
}

TEST_CASE("self-CCD: huge coordinates with tiny modes keep every bound finite", "[query]") {
  // ||q_hat||^2 overflows a double here; the bounds must not turn into NaN and cull.
  std::vector<Eigen::Vector3d> x;
  std::vector<sscc::Triangle> t;
  for (int i = 0; i < 8; ++i) {
    const int b = static_cast<int>(x.size());
    x.push_back({1.0 * i, 0, 0});
    x.push_back({i + 0.5, 0, 0});
    x.push_back({1.0 * i, 0.5, 0});
    t.push_back({b, b + 1, b + 2});
  }
  const sscc::TriangleMesh mesh(x, t);
  Eigen::MatrixXd u = Eigen::MatrixXd::Zero(3 * 24, 1);
  for (int v = 0; v < 24; ++v) {
    if ((v / 3) % 2) u(3 * v, 0) = -1e-160;  // odd triangles slide onto the even ones
  }
  const sscc::SubspaceModel model(mesh, u, Eigen::VectorXd::Ones(1));
  const sscc::SubspaceBvh bvh(model);
  const sscc::SelfCcd detector(bvh);
  const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(1);
  const Eigen::VectorXd q1 = Eigen::VectorXd::Constant(1, 1e160);
  const auto expected = detector.query_exhaustive(q0, q1).pairs;
  CHECK(expected.size() == 4);
  for (auto bounds : {sscc::NodeBounds::kHybrid, sscc::NodeBounds::kRefit, sscc::NodeBounds::kSubspace}) {
    sscc::SelfCcdOptions options;
    options.bounds = bounds;
    CHECK(detector.query(q0, q1, options).pairs == expected);
  }
  CHECK(detector.query_discrete(q1).pairs.size() == 4);
}

TEST_CASE("self-CCD: huge modes moved by tiny coordinates, every cull on, as exhaustive testing", "[query]") {
  // Modes of entries near 1e170 (their squares and their rates' products overflow) moved by
  // coordinates near 1e-170 move the sphere as the polynomial modes at scale 1 do: the
  // hierarchy, the cones bounded from the norm and the displacement bounds must neither trap
  // (the test runner traps overflow) nor cull a contact.
  const sscc::TriangleMesh mesh = sscc::test::uv_sphere(8, 16);
  const sscc::SubspaceModel model(mesh, 1e170 * sscc::polynomial_basis(mesh, 27), Eigen::VectorXd::Ones(27));
  const sscc::SubspaceBvh bvh(model);
  const sscc::SelfCcd detector(bvh);
  sscc::SelfCcdOptions options;  // the defaults: normal cones and displacement bounds on
  std::mt19937_64 rng(3);
  int colliding = 0;
  long radius_culls = 0;
  for (double amplitude : {0.01, 0.05, 0.25, 1.0}) {
    for (int step = 0; step < 4; ++step) {
      const Eigen::VectorXd q0 = 1e-170 * random_q(rng, amplitude);
      const Eigen::VectorXd q1 = 1e-170 * random_q(rng, amplitude);
      const sscc::SelfCcdReport report = detector.query(q0, q1, options);
      const sscc::SelfCcdReport expected = detector.query_exhaustive(q0, q1, options);
      INFO("amplitude " << amplitude << ", step " << step);
      CHECK(report.pairs == expected.pairs);
      CHECK(report.features == expected.features);
      colliding += expected.collided();
      radius_culls += report.stats.cone_radius_culled;
    }
  }
  CHECK(colliding > 0);
  CHECK(radius_culls > 0);  // the cones bounded from the norm cull at this scale too
}

TEST_CASE("self-CCD: a step that does not move reports nothing, bad q is refused", "[query]") {
  const Fixture f;
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(27);
  CHECK_FALSE(f.ccd.query(rest, rest).collided());
  CHECK_THROWS_WITH(f.ccd.query(Eigen::VectorXd::Zero(3), rest), Catch::Contains("q has 3 coordinates"));
  Eigen::VectorXd bad = rest;
  bad[4] = std::nan("");
  CHECK_THROWS_WITH(f.ccd.query(rest, bad), Catch::Contains("q[4] is not finite"));
}

TEST_CASE("self-CCD on given positions: wrong counts and non-finite coordinates are refused", "[query]") {
  const Fixture f;
  std::vector<Eigen::Vector3d> x = f.mesh.vertices();
  std::vector<Eigen::Vector3d> short_x(x.begin(), x.end() - 1);
  CHECK_THROWS_WITH(f.ccd.query_positions(x, short_x), Catch::Contains("positions given"));
  std::vector<Eigen::Vector3d> bad = x;
  bad[5][1] = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH(f.ccd.query_positions(bad, x), Catch::Contains("vertex 5"));
  CHECK_FALSE(f.ccd.query_positions(x, x).collided());
}

TEST_CASE("self-CCD with a minimum separation: every cull widened, pairs as brute force finds them", "[query]") {
  // Two parallel triangles: the top one comes down to 0.5 above the bottom one, never
  // touching; with d = 1 they are a pair.
  const sscc::TriangleMesh two({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 2}, {1, 0, 2}, {0, 1, 2}},
                               {{0, 1, 2}, {3, 4, 5}});
  Eigen::MatrixXd down = Eigen::MatrixXd::Zero(18, 1);
  for (int v = 3; v < 6; ++v) down(3 * v + 2, 0) = -1.0;
  const sscc::SubspaceModel model(two, down, Eigen::VectorXd::Ones(1));
  const sscc::SubspaceBvh bvh(model);
  const sscc::SelfCcd ccd(bvh);
  sscc::SelfCcdOptions thick;
  thick.kernel.minimum_separation = 1.0;
  for (auto bounds : {sscc::NodeBounds::kHybrid, sscc::NodeBounds::kRefit, sscc::NodeBounds::kSubspace}) {
    thick.bounds = bounds;
    CHECK(ccd.query(Eigen::VectorXd::Zero(1), Eigen::VectorXd::Constant(1, 1.5), thick).collided());
    CHECK_FALSE(ccd.query(Eigen::VectorXd::Zero(1), Eigen::VectorXd::Constant(1, 0.9), thick).collided());
  }
  CHECK(ccd.query_exhaustive(Eigen::VectorXd::Zero(1), Eigen::VectorXd::Constant(1, 1.5), thick).collided());

  const Fixture f(5, 8);  // small: the separation kernels are slow and brute force is O(N^2)
  std::mt19937_64 rng(31);
  int thick_only = 0;
  for (int step = 0; step < 3; ++step) {
    const Eigen::VectorXd q0 = random_q(rng, 0.3);
    const Eigen::VectorXd q1 = q0 + random_q(rng, 0.3);
    sscc::SelfCcdOptions options;
    options.kernel.minimum_separation = 0.005;
    const auto expected = brute_force(f, q0, q1, options.kernel);
    const auto found = f.ccd.query(q0, q1, options).pairs;
    REQUIRE(found.size() == expected.size());
    for (std::size_t i = 0; i < found.size(); ++i) {
      CHECK(found[i].first == expected[i].first);
      CHECK(found[i].second == expected[i].second);
    }
    thick_only += found.size() > f.ccd.query(q0, q1).pairs.size();
  }
  CHECK(thick_only >= 1);
}
