// A 4-ary bounding volume hierarchy over a subspace model's triangles whose node bounds
// hold in every configuration q, computed in O(r) per node (BD-tree style).
//
// Built by recursive k-means (k = 4) on each triangle's rest centroid together with its
// mode displacements (SSCC paper, section 3): triangles that are close and move alike share
// a node. Each cluster is then made edge-connected wherever its parent is (parts joined only
// at a vertex, or not at all, move to the neighbouring cluster they share most edges with):
// the normal-cone cull proves only connected patches free of self-contact
// (src/query/patch_cull.hpp). Children partition their parent's triangles; leaves hold at
// most kMaxLeafTriangles.
//
// Bound of node n for scaled coordinates q_hat: with c0 the centre of the rest box of the
// node's vertices, C the mean of their 3 x r scaled mode blocks, h0 the rest half extents
// and d_k = max over the vertices of ||(U_hat_v - C)_k||_2,
//   |x_vk(q_hat) - (c0 + C q_hat)_k| <= h0_k + d_k ||q_hat||   (Cauchy-Schwarz),
// so the box centre(q_hat) +- (h0 + d ||q_hat||) contains the node in configuration q_hat.
// Over a straight-line step the centre moves linearly and ||q_hat(t)|| <= max of the end
// norms (convexity), so the box spanned by the end centres, grown by h0 + d max(||q_hat0||,
// ||q_hat1||), contains the node for the whole step. Boxes are widened by a rounding margin
// so that they also contain the vertex positions as computed in floating point.
#pragma once

#include <Eigen/Core>

#include <random>
#include <string>
#include <vector>

#include "sscc/geometry/aabb.hpp"
#include "sscc/model/subspace_model.hpp"

namespace sscc {

inline constexpr int kBranchingFactor = 4;
inline constexpr int kMaxLeafTriangles = 4;

struct BvhBuildStats {
  int nodes = 0;
  int leaves = 0;
  int depth = 0;
  int largest_leaf = 0;
  double seconds = 0.0;
};

class SubspaceBvh {
 public:
  struct Node {
    int first_child = -1;  ///< -1 for a leaf; children are consecutive
    int child_count = 0;
    int triangle_begin = 0;  ///< range in triangle_order()
    int triangle_end = 0;
    bool is_leaf() const { return first_child < 0; }
  };

  /// Builds the hierarchy; `seed` makes the k-means seeding reproducible. The hierarchy
  /// holds the model (a handle sharing its data), so a temporary model is fine.
  explicit SubspaceBvh(const SubspaceModel& model, std::uint64_t seed = 1);

  const SubspaceModel& model() const { return model_; }
  const std::vector<Node>& nodes() const { return nodes_; }
  /// Triangle indices, grouped so that each node's triangles are contiguous.
  const std::vector<int>& triangle_order() const { return order_; }
  const BvhBuildStats& build_stats() const { return stats_; }
  /// Each node's depth (the root's is 0).
  std::vector<int> node_depths() const;

  /// Node n's bound: in every configuration q_hat its vertices lie in the box
  /// centre + mean_modes q_hat +- (half + rate ||q_hat||).
  struct SubspaceBound {
    Eigen::Vector3d centre, half, rate;
    Eigen::Map<const Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>> mean_modes;
  };
  SubspaceBound subspace_bound(int n) const;

  /// Box of node n for scaled coordinates q_hat, whose norm is given (O(r)).
  Aabb box(int n, const Eigen::VectorXd& q_hat, double q_hat_norm) const;
  /// Box of node n over the straight-line step q_hat0 -> q_hat1; s = max of their norms.
  Aabb swept_box(int n, const Eigen::VectorXd& q_hat0, const Eigen::VectorXd& q_hat1, double s) const;

  /// Checks the structure (children partition their parent, every triangle in exactly one
  /// leaf, leaf sizes) and that every node's box contains its vertices at `samples` random
  /// configurations of scaled norm up to `max_norm`. Returns "" when valid, else the first
  /// problem.
  std::string validate(int samples, double max_norm, std::uint64_t seed) const;

 private:
  void build(int node, std::vector<int>& triangles, std::mt19937_64& rng, int depth);
  void compute_bounds(int node);
  /// Moves every edge-connected part of a cluster other than its largest to the neighbouring
  /// cluster it shares most edges with (a few passes; parts with no neighbour stay).
  void make_clusters_connected(const std::vector<int>& triangles, std::vector<int>& cluster);

  SubspaceModel model_;
  std::vector<Node> nodes_;
  std::vector<int> order_;
  // Per node: rest centre c0, rest half extents h0, deviation rates d (3 each) and the
  // mean mode block C (3 x r, row-major).
  std::vector<Eigen::Vector3d> centre_, half_, rate_;
  std::vector<double> mean_modes_;
  std::vector<double> feature_;  // per triangle: centroid and mode block, 3 + 3r values
  std::vector<int> local_;       // build scratch: a triangle's index in the node being split, or -1
  BvhBuildStats stats_;
};

}  // namespace sscc
