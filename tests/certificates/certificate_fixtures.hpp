// Models with certificates for the certificate tests.
#pragma once

#include <Eigen/Core>

#include <memory>
#include <random>

#include "query/descent.hpp"
#include "sscc/certificates/certificates.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "support/test_meshes.hpp"

namespace sscc::test {

struct CertifiedModel {
  SubspaceModel model;
  SubspaceBvh bvh;
  Certificates certificates;
  CertifiedModel(TriangleMesh mesh, const Eigen::MatrixXd& basis, const Eigen::VectorXd& weights,
                 const CertificateParameters& parameters = {})
      : model(std::move(mesh), basis, weights), bvh(model), certificates(Certificates::precompute(bvh, parameters)) {}
  explicit CertifiedModel(SubspaceModel built, const CertificateParameters& parameters = {})
      : model(std::move(built)), bvh(model), certificates(Certificates::precompute(bvh, parameters)) {}
};

/// Two sheets 0.2 apart; mode 0 lowers the top sheet by its height (contact at q_0 = 1),
/// mode 1 bends both sheets (z += x^2 - x), mode 2 shears them (x += z).
inline Eigen::MatrixXd sheet_basis(const TriangleMesh& mesh) {
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(3 * mesh.vertex_count(), 3);
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    const Eigen::Vector3d& p = mesh.vertices()[v];
    basis(3 * v + 2, 0) = -p.z();
    basis(3 * v + 2, 1) = p.x() * p.x() - p.x();
    basis(3 * v + 0, 2) = p.z();
  }
  return basis;
}

inline std::unique_ptr<CertifiedModel> certified_sheets(const Eigen::VectorXd& weights) {
  TriangleMesh mesh = parallel_sheets(6, 0.2);
  const Eigen::MatrixXd basis = sheet_basis(mesh);
  return std::make_unique<CertifiedModel>(std::move(mesh), basis, weights);
}

inline std::unique_ptr<CertifiedModel> certified_sphere() {
  TriangleMesh mesh = uv_sphere(8, 16);
  const Eigen::MatrixXd basis = polynomial_basis(mesh, 27);
  return std::make_unique<CertifiedModel>(std::move(mesh), basis, Eigen::VectorXd::Ones(27));
}

/// Two spheres cutting each other at rest, the 27 polynomial modes, the pairs touching at
/// rest excluded.
inline std::unique_ptr<CertifiedModel> certified_touching_spheres() {
  TriangleMesh mesh = two_spheres(6, 12, kTwoSpheresOffset);
  const Eigen::MatrixXd basis = polynomial_basis(mesh, 27);
  return std::make_unique<CertifiedModel>(
      SubspaceModel(std::move(mesh), basis, Eigen::VectorXd::Ones(27)).excluding_rest_contacts());
}

/// A pair certificate with the node pair it certifies.
struct PairRegion {
  int x, y;
  double radius;
  bool has_children;
};

/// Every pair certificate below every sibling pair, walked as the traversal descends (the
/// larger node of each pair split).
inline std::vector<PairRegion> pair_regions(const SubspaceBvh& bvh, const Certificates& certificates) {
  std::vector<PairRegion> regions;
  const auto walk = [&](const auto& self, int k, int x, int y) -> void {
    const PairCertificate& pair = certificates.pair_certificate(k);
    regions.push_back({x, y, pair.radius, pair.first_child >= 0});
    if (pair.first_child < 0) return;
    const SubspaceBvh::Node& nx = bvh.nodes()[x];
    const SubspaceBvh::Node& ny = bvh.nodes()[y];
    const bool split_x = detail::splits_first(nx, ny);
    const SubspaceBvh::Node& split = split_x ? nx : ny;
    for (int i = 0; i < split.child_count; ++i) {
      const int c = split.first_child + i;
      self(self, pair.first_child + i, split_x ? c : x, split_x ? y : c);
    }
  };
  for (int n = 0; n < static_cast<int>(bvh.nodes().size()); ++n) {
    const SubspaceBvh::Node& node = bvh.nodes()[n];
    for (int a = node.first_child; a < node.first_child + node.child_count; ++a) {
      for (int b = a + 1; b < node.first_child + node.child_count; ++b) {
        const int k = certificates.sibling_pair_certificate(a, b);
        if (k >= 0) walk(walk, k, a, b);
      }
    }
  }
  return regions;
}

/// A scaled configuration of norm `norm` in a random direction.
inline Eigen::VectorXd random_scaled_coordinates(std::mt19937_64& rng, int r, double norm) {
  std::normal_distribution<double> normal;
  Eigen::VectorXd q_hat(r);
  for (int j = 0; j < r; ++j) q_hat[j] = normal(rng);
  return q_hat * (norm / q_hat.norm());
}

}  // namespace sscc::test
