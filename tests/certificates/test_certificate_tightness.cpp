// Certificates sampled where they matter: along the direction in which the triangles under
// a node (or a sibling pair) most nearly touch, at 0.95 to 0.999 of its radius. The
// direction comes from contact configurations found here on their own: for every
// non-adjacent pair of triangles, the least-norm q_hat that makes a point of one coincide
// with a point of the other, over a barycentric grid of points. With accurate certificates
// (epsilon 0.01) these contacts lie within a few percent of the radii, so radii inflated by
// 10 % fail: they exceed a contact found, and the samples along its direction intersect.
#include <catch2/catch.hpp>

#include <Eigen/Cholesky>

#include <random>

#include "certificate_fixtures.hpp"
#include "sscc/ccd/kernels.hpp"
#include "sscc/certificates/certificates.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "support/test_meshes.hpp"

namespace {

/// Barycentric points with denominator `grid`.
std::vector<Eigen::Vector3d> barycentric_grid(int grid) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i <= grid; ++i) {
    for (int j = 0; i + j <= grid; ++j)
      points.emplace_back(double(i) / grid, double(j) / grid, double(grid - i - j) / grid);
  }
  return points;
}

/// The least-norm q_hat over the grid's point pairs of triangles a and b: a point of a
/// coincides with a point of b there (the positions are linear in q_hat).
Eigen::VectorXd nearest_contact(const sscc::SubspaceModel& model, int a, int b,
                                const std::vector<Eigen::Vector3d>& grid) {
  const sscc::Triangle& ta = model.mesh().triangles()[a];
  const sscc::Triangle& tb = model.mesh().triangles()[b];
  const int r = model.mode_count();
  Eigen::VectorXd best;
  double best_norm = INFINITY;
  for (const Eigen::Vector3d& wa : grid) {
    Eigen::Vector3d xa = Eigen::Vector3d::Zero();
    Eigen::MatrixXd ua = Eigen::MatrixXd::Zero(3, r);
    for (int i = 0; i < 3; ++i) {
      xa += wa[i] * model.mesh().vertices()[ta[i]];
      ua += wa[i] * model.scaled_basis().middleRows<3>(3 * ta[i]);
    }
    for (const Eigen::Vector3d& wb : grid) {
      Eigen::Vector3d gap = xa;
      Eigen::MatrixXd modes = -ua;
      for (int i = 0; i < 3; ++i) {
        gap -= wb[i] * model.mesh().vertices()[tb[i]];
        modes += wb[i] * model.scaled_basis().middleRows<3>(3 * tb[i]);
      }
      // modes q_hat = gap (x_a + U_a q = x_b + U_b q), least norm: q_hat = modes^T (modes modes^T)^-1 gap.
      const Eigen::LDLT<Eigen::Matrix3d> gram(modes * modes.transpose());
      if (gram.info() != Eigen::Success || !(gram.vectorD().minCoeff() > 1e-12 * gram.vectorD().maxCoeff())) continue;
      const Eigen::VectorXd q_hat = modes.transpose() * gram.solve(gap);
      const double norm = q_hat.norm();
      if (norm < best_norm) best_norm = norm, best = q_hat;
    }
  }
  return best;
}

/// Non-adjacent pairs, one triangle from each of the position ranges (the same range: its pairs), that intersect at
/// q_hat.
int intersecting_pairs(const sscc::SubspaceBvh& bvh, const sscc::SubspaceBvh::Node& first,
                       const sscc::SubspaceBvh::Node& second, bool same, const Eigen::VectorXd& q_hat) {
  const sscc::SubspaceModel& model = bvh.model();
  const sscc::TriangleMesh& mesh = model.mesh();
  int found = 0;
  for (int i = first.triangle_begin; i < first.triangle_end; ++i) {
    for (int j = same ? i + 1 : second.triangle_begin; j < second.triangle_end; ++j) {
      const int a = bvh.triangle_order()[i], b = bvh.triangle_order()[j];
      if (mesh.adjacent(a, b)) continue;
      const sscc::Triangle& ta = mesh.triangles()[a];
      const sscc::Triangle& tb = mesh.triangles()[b];
      std::array<Eigen::Vector3d, 6> x;
      for (int k = 0; k < 3; ++k) {
        x[k] = model.position(ta[k], q_hat);
        x[3 + k] = model.position(tb[k], q_hat);
      }
      found += sscc::ccd::triangles_intersect(x[0], x[1], x[2], x[3], x[4], x[5]);
    }
  }
  return found;
}

struct Region {
  int a, b;  // a == b: node a's own pairs; else the sibling pair
  double radius;
};

}  // namespace

TEST_CASE("certificates: sampled at 0.95 to 0.999 of each radius where the triangles most nearly touch",
          "[certificates][tightness]") {
  const sscc::TriangleMesh mesh = sscc::test::uv_sphere(6, 10);
  const sscc::SubspaceModel model(mesh, sscc::polynomial_basis(mesh, 27), Eigen::VectorXd::Ones(27));
  const sscc::SubspaceBvh bvh(model);
  sscc::CertificateParameters accurate;
  accurate.epsilon = 0.01;
  const sscc::Certificates certificates = sscc::Certificates::precompute(bvh, accurate);
  const auto& nodes = bvh.nodes();
  std::vector<Region> regions;
  for (int n = 0; n < static_cast<int>(nodes.size()); ++n) {
    regions.push_back({n, n, certificates.node_radius(n)});
    for (int a = nodes[n].first_child; a < nodes[n].first_child + nodes[n].child_count; ++a) {
      for (int b = a + 1; b < nodes[n].first_child + nodes[n].child_count; ++b) {
        regions.push_back({a, b, certificates.sibling_radius(a, b)});
      }
    }
  }
  // And the pair certificates below them (resolved to kPairEpsilon only: not counted as tight).
  const std::size_t certificate_regions = regions.size();
  for (const sscc::test::PairRegion& pair : sscc::test::pair_regions(bvh, certificates)) {
    regions.push_back({pair.x, pair.y, pair.radius});
  }
  REQUIRE(regions.size() > certificate_regions + 100);
  // The nearest contact of every non-adjacent pair, by positions in the hierarchy's order.
  const std::vector<Eigen::Vector3d> grid = barycentric_grid(4);
  const int n_triangles = mesh.triangle_count();
  std::vector<Eigen::VectorXd> contact(static_cast<std::size_t>(n_triangles) * n_triangles);
  for (int i = 0; i < n_triangles; ++i) {
    for (int j = i + 1; j < n_triangles; ++j) {
      const int a = bvh.triangle_order()[i], b = bvh.triangle_order()[j];
      if (!mesh.adjacent(a, b)) contact[i * n_triangles + j] = nearest_contact(model, a, b, grid);
    }
  }
  int sampled = 0, tight = 0, pairs_tight = 0, pairs_sampled = 0;
  for (const Region& region : regions) {
    const sscc::SubspaceBvh::Node& first = nodes[region.a];
    const sscc::SubspaceBvh::Node& second = nodes[region.b];
    const bool same = region.a == region.b;
    Eigen::VectorXd nearest;
    for (int i = first.triangle_begin; i < first.triangle_end; ++i) {
      for (int j = same ? i + 1 : second.triangle_begin; j < second.triangle_end; ++j) {
        const Eigen::VectorXd& q = contact[std::min(i, j) * n_triangles + std::max(i, j)];
        if (q.size() > 0 && (nearest.size() == 0 || q.norm() < nearest.norm())) nearest = q;
      }
    }
    if (nearest.size() == 0) continue;  // no non-adjacent pair, or none that can touch
    const double contact_norm = nearest.norm();
    INFO("region " << region.a << ", " << region.b << ": radius " << region.radius << ", contact found at "
                   << contact_norm);
    // A contact configuration bounds the radius from above.
    REQUIRE(region.radius <= contact_norm * (1.0 + 1e-9));
    const Eigen::VectorXd direction = nearest / contact_norm;
    for (double fraction : {0.95, 0.97, 0.99, 0.995, 0.999}) {
      REQUIRE(intersecting_pairs(bvh, first, second, same, fraction * region.radius * direction) == 0);
      ++sampled;
    }
    const bool node_or_sibling = static_cast<std::size_t>(&region - regions.data()) < certificate_regions;
    tight += node_or_sibling && region.radius >= 0.95 * contact_norm;
    pairs_tight += !node_or_sibling && region.radius >= (1.0 - sscc::kPairEpsilon) * contact_norm;
    pairs_sampled += !node_or_sibling;
  }
  CHECK(sampled > 200);
  // Not vacuous: most radii lie within 5 % of a contact found (10 % inflation exceeds it), most
  // pair certificates within 30 % (an inflation by 1.5 exceeds it).
  CHECK(tight * 2 > static_cast<int>(certificate_regions));
  CHECK(pairs_tight * 2 > pairs_sampled);
}
