#include <catch2/catch.hpp>

#include "certificate_fixtures.hpp"
#include "sscc/ccd/kernels.hpp"
#include "sscc/query/self_ccd.hpp"
#include "sscc/threads.hpp"

namespace {

using sscc::test::CertifiedModel;

/// The considered triangle pairs (neither adjacent nor excluded), one from each list (or
/// within one list when the lists are the same), that intersect at configuration q (exact).
int intersecting_pairs(const sscc::SubspaceModel& model, const std::vector<int>& first, const std::vector<int>& second,
                       bool same, const Eigen::VectorXd& q) {
  const sscc::TriangleMesh& mesh = model.mesh();
  const std::vector<Eigen::Vector3d> x = model.deformed_positions(q);
  int found = 0;
  for (std::size_t i = 0; i < first.size(); ++i) {
    for (std::size_t j = same ? i + 1 : 0; j < second.size(); ++j) {
      const int a = first[i], b = second[j];
      if (!model.considers(a, b)) continue;
      const sscc::Triangle& ta = mesh.triangles()[a];
      const sscc::Triangle& tb = mesh.triangles()[b];
      found += sscc::ccd::triangles_intersect(x[ta[0]], x[ta[1]], x[ta[2]], x[tb[0]], x[tb[1]], x[tb[2]]);
    }
  }
  return found;
}

std::vector<int> triangles_under(const sscc::SubspaceBvh& bvh, int n) {
  const sscc::SubspaceBvh::Node& node = bvh.nodes()[n];
  return {bvh.triangle_order().begin() + node.triangle_begin, bvh.triangle_order().begin() + node.triangle_end};
}

/// Configurations inside the ellipsoid ||q||_M < radius: on its boundary (just inside) and
/// uniform in its volume. Returned as reduced coordinates q.
std::vector<Eigen::VectorXd> inside(const sscc::SubspaceModel& model, double radius, int count, std::mt19937_64& rng) {
  const int r = model.mode_count();
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Eigen::VectorXd> q;
  for (int i = 0; i < count; ++i) {
    const double norm = i % 2 == 0 ? radius * (1.0 - 1e-9) : radius * std::pow(uniform(rng), 1.0 / r);
    q.push_back(sscc::test::random_scaled_coordinates(rng, r, norm).cwiseQuotient(model.weights().cwiseSqrt()));
  }
  return q;
}

/// Every node and sibling pair: sampled configurations inside its certificate have no
/// touching non-adjacent pair under it.
void check_certificates_by_sampling(const CertifiedModel& m, int samples, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const auto& nodes = m.bvh.nodes();
  int checked = 0;
  for (int n = 0; n < static_cast<int>(nodes.size()); ++n) {
    const std::vector<int> under = triangles_under(m.bvh, n);
    for (const Eigen::VectorXd& q : inside(m.model, m.certificates.node_radius(n), samples, rng)) {
      INFO("node " << n << " radius " << m.certificates.node_radius(n));
      REQUIRE(intersecting_pairs(m.model, under, under, true, q) == 0);
      ++checked;
    }
    for (int a = nodes[n].first_child; a < nodes[n].first_child + nodes[n].child_count; ++a) {
      for (int b = a + 1; b < nodes[n].first_child + nodes[n].child_count; ++b) {
        for (const Eigen::VectorXd& q : inside(m.model, m.certificates.sibling_radius(a, b), samples, rng)) {
          INFO("siblings " << a << ", " << b << " radius " << m.certificates.sibling_radius(a, b));
          REQUIRE(intersecting_pairs(m.model, triangles_under(m.bvh, a), triangles_under(m.bvh, b), false, q) == 0);
          ++checked;
        }
      }
    }
  }
  // The pair certificates below the sibling pairs, likewise.
  int pairs = 0;
  for (const sscc::test::PairRegion& region : sscc::test::pair_regions(m.bvh, m.certificates)) {
    for (const Eigen::VectorXd& q : inside(m.model, region.radius, samples / 2 + 1, rng)) {
      INFO("pair " << region.x << ", " << region.y << " radius " << region.radius);
      REQUIRE(intersecting_pairs(m.model, triangles_under(m.bvh, region.x), triangles_under(m.bvh, region.y), false,
                                 q) == 0);
      ++pairs;
    }
  }
  REQUIRE(checked > 100);
  REQUIRE(pairs > 100);
}

}  // namespace

TEST_CASE("certificates: configurations inside every node and sibling certificate are free of contact",
          "[certificates]") {
  SECTION("two sheets, 3 modes (random directions cover the sphere of directions densely)") {
    check_certificates_by_sampling(*sscc::test::certified_sheets(Eigen::Vector3d(1, 1, 1)), 24, 1);
  }
  SECTION("two sheets, weighted modes") {
    check_certificates_by_sampling(*sscc::test::certified_sheets(Eigen::Vector3d(4, 0.5, 2)), 24, 2);
  }
  SECTION("sphere, 27 polynomial modes") { check_certificates_by_sampling(*sscc::test::certified_sphere(), 8, 3); }
  SECTION("two spheres touching at rest, those pairs excluded") {
    const auto m = sscc::test::certified_touching_spheres();
    REQUIRE_FALSE(m->model.excluded_pairs().empty());
    REQUIRE(m->certificates.node_radius(0) > 0.0);
    check_certificates_by_sampling(*m, 6, 4);
  }
}

TEST_CASE("certificates: never above a known contact, in the weighted norm", "[certificates]") {
  for (double w : {1.0, 4.0, 0.25}) {
    const auto m = sscc::test::certified_sheets(Eigen::Vector3d(w, 1, 1));
    // Mode 0 at q_0 = 1 lowers the top sheet onto the bottom one: ||q||_M = sqrt(w).
    const Eigen::VectorXd touching = Eigen::Vector3d(1, 0, 0);
    const sscc::SelfCcd ccd(m->bvh, m->certificates);
    sscc::SelfCcdOptions traditional;
    sscc::set_traditional(traditional);
    REQUIRE(ccd.query_discrete(touching, traditional).collided());
    INFO("weight " << w << " root radius " << m->certificates.node_radius(0));
    REQUIRE(m->certificates.node_radius(0) <= std::sqrt(w));
    REQUIRE(m->certificates.node_radius(0) >= 0.3 * std::sqrt(w));  // not vacuous
  }
}

TEST_CASE("certificates: steps with both ends inside the root certificate have no contact", "[certificates]") {
  const auto sheets = sscc::test::certified_sheets(Eigen::Vector3d(1, 1, 1));
  const auto sphere = sscc::test::certified_sphere();
  std::mt19937_64 rng(9);
  for (const CertifiedModel* m : {sheets.get(), sphere.get()}) {
    const sscc::SelfCcd ccd(m->bvh, m->certificates);
    const double radius = m->certificates.node_radius(0);
    const std::vector<Eigen::VectorXd> ends = inside(m->model, radius, 24, rng);
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
      INFO("step " << i);
      REQUIRE_FALSE(ccd.query_exhaustive(ends[i], ends[i + 1]).collided());
      const sscc::SelfCcdReport certified = ccd.query(ends[i], ends[i + 1]);
      REQUIRE(certified.stats.root_certified);
      REQUIRE_FALSE(certified.collided());
    }
  }
}

TEST_CASE("certificates: the culled query reports exactly what the traditional one does", "[certificates]") {
  const auto m = sscc::test::certified_sphere();
  const sscc::SelfCcd ccd(m->bvh, m->certificates);
  sscc::SelfCcdOptions traditional;
  sscc::set_traditional(traditional);
  std::mt19937_64 rng(17);
  const double radius = m->certificates.node_radius(0);
  int certified = 0, partly = 0, colliding = 0;
  long pair_certified = 0;
  for (double norm : {0.5 * radius, 0.9 * radius, 1.5 * radius, 3.0 * radius, 0.4, 0.8, 1.2}) {
    for (int step = 0; step < 4; ++step) {
      const Eigen::VectorXd q0 = sscc::test::random_scaled_coordinates(rng, 27, norm);
      const Eigen::VectorXd q1 = sscc::test::random_scaled_coordinates(rng, 27, norm);
      for (sscc::NodeBounds bounds :
           {sscc::NodeBounds::kHybrid, sscc::NodeBounds::kRefit, sscc::NodeBounds::kSubspace}) {
        sscc::SelfCcdOptions with = {};
        with.bounds = bounds;
        sscc::SelfCcdOptions without = traditional;
        without.bounds = bounds;
        const sscc::SelfCcdReport a = ccd.query(q0, q1, with);
        const sscc::SelfCcdReport b = ccd.query(q0, q1, without);
        INFO("norm " << norm << " step " << step);
        REQUIRE(a.pairs == b.pairs);
        REQUIRE(a.features == b.features);
        REQUIRE(ccd.query_discrete(q1, with).pairs == ccd.query_discrete(q1, without).pairs);
        certified += a.stats.root_certified;
        partly += !a.stats.root_certified && a.stats.certified > 0;
        colliding += a.collided();
        pair_certified += a.stats.pair_certified;
        REQUIRE(b.stats.certified == 0);
      }
    }
  }
  REQUIRE(certified > 0);
  REQUIRE(partly > 0);
  REQUIRE(colliding > 0);
  REQUIRE(pair_certified > 0);  // the pair certificates below the sibling pairs took part
}

TEST_CASE("certificates: pair certificates are walked on steps taken lazily, not on those that compute every vertex",
          "[certificates]") {
  const auto m = sscc::test::certified_sphere();
  const sscc::SelfCcd ccd(m->bvh, m->certificates);
  sscc::SelfCcdOptions options;
  options.threads = 2;  // a step computing every vertex runs on both threads, a lazy one on one
  std::mt19937_64 rng(23);
  const double radius = m->certificates.node_radius(0);
  double largest_pair_radius = 0.0;
  for (const sscc::PairCertificate& pair : m->certificates.pair_certificates())
    largest_pair_radius = std::max(largest_pair_radius, pair.radius);
  int lazy = 0, every_vertex = 0, every_vertex_below_a_pair_radius = 0;
  long lazy_pair_certified = 0;
  for (double norm : {1.2 * radius, 1.5 * radius, 2.5 * radius, 4.0 * radius, 0.8, 1.2, 3.0}) {
    for (int step = 0; step < 4; ++step) {
      const Eigen::VectorXd q0 = sscc::test::random_scaled_coordinates(rng, 27, norm);
      const Eigen::VectorXd q1 = sscc::test::random_scaled_coordinates(rng, 27, norm);
      if (ccd.root_certifies(q0, q1, options)) continue;
      const sscc::SelfCcdReport report = ccd.query(q0, q1, options);
      INFO("norm " << norm << " step " << step);
      REQUIRE(report.pairs == ccd.query_exhaustive(q0, q1).pairs);
      if (ccd.query_threads(q0, q1, options) > 1) {
        ++every_vertex;
        const double s = std::max(m->model.scaled_coordinates(q0).norm(), m->model.scaled_coordinates(q1).norm());
        every_vertex_below_a_pair_radius += s < largest_pair_radius;
        REQUIRE(report.stats.pair_certified == 0);
      } else {
        ++lazy;
        lazy_pair_certified += report.stats.pair_certified;
      }
    }
  }
  REQUIRE(every_vertex > 0);
  REQUIRE(every_vertex_below_a_pair_radius > 0);  // where walking them could have certified a pair
  REQUIRE(lazy > 0);
  REQUIRE(lazy_pair_certified > 0);
}

TEST_CASE("certificates: sibling radii are looked up by either order, and only for siblings", "[certificates]") {
  const auto m = sscc::test::certified_sphere();
  const sscc::Certificates& c = m->certificates;
  const auto& nodes = m->bvh.nodes();
  REQUIRE(c.node_count() == static_cast<int>(nodes.size()));
  REQUIRE(c.node_radius(0) > 0.0);
  int positive = 0;
  for (int n = 0; n < c.node_count(); ++n) {
    for (int a = nodes[n].first_child; a < nodes[n].first_child + nodes[n].child_count; ++a) {
      for (int b = nodes[n].first_child; b < nodes[n].first_child + nodes[n].child_count; ++b) {
        if (a == b) continue;
        REQUIRE(c.sibling_radius(a, b) == c.sibling_radius(b, a));
        positive += c.sibling_radius(a, b) > 0.0;
        // A child and its parent's sibling are not siblings: no certificate.
        if (n > 0) REQUIRE(c.sibling_radius(a, n == 1 ? 2 : 1) == 0.0);
      }
    }
  }
  REQUIRE(positive > 0);
  REQUIRE(c.sibling_radius(0, 1) == 0.0);  // the root has no sibling
}

TEST_CASE("certificates: the same radii on one thread as on every thread", "[certificates]") {
  // Large enough for pair trees whose descents run as tasks (precomputed on every core).
  sscc::TriangleMesh mesh = sscc::test::uv_sphere(12, 24);
  const Eigen::MatrixXd basis = sscc::polynomial_basis(mesh, 27);
  const auto m = std::make_unique<sscc::test::CertifiedModel>(std::move(mesh), basis, Eigen::VectorXd::Ones(27));
  sscc::set_default_threads(1);
  const sscc::Certificates serial = sscc::Certificates::precompute(m->bvh);
  sscc::set_default_threads(0);
  REQUIRE(serial.stats().threads == 1);
  // Pair trees whose descents ran as tasks: in line on one thread, in any order on several.
  REQUIRE(serial.stats().pair_tree_tasks > 0);
  REQUIRE(m->certificates.stats().pair_tree_tasks == serial.stats().pair_tree_tasks);
  const auto& nodes = m->bvh.nodes();
  for (int n = 0; n < serial.node_count(); ++n) {
    REQUIRE(serial.node_radius(n) == m->certificates.node_radius(n));
    for (int a = nodes[n].first_child; a < nodes[n].first_child + nodes[n].child_count; ++a) {
      for (int b = a + 1; b < nodes[n].first_child + nodes[n].child_count; ++b) {
        REQUIRE(serial.sibling_radius(a, b) == m->certificates.sibling_radius(a, b));
        REQUIRE(serial.sibling_pair_certificate(a, b) == m->certificates.sibling_pair_certificate(a, b));
      }
    }
  }
  const std::vector<sscc::PairCertificate>& one = serial.pair_certificates();
  const std::vector<sscc::PairCertificate>& every = m->certificates.pair_certificates();
  REQUIRE(one.size() == every.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    REQUIRE(one[i].radius == every[i].radius);
    REQUIRE(one[i].first_child == every[i].first_child);
  }
}

TEST_CASE("certificates: bad parameters and misuse are refused with a message", "[certificates]") {
  const auto m = sscc::test::certified_sheets(Eigen::Vector3d(1, 1, 1));
  for (double epsilon : {0.0, 1.0, -0.1, std::nan("")}) {
    sscc::CertificateParameters p;
    p.epsilon = epsilon;
    REQUIRE_THROWS_WITH(sscc::Certificates::precompute(m->bvh, p), Catch::Contains("epsilon"));
  }
  sscc::CertificateParameters p;
  p.global_radius_scale = 0.0;
  REQUIRE_THROWS_WITH(sscc::Certificates::precompute(m->bvh, p), Catch::Contains("global radius"));

  const auto other = sscc::test::certified_sheets(Eigen::Vector3d(2, 1, 1));
  REQUIRE_THROWS_WITH(sscc::SelfCcd(m->bvh, other->certificates), Catch::Contains("another mesh"));

  const sscc::SelfCcd ccd(m->bvh, m->certificates);
  sscc::SelfCcdOptions separation;
  separation.kernel.minimum_separation = 1e-3;
  const Eigen::VectorXd q = Eigen::Vector3d(0.1, 0, 0);
  REQUIRE_THROWS_WITH(ccd.query(q, q, separation), Catch::Contains("minimum separation"));
  separation.use_certificates = false;
  REQUIRE_NOTHROW(ccd.query(q, q, separation));
}

TEST_CASE("certificates: a basis of entries far from 1 is refused, and within the range the radii scale", "[cert]") {
  // Times 2^-565 (entries near 1e-170) the Gram matrices of the mode blocks underflow and every
  // radius came out infinite; times 2^520 they overflow; from 2^-300 down the precomputation
  // overflows (the test runner traps it). Within the range the root's radius,
  // scaled back, is scale 1's (to the hierarchies' differences: their clusterings weigh the
  // modes against the positions).
  using namespace sscc;
  const TriangleMesh mesh = test::uv_sphere(8, 16);
  const Eigen::MatrixXd basis = polynomial_basis(mesh, 27);
  const auto model_times = [&](int exponent) {
    return SubspaceModel(mesh, std::ldexp(1.0, exponent) * basis, Eigen::VectorXd::Ones(27));
  };
  const SubspaceModel original = model_times(0);
  const SubspaceBvh original_bvh(original);
  const Certificates original_certificates = Certificates::precompute(original_bvh);
  const double root = original_certificates.node_radius(0);
  REQUIRE(root > 0.0);
  REQUIRE(std::isfinite(root));
  for (const int exponent : {-565, -260, 260, 520}) {
    INFO("modes times 2^" << exponent);
    const SubspaceModel model = model_times(exponent);
    const SubspaceBvh bvh(model);
    CHECK(basis_scale_problem(model).find("scaled basis") != std::string::npos);
    CHECK_THROWS_AS(Certificates::precompute(bvh), std::invalid_argument);
    // Certificates met with such a model are refused for its scale (checked before the key).
    CHECK_THROWS_WITH(SelfCcd(bvh, original_certificates), Catch::Contains("scaled basis"));
  }
  for (const int exponent : {-190, -100, 100, 190}) {
    INFO("modes times 2^" << exponent);
    const SubspaceModel model = model_times(exponent);
    const SubspaceBvh bvh(model);
    CHECK(basis_scale_problem(model).empty());
    const double scaled_back = std::ldexp(Certificates::precompute(bvh).node_radius(0), exponent);
    CHECK(std::abs(scaled_back - root) <= 1e-3 * root);
  }
}
