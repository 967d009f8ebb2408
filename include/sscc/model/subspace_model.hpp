// A reduced deformable object: x = p + U q for rest positions p (the mesh's vertices), a
// basis U (3V x r; row 3v + k is vertex v's coordinate k) and reduced coordinates q, with a
// diagonal weight M (||q||_M^2 = sum_i w_i q_i^2).
//
// The basis is kept scaled, U_hat = U M^(-1/2), with q_hat = M^(1/2) q, so that every bound
// downstream is a plain 2-norm of q_hat (SSCC paper, eq. 3). Immutable once built; safe to
// share between threads. A model is a handle: copies share the same immutable mesh and
// basis (copying is O(1)), so whatever holds a model keeps it alive.
//
// A model may carry excluded triangle pairs (excluded_pairs.hpp), on request: the pairs
// touching in the rest shape. Every hierarchy, certificate and query built on the model
// ignores them, and the certificates' key records them.
#pragma once

#include <Eigen/Core>

#include <cstddef>

#include <memory>
#include <vector>

#include "sscc/mesh/excluded_pairs.hpp"
#include "sscc/mesh/triangle_mesh.hpp"

namespace sscc {

using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

class SubspaceModel {
 public:
  /// Throws std::invalid_argument when the basis is not 3V x r (naming both sizes), r is 0,
  /// the weights are not r positive finite numbers, or any entry is not finite.
  SubspaceModel(TriangleMesh mesh, const Eigen::MatrixXd& basis, const Eigen::VectorXd& weights);

  /// A model with no modes (r = 0): the mesh alone, for detectors that are handed vertex
  /// positions each step (position_ccd.hpp) rather than reduced coordinates.
  static SubspaceModel without_basis(TriangleMesh mesh);

  /// This model (sharing its mesh and basis) with `excluded` ignored by every query and
  /// certificate built on it. Throws std::invalid_argument when the set was made for a mesh
  /// of another triangle count.
  SubspaceModel excluding(ExcludedPairs excluded) const;
  /// excluding(ExcludedPairs::touching_at_rest(mesh())): the pairs touching at rest.
  SubspaceModel excluding_rest_contacts() const;
  /// The excluded pairs (empty unless excluding() made this model).
  const ExcludedPairs& excluded_pairs() const { return *excluded_; }
  /// Whether queries consider triangles a and b: neither adjacent nor excluded.
  bool considers(int a, int b) const { return !state_->mesh.adjacent(a, b) && !excluded_->contains(a, b); }

  const TriangleMesh& mesh() const { return state_->mesh; }
  int mode_count() const { return static_cast<int>(state_->weights.size()); }
  const Eigen::VectorXd& weights() const { return state_->weights; }
  /// U M^(-1/2), 3V x r, row-major (a vertex's three rows are contiguous).
  const RowMajorMatrix& scaled_basis() const { return state_->scaled_basis; }

  /// M^(1/2) q. Throws std::invalid_argument when q has the wrong size or a NaN/infinity.
  Eigen::VectorXd scaled_coordinates(const Eigen::VectorXd& q) const;
  /// ||q||_M.
  double weighted_norm(const Eigen::VectorXd& q) const;
  /// Vertex v's position for scaled coordinates q_hat (3r flops): rest position plus each row
  /// of its block dotted with q_hat in order (the rounding every bound allows for: an r-term
  /// dot product and one addition).
  Eigen::Vector3d position(int v, const Eigen::VectorXd& q_hat) const {
    return position(state_->mesh.vertices()[v], vertex_block(v), q_hat);
  }
  /// position for a vertex at rest position `rest` whose 3 x r block (row-major) is `rows`.
  static Eigen::Vector3d position(const Eigen::Vector3d& rest, const double* rows, const Eigen::VectorXd& q_hat) {
    const int r = static_cast<int>(q_hat.size());
    const double* q = q_hat.data();
    double sum[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k < r; ++k) {
      for (int i = 0; i < 3; ++i) sum[i] += rows[i * r + k] * q[k];
    }
    return rest + Eigen::Vector3d(sum[0], sum[1], sum[2]);
  }
  /// Vertex v's 3 x r block of the scaled basis (row-major, three contiguous rows).
  const double* vertex_block(int v) const {
    return state_->scaled_basis.data() + 3 * static_cast<std::ptrdiff_t>(v) * state_->scaled_basis.cols();
  }
  /// position(v, q_hat0) and position(v, q_hat1) (the same operations in the same order) in one pass over v's rows of
  /// the basis (the queries need both ends of a step).
  void position_pair(int v, const Eigen::VectorXd& q_hat0, const Eigen::VectorXd& q_hat1, Eigen::Vector3d& x0,
                     Eigen::Vector3d& x1) const {
    position_pair(state_->mesh.vertices()[v], vertex_block(v), q_hat0, q_hat1, x0, x1);
  }
  /// position_pair for a vertex at rest position `rest` whose 3 x r block (row-major) is
  /// `rows`: the same values as position(rest, rows, q_hat0) and position(rest, rows, q_hat1),
  /// and as the model's own for its vertex's block (copies of the basis laid out for a
  /// query's order of access use it).
  static void position_pair(const Eigen::Vector3d& rest, const double* rows, const Eigen::VectorXd& q_hat0,
                            const Eigen::VectorXd& q_hat1, Eigen::Vector3d& x0, Eigen::Vector3d& x1) {
    const int r = static_cast<int>(q_hat0.size());
    const double* q0 = q_hat0.data();
    const double* q1 = q_hat1.data();
    double sum0[3] = {0.0, 0.0, 0.0}, sum1[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k < r; ++k) {
      for (int i = 0; i < 3; ++i) {
        sum0[i] += rows[i * r + k] * q0[k];
        sum1[i] += rows[i * r + k] * q1[k];
      }
    }
    x0 = rest + Eigen::Vector3d(sum0[0], sum0[1], sum0[2]);
    x1 = rest + Eigen::Vector3d(sum1[0], sum1[1], sum1[2]);
  }
  /// All positions for coordinates q (not scaled).
  std::vector<Eigen::Vector3d> deformed_positions(const Eigen::VectorXd& q) const;

 private:
  struct State {
    TriangleMesh mesh;
    Eigen::VectorXd weights;
    RowMajorMatrix scaled_basis;
  };
  SubspaceModel() = default;

  std::shared_ptr<const State> state_;
  std::shared_ptr<const ExcludedPairs> excluded_;
};

}  // namespace sscc
