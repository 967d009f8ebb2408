#include "sscc/model/subspace_model.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/finite.hpp"

namespace sscc {

namespace {

const std::shared_ptr<const ExcludedPairs>& no_excluded_pairs() {
  static const auto none = std::make_shared<const ExcludedPairs>();
  return none;
}

}  // namespace

SubspaceModel::SubspaceModel(TriangleMesh mesh, const Eigen::MatrixXd& basis, const Eigen::VectorXd& weights) {
  const long rows = 3L * mesh.vertex_count();
  if (basis.rows() != rows) {
    throw std::invalid_argument("SubspaceModel: the basis has " + std::to_string(basis.rows()) +
                                " rows, but the mesh's " + std::to_string(mesh.vertex_count()) + " vertices need " +
                                std::to_string(rows));
  }
  if (basis.cols() == 0) throw std::invalid_argument("SubspaceModel: the basis has no modes");
  if (weights.size() != basis.cols()) {
    throw std::invalid_argument("SubspaceModel: " + std::to_string(weights.size()) + " weights for " +
                                std::to_string(basis.cols()) + " modes");
  }
  if (!all_finite(basis)) throw std::invalid_argument("SubspaceModel: the basis has a NaN or infinity");
  for (long i = 0; i < weights.size(); ++i) {
    if (!(weights[i] > 0.0) || !std::isfinite(weights[i])) {
      throw std::invalid_argument("SubspaceModel: weight " + std::to_string(i) + " is not a positive finite number");
    }
  }
  RowMajorMatrix scaled_basis = basis * weights.cwiseSqrt().cwiseInverse().asDiagonal();
  if (!all_finite(scaled_basis)) {
    throw std::invalid_argument("SubspaceModel: basis / sqrt(weight) overflows; a weight is too small");
  }
  state_ = std::make_shared<const State>(State{std::move(mesh), weights, std::move(scaled_basis)});
  excluded_ = no_excluded_pairs();
}

SubspaceModel SubspaceModel::without_basis(TriangleMesh mesh) {
  SubspaceModel model;
  const long rows = 3L * mesh.vertex_count();
  model.state_ = std::make_shared<const State>(State{std::move(mesh), Eigen::VectorXd(), RowMajorMatrix(rows, 0)});
  model.excluded_ = no_excluded_pairs();
  return model;
}

SubspaceModel SubspaceModel::excluding(ExcludedPairs excluded) const {
  if (!excluded.empty() && excluded.triangle_count() != mesh().triangle_count()) {
    throw std::invalid_argument("SubspaceModel: excluded pairs made for " + std::to_string(excluded.triangle_count()) +
                                " triangles, the mesh has " + std::to_string(mesh().triangle_count()));
  }
  SubspaceModel model = *this;
  model.excluded_ = std::make_shared<const ExcludedPairs>(std::move(excluded));
  return model;
}

SubspaceModel SubspaceModel::excluding_rest_contacts() const {
  return excluding(ExcludedPairs::touching_at_rest(mesh()));
}

Eigen::VectorXd SubspaceModel::scaled_coordinates(const Eigen::VectorXd& q) const {
  const Eigen::VectorXd& weights = state_->weights;
  if (q.size() != weights.size()) {
    throw std::invalid_argument("SubspaceModel: q has " + std::to_string(q.size()) + " coordinates, the model has " +
                                std::to_string(weights.size()) + " modes");
  }
  for (long i = 0; i < q.size(); ++i) {
    if (!std::isfinite(q[i])) {
      throw std::invalid_argument("SubspaceModel: q[" + std::to_string(i) + "] is not finite");
    }
  }
  Eigen::VectorXd q_hat = weights.cwiseSqrt().cwiseProduct(q);
  if (!all_finite(q_hat) || !std::isfinite(q_hat.stableNorm())) {
    throw std::invalid_argument("SubspaceModel: q scaled by the weights overflows");
  }
  return q_hat;
}

double SubspaceModel::weighted_norm(const Eigen::VectorXd& q) const { return scaled_coordinates(q).stableNorm(); }

std::vector<Eigen::Vector3d> SubspaceModel::deformed_positions(const Eigen::VectorXd& q) const {
  const Eigen::VectorXd q_hat = scaled_coordinates(q);
  std::vector<Eigen::Vector3d> x(mesh().vertex_count());
  for (int v = 0; v < mesh().vertex_count(); ++v) x[v] = position(v, q_hat);
  return x;
}

}  // namespace sscc
