// Properties of the precomputation's bounds that soundness alone would not show:
//  - the triangle-pair bound is never weaker than the paper's perturbation bound (eq. 10,
//    with |dU| the largest spectral norm of a vertex's deviation from its triangle's mean
//    modes), computed here on its own from the constant-mode distance;
//  - the box-box bound is the smallest norm at which the subspace boxes meet: below it they
//    are apart in every direction tried, including the one that closes a gap fastest, and
//    just above it they meet along that direction when only one axis separates them.
#include <catch2/catch.hpp>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <random>

#include "certificates/box_box_bound.hpp"
#include "sscc/ccd/kernels.hpp"
#include "sscc/certificates/triangle_pair_bound.hpp"
#include "sscc/geometry/triangle_distance.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "support/test_meshes.hpp"

namespace {

using Block = Eigen::Matrix<double, 3, Eigen::Dynamic>;

Block mean_modes(const sscc::ModalTriangle& t) { return (t.modes[0] + t.modes[1] + t.modes[2]) / 3.0; }

/// The paper's perturbation bound: R_c / (1 + (|dU_a| + |dU_b|) / sigma_min(A)), R_c the
/// distance of the triangles mapped by (A A^T)^(-1/2), A = mean_b - mean_a. The triangle
/// distance is sscc::closest_points_disjoint_triangles (tested on its own against sampling).
double perturbation_bound(const sscc::ModalTriangle& a, const sscc::ModalTriangle& b) {
  const Block ua = mean_modes(a), ub = mean_modes(b);
  const Block difference = ub - ua;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(difference);
  const double sigma_min = svd.singularValues()[2];
  if (!(sigma_min > 0.0)) return 0.0;
  double deviation = 0.0;
  for (const auto& [t, mean] : {std::make_pair(&a, &ua), std::make_pair(&b, &ub)}) {
    double largest = 0.0;
    for (int i = 0; i < 3; ++i) {
      largest = std::max(largest, Eigen::JacobiSVD<Eigen::MatrixXd>(t->modes[i] - *mean).singularValues()[0]);
    }
    deviation += largest;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> gram(difference * difference.transpose());
  const Eigen::Matrix3d map = gram.operatorInverseSqrt();
  std::array<Eigen::Vector3d, 3> mapped_a, mapped_b;
  for (int i = 0; i < 3; ++i) {
    mapped_a[i] = map * a.rest[i];
    mapped_b[i] = map * b.rest[i];
  }
  const double constant_mode_radius = sscc::closest_points_disjoint_triangles(mapped_a, mapped_b).distance;
  return constant_mode_radius / (1.0 + deviation / sigma_min);
}

double root_bound(const sscc::ModalTriangle& a, const sscc::ModalTriangle& b) {
  sscc::TrianglePairRadiusOptions unrefined;
  unrefined.max_depth = 0;
  return sscc::triangle_pair_radius(a, b, unrefined).lower;
}

}  // namespace

TEST_CASE("triangle-pair radius: never weaker than the perturbation bound", "[certificates][bounds]") {
  std::mt19937_64 rng(43);
  std::normal_distribution<double> normal;
  constexpr int kR = 5;
  int compared = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    // Modes shared by each triangle's vertices up to a deviation of varying size.
    const double spread = std::ldexp(1.0, -(trial % 8));
    sscc::ModalTriangle t[2];
    for (int s = 0; s < 2; ++s) {
      const Block common = Block::NullaryExpr(3, kR, [&] { return normal(rng); });
      const Eigen::Vector3d offset = s == 0 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(0, 0, 2.5);
      for (int i = 0; i < 3; ++i) {
        t[s].rest[i] = offset + Eigen::Vector3d(normal(rng), normal(rng), 0.3 * normal(rng));
        t[s].modes[i] = common + spread * Block::NullaryExpr(3, kR, [&] { return normal(rng); });
      }
    }
    if (sscc::ccd::triangles_intersect(t[0].rest[0], t[0].rest[1], t[0].rest[2], t[1].rest[0], t[1].rest[1],
                                       t[1].rest[2])) {
      continue;
    }
    const double paper = perturbation_bound(t[0], t[1]);
    INFO("trial " << trial << " perturbation bound " << paper);
    REQUIRE(root_bound(t[0], t[1]) >= paper * (1.0 - 1e-9));
    compared += paper > 0.0;
  }
  CHECK(compared > 1000);
}

TEST_CASE("triangle-pair radius: the constant-mode multiplier alone beats the perturbation bound",
          "[certificates][bounds]") {
  // Triangle b comes down on a static triangle a. Its lowest vertex cannot move vertically
  // (modes diag(1, 1, 0)), the others can (diag(1, 1, 3)): at the constant-mode closest
  // points the true modes cannot close the gap, so only the constant-mode multiplier gives
  // a bound. Mean modes A = diag(1, 1, 2): R_c = 1/2, sigma_min = 1, |dU_b| = 2, so the
  // perturbation bound is 1/6; the contact radius is 1/2 (the upper vertices, 1.5 above a,
  // come down at rate 3).
  sscc::ModalTriangle a, b;
  a.rest = {Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(2, -1, 0), Eigen::Vector3d(-1, 2, 0)};
  b.rest = {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 1.5), Eigen::Vector3d(0, 1, 1.5)};
  for (int i = 0; i < 3; ++i) {
    a.modes[i] = Block::Zero(3, 3);
    b.modes[i] = Eigen::Vector3d(1.0, 1.0, i == 0 ? 0.0 : 3.0).asDiagonal().toDenseMatrix();
  }
  const double paper = perturbation_bound(a, b);
  CHECK(paper == Approx(1.0 / 6.0).epsilon(1e-12));
  const double bound = root_bound(a, b);
  CHECK(bound >= paper);
  CHECK(bound <= 0.5);
  CHECK(sscc::triangle_pair_radius(a, b).lower <= 0.5);
}

TEST_CASE("box-box bound: the boxes stay apart below it and meet just above it", "[certificates][bounds]") {
  const sscc::TriangleMesh mesh = sscc::test::uv_sphere(8, 16);
  const sscc::SubspaceModel model(mesh, sscc::polynomial_basis(mesh, 27), Eigen::VectorXd::Ones(27));
  const sscc::SubspaceBvh bvh(model);
  std::mt19937_64 rng(47);
  std::normal_distribution<double> normal;
  const auto boxes_meet = [&](int a, int b, const Eigen::VectorXd& q_hat) {
    const double norm = q_hat.norm();
    return bvh.box(a, q_hat, norm).overlaps(bvh.box(b, q_hat, norm));
  };
  const int nodes = static_cast<int>(bvh.nodes().size());
  int pairs = 0, tight = 0;
  for (int a = 1; a < nodes; ++a) {
    for (int b = a + 1; b < nodes; ++b) {
      const double radius = sscc::detail::box_box_radius(bvh, a, b);
      if (!(radius > 0.0) || !std::isfinite(radius)) continue;
      ++pairs;
      INFO("nodes " << a << ", " << b << " radius " << radius);
      const sscc::SubspaceBvh::SubspaceBound x = bvh.subspace_bound(a), y = bvh.subspace_bound(b);
      // Per separated axis, the direction that closes its gap fastest.
      int separated = 0;
      double only_radius = 0.0;
      Eigen::VectorXd only_closing;
      for (int k = 0; k < 3; ++k) {
        const double gap = std::fabs(x.centre[k] - y.centre[k]) - x.half[k] - y.half[k];
        if (!(gap > 0.0)) continue;
        ++separated;
        const Eigen::VectorXd row = (x.mean_modes.row(k) - y.mean_modes.row(k)).transpose();
        const Eigen::VectorXd closing = (x.centre[k] > y.centre[k] ? -1.0 : 1.0) * row.normalized();
        REQUIRE_FALSE(boxes_meet(a, b, 0.999 * radius * closing));
        only_radius = gap / (row.norm() + x.rate[k] + y.rate[k]);
        only_closing = closing;
      }
      // One axis apart: its own radius is the bound, and the boxes meet just past it.
      if (separated == 1) tight += boxes_meet(a, b, 1.001 * only_radius * only_closing);
      for (int sample = 0; sample < 4; ++sample) {
        Eigen::VectorXd q_hat(27);
        for (int j = 0; j < 27; ++j) q_hat[j] = normal(rng);
        REQUIRE_FALSE(boxes_meet(a, b, 0.999 * radius * q_hat.normalized()));
      }
    }
  }
  CHECK(pairs > 1000);
  CHECK(tight > 100);  // the bound is not vacuous: many pairs meet 0.1 % above it
}
