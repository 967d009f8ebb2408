// The self query on several threads reports exactly what it reports on one: the same pairs,
// features and earliest time, in the same order, in every mode (the first hit included).
#include <catch2/catch.hpp>

#include <random>
#include <thread>

#include "certificates/certificate_fixtures.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "sscc/query/self_ccd.hpp"
#include "support/test_meshes.hpp"

namespace {

constexpr int kThreadCounts[] = {2, 3, 4, 8};

Eigen::VectorXd random_q(std::mt19937_64& rng, int r, double amplitude) {
  std::normal_distribution<double> normal;
  Eigen::VectorXd q(r);
  for (int j = 0; j < r; ++j) q[j] = amplitude * normal(rng) / std::sqrt(double(r));
  return q;
}

void require_same_report(const sscc::SelfCcdReport& parallel, const sscc::SelfCcdReport& serial) {
  REQUIRE(parallel.pairs == serial.pairs);
  REQUIRE(parallel.features == serial.features);
  REQUIRE(parallel.earliest_toi == serial.earliest_toi);
  REQUIRE(parallel.stats.root_certified == serial.stats.root_certified);
}

sscc::SelfCcdOptions with(sscc::SelfCcdMode mode, sscc::NodeBounds bounds, int threads, bool certificates = true) {
  sscc::SelfCcdOptions options;
  options.mode = mode;
  options.bounds = bounds;
  options.threads = threads;
  options.use_certificates = certificates;
  return options;
}

constexpr sscc::SelfCcdMode kModes[] = {sscc::SelfCcdMode::kAllContacts, sscc::SelfCcdMode::kEarliest,
                                        sscc::SelfCcdMode::kAnyHit};
constexpr sscc::NodeBounds kBounds[] = {sscc::NodeBounds::kHybrid, sscc::NodeBounds::kRefit,
                                        sscc::NodeBounds::kSubspace};

/// Every mode, bound kind and thread count against one thread, for the query on q and on
/// given positions; returns how many steps collided.
int check_steps(const sscc::SelfCcd& ccd, const std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>>& steps) {
  const sscc::SubspaceModel& model = ccd.bvh().model();
  int colliding = 0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const auto& [q0, q1] = steps[i];
    const std::vector<Eigen::Vector3d> x0 = model.deformed_positions(q0);
    const std::vector<Eigen::Vector3d> x1 = model.deformed_positions(q1);
    for (sscc::SelfCcdMode mode : kModes) {
      for (sscc::NodeBounds bounds : kBounds) {
        const sscc::SelfCcdReport serial = ccd.query(q0, q1, with(mode, bounds, 1));
        if (mode == sscc::SelfCcdMode::kAllContacts && bounds == sscc::NodeBounds::kHybrid) {
          colliding += serial.collided();
        }
        for (int threads : kThreadCounts) {
          INFO("step " << i << " mode " << int(mode) << " bounds " << int(bounds) << " threads " << threads);
          require_same_report(ccd.query(q0, q1, with(mode, bounds, threads)), serial);
        }
      }
      const sscc::SelfCcdReport serial = ccd.query_positions(x0, x1, with(mode, sscc::NodeBounds::kRefit, 1));
      for (int threads : kThreadCounts) {
        INFO("step " << i << " given positions, mode " << int(mode) << " threads " << threads);
        require_same_report(ccd.query_positions(x0, x1, with(mode, sscc::NodeBounds::kRefit, threads)), serial);
      }
    }
  }
  return colliding;
}

}  // namespace

TEST_CASE("parallel self-CCD: reports equal the serial ones on every thread count and mode", "[query][parallel]") {
  const sscc::TriangleMesh mesh = sscc::test::uv_sphere(10, 20);
  const sscc::SubspaceModel model{mesh, sscc::polynomial_basis(mesh, 27), Eigen::VectorXd::Ones(27)};
  const sscc::SubspaceBvh bvh{model};
  const sscc::SelfCcd ccd{bvh};
  std::mt19937_64 rng(31);
  std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> steps;
  for (double amplitude : {0.02, 0.15, 0.4, 0.8}) {
    for (int step = 0; step < 4; ++step) {
      const Eigen::VectorXd q0 = random_q(rng, 27, amplitude);
      steps.emplace_back(q0, q0 + random_q(rng, 27, amplitude));
    }
  }
  const int colliding = check_steps(ccd, steps);
  CHECK(colliding >= 4);
  CHECK(colliding <= static_cast<int>(steps.size()) - 4);
}

TEST_CASE("parallel self-CCD: with certificates, steps around the root radius", "[query][parallel]") {
  const auto sphere = sscc::test::certified_sphere();
  const sscc::SelfCcd ccd(sphere->bvh, sphere->certificates);
  const double root = sphere->certificates.node_radius(0);
  std::mt19937_64 rng(32);
  std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> steps;
  int root_certified = 0;
  for (double factor : {0.5, 1.5, 3.0, 8.0, 20.0}) {
    for (int step = 0; step < 3; ++step) {
      // Unit weights: scaled coordinates are the coordinates.
      const Eigen::VectorXd q0 = sscc::test::random_scaled_coordinates(rng, 27, factor * root);
      const Eigen::VectorXd q1 = sscc::test::random_scaled_coordinates(rng, 27, factor * root);
      steps.emplace_back(q0, q1);
      root_certified +=
          ccd.query(q0, q1, with(sscc::SelfCcdMode::kAllContacts, sscc::NodeBounds::kHybrid, 4)).stats.root_certified;
    }
  }
  CHECK(root_certified == 3);  // the steps at half the root radius, on four threads too
  // The threads a query runs on: one within twice the root radius (kFarPastCertificateRatio),
  // all beyond it and without certificates.
  const auto threads_at = [&](double factor, bool certificates) {
    const Eigen::VectorXd q = factor * root * Eigen::VectorXd::Unit(27, 3);
    return ccd.query_threads(-q, q, with(sscc::SelfCcdMode::kAllContacts, sscc::NodeBounds::kHybrid, 4, certificates));
  };
  CHECK(threads_at(0.5, true) == 1);
  CHECK(threads_at(1.5, true) == 1);
  CHECK(threads_at(3.0, true) == 4);
  CHECK(threads_at(0.5, false) == 4);
  CHECK(check_steps(ccd, steps) >= 1);
  // The traditional query on the same steps.
  for (const auto& step : steps) {
    const auto off = [&](int threads) {
      return ccd.query(step.first, step.second,
                       with(sscc::SelfCcdMode::kAllContacts, sscc::NodeBounds::kHybrid, threads, false));
    };
    require_same_report(off(2), off(1));
  }
}

TEST_CASE("parallel self-CCD: concurrent callers of one detector, each on several threads", "[query][parallel]") {
  const sscc::TriangleMesh mesh = sscc::test::uv_sphere(10, 20);
  const sscc::SubspaceModel model{mesh, sscc::polynomial_basis(mesh, 27), Eigen::VectorXd::Ones(27)};
  const sscc::SubspaceBvh bvh{model};
  const sscc::SelfCcd ccd{bvh};
  std::mt19937_64 rng(33);
  std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> steps;
  for (int i = 0; i < 6; ++i) {
    const Eigen::VectorXd q0 = random_q(rng, 27, 0.6);
    steps.emplace_back(q0, q0 + random_q(rng, 27, 0.6));
  }
  std::vector<sscc::SelfCcdReport> serial;
  std::vector<sscc::SelfCcdReport> first_hits;
  for (const auto& [q0, q1] : steps) {
    serial.push_back(ccd.query(q0, q1, with(sscc::SelfCcdMode::kAllContacts, sscc::NodeBounds::kHybrid, 1)));
    first_hits.push_back(ccd.query(q0, q1, with(sscc::SelfCcdMode::kAnyHit, sscc::NodeBounds::kHybrid, 1)));
  }
  std::vector<sscc::SelfCcdReport> all(steps.size());
  std::vector<sscc::SelfCcdReport> any(steps.size());
  const auto worker = [&](std::size_t begin) {
    for (std::size_t i = begin; i < steps.size(); i += 2) {
      all[i] = ccd.query(steps[i].first, steps[i].second,
                         with(sscc::SelfCcdMode::kAllContacts, sscc::NodeBounds::kHybrid, 2));
      any[i] =
          ccd.query(steps[i].first, steps[i].second, with(sscc::SelfCcdMode::kAnyHit, sscc::NodeBounds::kHybrid, 3));
    }
  };
  std::thread other(worker, 1);
  worker(0);
  other.join();
  int colliding = 0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    INFO("step " << i);
    require_same_report(all[i], serial[i]);
    require_same_report(any[i], first_hits[i]);
    colliding += serial[i].collided();
  }
  CHECK(colliding >= 2);
}
