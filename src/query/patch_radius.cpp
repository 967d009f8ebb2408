#include "query/patch_radius.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "query/normal_cone.hpp"
#include "query/patch_cull.hpp"
#include "query/simple_contour.hpp"

namespace sscc::detail {

namespace {

using Eigen::Vector3d;

constexpr double kUp = 1.0 + kRadiusMargin;
constexpr double kDown = 1.0 - kRadiusMargin;

/// The rest shape, the scaled modes and the rounding bound eta(s) = eta0 + eta1 s of the
/// positions a query computes (patch_radius.hpp), with the radii of both hypotheses.
class RadiusBounds {
 public:
  explicit RadiusBounds(const SubspaceBvh& bvh)
      : bvh_(bvh), mesh_(bvh.model().mesh()), rest_(mesh_.vertices()), r_(bvh.model().mode_count()) {
    double largest_coordinate = 0.0, largest_block = 0.0;
    for (int v = 0; v < mesh_.vertex_count(); ++v) {
      largest_coordinate = std::max(largest_coordinate, rest_[v].cwiseAbs().maxCoeff());
      largest_block = std::max(largest_block, block(v).stableNorm());
    }
    // Per coordinate, position() rounds an r-term dot product and one addition: within
    // (r + 2) u of |p| + ||U_hat_v|| ||q_hat||; sqrt(3) for the vector; doubled for room.
    const double per_unit = 2.0 * (r_ + 2) * kUnitRoundoff * kUp;
    eta0_ = per_unit * std::sqrt(3.0) * largest_coordinate;
    eta1_ = per_unit * largest_block;
    edge_norms_.resize(mesh_.edges().size());
    for (std::size_t e = 0; e < mesh_.edges().size(); ++e) {
      edge_norms_[e] = difference_norm(mesh_.edges()[e][0], mesh_.edges()[e][1]);
    }
  }

  /// Triangle t's area-weighted normal at rest (e1 x e2).
  Vector3d rest_normal(int t) const {
    const Triangle& f = mesh_.triangles()[t];
    return (rest_[f[1]] - rest_[f[0]]).cross(rest_[f[2]] - rest_[f[0]]);
  }

  /// The positive root of hypothesis (i) for triangle t and direction d (0 when it fails at
  /// rest; infinity when the modes do not move the triangle's edges).
  double triangle_radius(const Vector3d& d, int t) const {
    const Triangle& f = mesh_.triangles()[t];
    const Vector3d e1 = rest_[f[1]] - rest_[f[0]];
    const Vector3d e2 = rest_[f[2]] - rest_[f[0]];
    const double l1 = e1.norm() * kUp, l2 = e2.norm() * kUp;
    // Edges (v0 v1) and (v2 v0) of the triangle: E1 and E2 (up to sign); E3 = E2 - E1 along
    // (v1 v2). (E1 q) x (E2 q) = (E1 q) x (E3 q) = (E2 q) x (E3 q): the two smallest bound it.
    const double m1 = edge_norms_[mesh_.triangle_edges(t)[0]];
    const double m2 = edge_norms_[mesh_.triangle_edges(t)[2]];
    const double m3 = edge_norms_[mesh_.triangle_edges(t)[1]];
    const double l0_sum = l1 + l2, m_sum = m1 + m2;
    // The linear term's component along d, q_hat . (E2^T (d x e1) + E1^T (e2 x d)): at most
    // |g| s, computed with a margin for its rounding.
    const Vector3d w2 = d.cross(e1), w1 = e2.cross(d);
    const Eigen::VectorXd g =
        (block(f[2]) - block(f[0])).transpose() * w2 + (block(f[1]) - block(f[0])).transpose() * w1;
    const double g_norm =
        g.stableNorm() * kUp + kRadiusMargin * (w2.norm() * m2 + w1.norm() * m1) + kUnderflowAllowance;
    const double constant = (2.0 * eta0_ * l0_sum + 4.0 * eta0_ * eta0_) * kUp;
    const double linear = (g_norm + 2.0 * eta0_ * m_sum + 2.0 * eta1_ * l0_sum + 8.0 * eta0_ * eta1_) * kUp;
    const double smallest_product = std::min({m1 * m2, m1 * m3, m2 * m3});
    const double quadratic = (smallest_product + 2.0 * eta1_ * m_sum + 4.0 * eta1_ * eta1_) * kUp;
    const double slack = d.dot(e1.cross(e2)) - kRadiusMargin * l1 * l2 - constant;
    if (!(slack > 0.0)) return 0.0;
    const double denominator = linear + std::sqrt(linear * linear + 4.0 * quadratic * slack);
    return denominator > 0.0 ? kDown * 2.0 * slack / denominator : std::numeric_limits<double>::infinity();
  }

  /// The radius of hypothesis (ii) for a boundary cycle seen along d (0 when its projection
  /// is not certainly simple at rest).
  double contour_radius(const Vector3d& d, const std::vector<DirectedEdge>& chain) const {
    if (!stays_simple_in_projection(d, chain, rest_, rest_)) return 0.0;
    const auto project = [&](int v) -> Vector3d { return rest_[v] - rest_[v].dot(d) * d; };
    std::vector<Vector3d> projected(chain.size());
    for (std::size_t i = 0; i < chain.size(); ++i) projected[i] = project(chain[i][0]);
    // Each vertex's parting rate from the chain's mean block C bounds a pair's by the
    // triangle inequality: the exact rate is needed only where that bound would lower the
    // radius.
    Eigen::Matrix<double, 3, Eigen::Dynamic> mean = Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, r_);
    for (const DirectedEdge& e : chain) mean += block(e[0]);
    mean /= static_cast<double>(chain.size());
    const auto distance_from_mean = [&](int v) {
      const Eigen::Matrix<double, 3, Eigen::Dynamic> difference = block(v) - mean;
      return difference.stableNorm() * kUp;  // bounds the projected rate too
    };
    std::vector<double> start_from_mean(chain.size()), end_from_mean(chain.size());
    for (std::size_t i = 0; i < chain.size(); ++i) {
      start_from_mean[i] = distance_from_mean(chain[i][0]);
      end_from_mean[i] = distance_from_mean(chain[i][1]);
    }
    double radius = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < chain.size(); ++i) {
      const int a = chain[i][0], b = chain[i][1];
      const Vector3d& pa = projected[i];
      const Vector3d pb = project(b);
      for (std::size_t j = 0; j < chain.size(); ++j) {
        const int p = chain[j][0];
        if (p == a || p == b) continue;
        const Vector3d& pp = projected[j];
        const double magnitude =
            rest_[p].cwiseAbs().maxCoeff() + rest_[a].cwiseAbs().maxCoeff() + rest_[b].cwiseAbs().maxCoeff();
        const double gap = point_segment_distance(pp, pa, pb) - kRadiusMargin * magnitude - 2.0 * eta0_ * kUp;
        if (!(gap > 0.0)) return 0.0;
        const double bound = (start_from_mean[j] + std::max(start_from_mean[i], end_from_mean[i]) + 2.0 * eta1_) * kUp +
                             kUnderflowAllowance;
        if (kDown * gap >= radius * bound) continue;
        const double rate =
            (std::max(projected_difference_norm(d, p, a), projected_difference_norm(d, p, b)) + 2.0 * eta1_) * kUp;
        radius = std::min(radius, kDown * gap / rate);
      }
    }
    return radius;
  }

 private:
  /// Vertex v's scaled mode block (3 x r).
  Eigen::Map<const Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>> block(int v) const {
    return {bvh_.model().scaled_basis().data() + 3 * static_cast<std::ptrdiff_t>(v) * r_, 3, r_};
  }
  /// ||U_hat_a - U_hat_b||_F, rounded up.
  double difference_norm(int a, int b) const { return (block(a) - block(b)).stableNorm() * kUp; }
  /// ||(I - d d^T)(U_hat_a - U_hat_b)||_F for the unit d, rounded up: how fast the two
  /// vertices part in projection along d.
  double projected_difference_norm(const Vector3d& d, int a, int b) const {
    const Eigen::Matrix<double, 3, Eigen::Dynamic> difference = block(a) - block(b);
    const Eigen::Matrix<double, 3, Eigen::Dynamic> across = difference - d * (d.transpose() * difference);
    return across.stableNorm() * kUp + kRadiusMargin * difference.stableNorm() + kUnderflowAllowance;
  }

  static double point_segment_distance(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
    const Vector3d ab = b - a;
    const double length2 = ab.squaredNorm();
    const double l = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    return (p - (a + l * ab)).norm();
  }

  const SubspaceBvh& bvh_;
  const TriangleMesh& mesh_;
  const std::vector<Vector3d>& rest_;
  int r_;
  double eta0_ = 0.0, eta1_ = 0.0;
  std::vector<double> edge_norms_;
};

/// The radius of a set of triangles with boundary `chain` (a simple cycle) and normal sum
/// `normal_sum`: the smaller of its triangles' and its contour's along the mean normal.
template <typename Triangles>
double set_radius(const RadiusBounds& bounds, const Vector3d& normal_sum, const std::vector<DirectedEdge>& chain,
                  Triangles for_each_triangle) {
  const double length = normal_sum.norm();
  if (!(length > 0.0) || !std::isfinite(length)) return 0.0;
  const Vector3d d = normal_sum / length;
  double radius = std::numeric_limits<double>::infinity();
  for_each_triangle([&](int t) {
    if (radius > 0.0) radius = std::min(radius, bounds.triangle_radius(d, t));
  });
  if (!(radius > 0.0)) return 0.0;
  return std::min(radius, bounds.contour_radius(d, chain));
}

}  // namespace

PatchRadii::PatchRadii(const SubspaceBvh& bvh, const NodeBoundaries& boundaries)
    : node_radius_(bvh.nodes().size(), 0.0), patch_(bvh.nodes().size(), -1) {
  const RadiusBounds bounds(bvh);
  const std::vector<SubspaceBvh::Node>& nodes = bvh.nodes();
  const std::vector<int>& order = bvh.triangle_order();
  const int node_count = static_cast<int>(nodes.size());
  // Normal sums bottom-up: children follow their parent in the node array.
  std::vector<Vector3d> normal_sums(nodes.size(), Vector3d::Zero());
  for (int n = node_count - 1; n >= 0; --n) {
    const SubspaceBvh::Node& node = nodes[n];
    if (node.is_leaf()) {
      for (int i = node.triangle_begin; i < node.triangle_end; ++i) normal_sums[n] += bounds.rest_normal(order[i]);
    } else {
      for (int c = node.first_child; c < node.first_child + node.child_count; ++c) normal_sums[n] += normal_sums[c];
    }
  }
  const auto node_triangles = [&](int n) {
    return [&, n](auto visit) {
      for (int i = nodes[n].triangle_begin; i < nodes[n].triangle_end; ++i) visit(order[i]);
    };
  };
  for (int n = 0; n < node_count; ++n) {
    const SubspaceBvh::Node& node = nodes[n];
    if (node.triangle_end - node.triangle_begin >= kSmallestConeNode && boundaries.simple_cycle(n)) {
      node_radius_[n] = set_radius(bounds, normal_sums[n], boundaries.chain(n), node_triangles(n));
    }
    const int parent = boundaries.parent(n);
    patch_[n] = parent >= 0 && patch_[parent] >= 0 ? patch_[parent] : node_radius_[n] > 0.0 ? n : -1;
    patch_count_ += patch_[n] == n;
  }

  // Pairs of adjacent patches: across every edge whose triangles lie in two of them.
  std::vector<int> patch_of_triangle(bvh.model().mesh().triangle_count(), -1);
  for (int n = 0; n < node_count; ++n) {
    if (nodes[n].is_leaf()) {
      for (int i = nodes[n].triangle_begin; i < nodes[n].triangle_end; ++i) patch_of_triangle[order[i]] = patch_[n];
    }
  }
  const TriangleMesh& mesh = bvh.model().mesh();
  std::vector<DirectedEdge> union_chain;
  for (int e = 0; e < static_cast<int>(mesh.edges().size()); ++e) {
    for (const int* t = mesh.triangles_of_edge_begin(e); t != mesh.triangles_of_edge_end(e); ++t) {
      for (const int* u = t + 1; u != mesh.triangles_of_edge_end(e); ++u) {
        int a = patch_of_triangle[*t], b = patch_of_triangle[*u];
        if (a < 0 || b < 0 || a == b) continue;
        if (a > b) std::swap(a, b);
        const std::uint64_t key = (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
        if (pair_radius_.count(key)) continue;
        double radius = 0.0;
        if (union_is_simple_cycle(boundaries.chain(a), boundaries.chain(b), union_chain)) {
          radius = set_radius(bounds, normal_sums[a] + normal_sums[b], union_chain, [&](auto visit) {
            node_triangles(a)(visit);
            node_triangles(b)(visit);
          });
        }
        pair_radius_.emplace(key, radius);
      }
    }
  }
  // Only pairs with a radius are kept.
  largest_pair_radius_ = node_radius_;
  for (auto it = pair_radius_.begin(); it != pair_radius_.end();) {
    for (const int patch : {static_cast<int>(it->first >> 32), static_cast<int>(it->first & 0xffffffffu)}) {
      largest_pair_radius_[patch] = std::max(largest_pair_radius_[patch], it->second);
    }
    it = it->second > 0.0 ? std::next(it) : pair_radius_.erase(it);
  }
  for (double radius : largest_pair_radius_) largest_radius_ = std::max(largest_radius_, radius);
}

double PatchRadii::pair_radius(int a, int b) const {
  int patch_a = patch_[a], patch_b = patch_[b];
  if (patch_a < 0 || patch_b < 0) return 0.0;
  if (patch_a == patch_b) return node_radius_[patch_a];
  if (patch_a > patch_b) std::swap(patch_a, patch_b);
  const auto found =
      pair_radius_.find((static_cast<std::uint64_t>(patch_a) << 32) | static_cast<std::uint32_t>(patch_b));
  return found == pair_radius_.end() ? 0.0 : found->second;
}

}  // namespace sscc::detail
