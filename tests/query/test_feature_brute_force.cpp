// The self query against the plainest reference there is, feature by feature: every pair of
// triangles that share no vertex (adjacency worked out here from the triangles' vertices),
// all 15 features of each through the kernels directly, nothing culled, no ownership, each
// feature recorded once. A query that tests a feature twice reports it twice and one that
// skips a feature misses it: both differ from this list.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <tuple>

#include "sscc/ccd/kernels.hpp"
#include "sscc/certificates/certificates.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "sscc/query/self_ccd.hpp"
#include "support/test_meshes.hpp"

namespace {

using FeatureKey = std::tuple<sscc::FeatureKind, int, int>;

bool share_a_vertex(const sscc::Triangle& a, const sscc::Triangle& b) {
  for (int v : a) {
    if (std::find(b.begin(), b.end(), v) != b.end()) return true;
  }
  return false;
}

struct BruteForce {
  std::vector<sscc::FeatureContact> features;    // sorted by (kind, first, second)
  std::vector<sscc::TrianglePairContact> pairs;  // sorted by (first, second)
};

BruteForce brute_force(const sscc::TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& x0,
                       const std::vector<Eigen::Vector3d>& x1, const sscc::ccd::CcdOptions& options = {}) {
  // The report names edges by their index in mesh.edges(); the pairs of vertices are ours.
  std::map<std::pair<int, int>, int> edge_index;
  for (std::size_t e = 0; e < mesh.edges().size(); ++e) edge_index[{mesh.edges()[e][0], mesh.edges()[e][1]}] = int(e);
  const auto edge_of = [&](int u, int v) { return edge_index.at({std::min(u, v), std::max(u, v)}); };
  std::map<FeatureKey, double> hits;
  std::map<std::pair<int, int>, double> pairs;
  const auto record = [&](const sscc::ccd::CcdResult& r, const FeatureKey& key, int a, int b) {
    if (!r.hit) return;
    const auto [it, inserted] = hits.emplace(key, r.toi);
    if (!inserted) REQUIRE(it->second == r.toi);  // the same feature, the same kernel call
    auto [p, first] = pairs.emplace(std::make_pair(a, b), r.toi);
    if (!first) p->second = std::min(p->second, r.toi);
  };
  const int n = mesh.triangle_count();
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      const sscc::Triangle& ta = mesh.triangles()[a];
      const sscc::Triangle& tb = mesh.triangles()[b];
      if (share_a_vertex(ta, tb)) continue;
      for (int side = 0; side < 2; ++side) {
        const sscc::Triangle& vertices = side == 0 ? ta : tb;
        const sscc::Triangle& f = side == 0 ? tb : ta;
        const int face = side == 0 ? b : a;
        for (int v : vertices) {
          record(sscc::ccd::vertex_face_ccd(x0[v], x0[f[0]], x0[f[1]], x0[f[2]], x1[v], x1[f[0]], x1[f[1]], x1[f[2]],
                                            options),
                 {sscc::FeatureKind::kVertexFace, v, face}, a, b);
        }
      }
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          int e = edge_of(ta[i], ta[(i + 1) % 3]), g = edge_of(tb[j], tb[(j + 1) % 3]);
          if (e > g) std::swap(e, g);
          const sscc::Edge& p = mesh.edges()[e];
          const sscc::Edge& q = mesh.edges()[g];
          record(sscc::ccd::edge_edge_ccd(x0[p[0]], x0[p[1]], x0[q[0]], x0[q[1]], x1[p[0]], x1[p[1]], x1[q[0]],
                                          x1[q[1]], options),
                 {sscc::FeatureKind::kEdgeEdge, e, g}, a, b);
        }
      }
    }
  }
  BruteForce result;
  for (const auto& [key, toi] : hits)
    result.features.push_back({std::get<0>(key), std::get<1>(key), std::get<2>(key), toi});
  for (const auto& [key, toi] : pairs) result.pairs.push_back({key.first, key.second, toi});
  return result;
}

void require_same(const sscc::SelfCcdReport& report, const BruteForce& expected) {
  REQUIRE(report.features == expected.features);
  REQUIRE(report.pairs == expected.pairs);
}

Eigen::VectorXd random_q(std::mt19937_64& rng, int r, double amplitude) {
  std::normal_distribution<double> normal;
  Eigen::VectorXd q(r);
  for (int j = 0; j < r; ++j) q[j] = amplitude * normal(rng) / std::sqrt(double(r));
  return q;
}

/// Every way of querying a detector (bounds, threads, certificates, given positions,
/// exhaustive) against the per-feature brute force on random steps of the given amplitudes;
/// returns how many steps collided.
int check_queries(const sscc::SubspaceModel& model, const sscc::SelfCcd& detector, std::uint64_t seed,
                  std::initializer_list<double> amplitudes) {
  std::mt19937_64 rng(seed);
  int colliding = 0;
  for (double amplitude : amplitudes) {
    for (int step = 0; step < 2; ++step) {
      const Eigen::VectorXd q0 = random_q(rng, model.mode_count(), amplitude);
      const Eigen::VectorXd q1 = q0 + random_q(rng, model.mode_count(), amplitude);
      const std::vector<Eigen::Vector3d> x0 = model.deformed_positions(q0);
      const std::vector<Eigen::Vector3d> x1 = model.deformed_positions(q1);
      const BruteForce expected = brute_force(model.mesh(), x0, x1);
      INFO("amplitude " << amplitude << " step " << step << ": " << expected.features.size() << " features");
      colliding += !expected.features.empty();
      for (auto bounds : {sscc::NodeBounds::kHybrid, sscc::NodeBounds::kRefit, sscc::NodeBounds::kSubspace}) {
        for (int threads : {1, 3}) {
          INFO("bounds " << int(bounds) << " threads " << threads);
          sscc::SelfCcdOptions options;  // the defaults, then without cones, then the cones alone
          options.bounds = bounds;
          options.threads = threads;
          require_same(detector.query(q0, q1, options), expected);
          options.use_normal_cones = false;
          require_same(detector.query(q0, q1, options), expected);
          sscc::set_traditional(options);
          options.use_normal_cones = true;
          require_same(detector.query(q0, q1, options), expected);
        }
      }
      require_same(detector.query_positions(x0, x1), expected);
      require_same(detector.query_exhaustive(q0, q1), expected);
    }
  }
  return colliding;
}

}  // namespace

TEST_CASE("self-CCD: every feature contact reported once, as the per-feature brute force finds it",
          "[query][brute_force]") {
  SECTION("sphere, 27 polynomial modes, with certificates") {
    const sscc::TriangleMesh mesh = sscc::test::uv_sphere(7, 12);
    const sscc::SubspaceModel model(mesh, sscc::polynomial_basis(mesh, 27), Eigen::VectorXd::Ones(27));
    const sscc::SubspaceBvh bvh(model);
    const sscc::SelfCcd detector(bvh, sscc::Certificates::precompute(bvh));
    CHECK(check_queries(model, detector, 3, {0.2, 0.6, 1.0}) >= 3);
  }
  SECTION("two sheets folding onto each other (features of many triangle pairs each)") {
    const sscc::TriangleMesh mesh = sscc::test::parallel_sheets(5, 0.1);
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> uniform(-0.1, 0.1);
    Eigen::MatrixXd basis(3 * mesh.vertex_count(), 4);
    for (Eigen::Index i = 0; i < basis.size(); ++i) basis.data()[i] = uniform(rng);
    for (int v = 0; v < mesh.vertex_count(); ++v) basis(3 * v + 2, 0) = -mesh.vertices()[v].z();
    const sscc::SubspaceModel model(mesh, basis, Eigen::VectorXd::Ones(4));
    const sscc::SubspaceBvh bvh(model);
    const sscc::SelfCcd detector(bvh);
    CHECK(check_queries(model, detector, 4, {0.5, 2.0, 4.0}) >= 3);
  }
}

TEST_CASE("self-CCD with a minimum separation: every feature within reach, once", "[query][brute_force]") {
  const sscc::TriangleMesh mesh = sscc::test::uv_sphere(5, 8);
  const sscc::SubspaceModel model(mesh, sscc::polynomial_basis(mesh, 9), Eigen::VectorXd::Ones(9));
  const sscc::SubspaceBvh bvh(model);
  const sscc::SelfCcd detector(bvh);
  std::mt19937_64 rng(8);
  int near = 0;
  for (int step = 0; step < 2; ++step) {
    const Eigen::VectorXd q0 = random_q(rng, 9, 0.6);
    const Eigen::VectorXd q1 = q0 + random_q(rng, 9, 0.6);
    sscc::SelfCcdOptions options;
    options.use_certificates = false;
    options.kernel.minimum_separation = 0.03;
    const BruteForce expected =
        brute_force(mesh, model.deformed_positions(q0), model.deformed_positions(q1), options.kernel);
    require_same(detector.query(q0, q1, options), expected);
    near += !expected.features.empty();
  }
  CHECK(near >= 1);
}
