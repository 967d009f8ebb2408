#include "query/displacement_bound.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>

#include "common/scaled_norm.hpp"
#include "sscc/geometry/triangle_distance.hpp"

namespace sscc::detail {

namespace {

using Eigen::Vector3d;
using TrianglePoints = std::array<Vector3d, 3>;

constexpr double kRoundoff = 0x1p-53;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// An absolute allowance for the rounding of results in the subnormal range, where each
/// operation may err by up to 2^-1074 whatever the relative bounds say: far above the few dozen
/// such roundings of any bound here, and far below anything a cull compares it with.
constexpr double kUnderflowAllowance = 0x1p-1000;

/// gamma_k = k u / (1 - k u): the relative error bound of k roundings.
double gamma(int k) { return k * kRoundoff / (1.0 - k * kRoundoff); }

/// Coordinates from which the closest-point search (which squares differences) could
/// overflow: beyond it the triangles' boxes bound their distance instead.
constexpr double kLargestSquarable = 1e150;

/// The Euclidean distance between two boxes (a lower bound of the distance of what they
/// hold), scaled so that it neither overflows nor underflows (an underflow would only lower
/// it); 0 when a gap overflows.
double box_distance(const Aabb& a, const Aabb& b) {
  Vector3d gaps;
  for (int k = 0; k < 3; ++k) gaps[k] = std::max({0.0, b.lo[k] - a.hi[k], a.lo[k] - b.hi[k]});
  const double distance = gaps.stableNorm();
  return std::isfinite(distance) ? distance : 0.0;
}

Aabb box_of(const TrianglePoints& t) {
  Aabb box = Aabb::empty();
  for (const Vector3d& p : t) box.add(p);
  return box;
}

/// A lower bound of the distance between triangles a and b, 0 when they may touch. Any
/// direction n bounds it: the triangles' projections on n are at least the gap apart, so the
/// distance is at least gap / ||n||. The direction joining the closest points found makes that
/// bound the distance itself (up to rounding); a poor direction only gives a smaller bound.
/// Rounding: each dot product n . v errs by at most gamma_3 |n| . |v| (here bounded with a
/// factor above 5) plus kUnderflowAllowance, the gap's subtraction by u |gap|, and the norm
/// (scaled against underflow and overflow) by a few u. n is scaled to about unit length first,
/// so that its products neither underflow nor overflow where the coordinates do not; any n is
/// a direction, so the scaling's rounding does not matter.
double distance_lower_bound(const TrianglePoints& a, const TrianglePoints& b) {
  double largest = 0.0;
  for (const TrianglePoints* t : {&a, &b}) {
    for (const Vector3d& v : *t) largest = std::max(largest, v.cwiseAbs().maxCoeff());
  }
  if (!(largest < kLargestSquarable)) return box_distance(box_of(a), box_of(b));
  const TriangleClosestPoints closest = closest_points_disjoint_triangles(a, b);
  Vector3d on_a = Vector3d::Zero(), on_b = Vector3d::Zero();
  for (int i = 0; i < 3; ++i) {
    on_a += closest.first_weights[i] * a[i];
    on_b += closest.second_weights[i] * b[i];
  }
  const Vector3d joining = on_b - on_a;
  const double scale = joining.stableNorm();
  if (!(scale > 0.0) || !std::isfinite(scale)) return 0.0;
  const Vector3d n = joining / scale;
  const double length = n.stableNorm();
  if (!(length > 0.0) || !std::isfinite(length)) return 0.0;
  double lowest_b = kInfinity, highest_a = -kInfinity, magnitude = 0.0;
  for (const Vector3d& v : b) {
    lowest_b = std::min(lowest_b, n.dot(v));
    magnitude = std::max(magnitude, n.cwiseAbs().dot(v.cwiseAbs()));
  }
  for (const Vector3d& v : a) {
    highest_a = std::max(highest_a, n.dot(v));
    magnitude = std::max(magnitude, n.cwiseAbs().dot(v.cwiseAbs()));
  }
  const double gap = lowest_b - highest_a;
  const double lower = gap - 16.0 * kRoundoff * (magnitude + std::abs(gap)) - kUnderflowAllowance;
  if (!(lower > 0.0)) return 0.0;
  return lower / (length * (1.0 + 16.0 * kRoundoff)) * (1.0 - 4.0 * kRoundoff);
}

/// Per triangle (mesh index), a lower bound of its rest distance to every triangle it is
/// considered with: a search of the hierarchy's rest boxes that skips a subtree once its box
/// is as far as the nearest bound found. What is skipped lies at least that far (the box
/// distance rounds by a few u: the result is lowered by kSumSlack's margin to cover it).
std::vector<double> triangle_clearances(const SubspaceBvh& bvh) {
  const SubspaceModel& model = bvh.model();
  const TriangleMesh& mesh = model.mesh();
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(model.mode_count());
  std::vector<Aabb> node_boxes(bvh.nodes().size());
  for (std::size_t n = 0; n < node_boxes.size(); ++n) node_boxes[n] = bvh.box(static_cast<int>(n), rest, 0.0);
  const auto points = [&](int t) {
    const Triangle& triangle = mesh.triangles()[t];
    return TrianglePoints{mesh.vertices()[triangle[0]], mesh.vertices()[triangle[1]], mesh.vertices()[triangle[2]]};
  };
  std::vector<Aabb> triangle_boxes(mesh.triangle_count());
  for (int t = 0; t < mesh.triangle_count(); ++t) triangle_boxes[t] = box_of(points(t));
  std::vector<double> clearance(mesh.triangle_count(), kInfinity);
#pragma omp parallel for schedule(dynamic, 64)
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const TrianglePoints own = points(t);
    double nearest = kInfinity;
    std::vector<int> stack{0};
    while (!stack.empty()) {
      const int n = stack.back();
      stack.pop_back();
      if (nearest < kInfinity && box_distance(triangle_boxes[t], node_boxes[n]) >= nearest) continue;
      const SubspaceBvh::Node& node = bvh.nodes()[n];
      if (node.is_leaf()) {
        for (int i = node.triangle_begin; i < node.triangle_end; ++i) {
          const int u = bvh.triangle_order()[i];
          if (!model.considers(t, u)) continue;
          if (nearest < kInfinity && box_distance(triangle_boxes[t], triangle_boxes[u]) >= nearest) continue;
          nearest = std::min(nearest, distance_lower_bound(own, points(u)));
        }
        continue;
      }
      // Nearest child last, so that it is searched first.
      std::array<std::pair<double, int>, kBranchingFactor> children;
      children.fill({-1.0, -1});  // sorted after every child
      for (int c = 0; c < node.child_count; ++c) {
        children[c] = {box_distance(triangle_boxes[t], node_boxes[node.first_child + c]), node.first_child + c};
      }
      std::sort(children.begin(), children.end(), std::greater<>());
      for (int c = 0; c < node.child_count; ++c) stack.push_back(children[c].second);
    }
    clearance[t] = nearest / kSumSlack;
  }
  return clearance;
}

/// Fits, per mode, the affine map of the mode's displacements over `vertices` (least squares,
/// regularised so that flat or degenerate nodes get a finite matrix: the theorem holds for any
/// matrix, only the residual bound must match the one stored), and bounds each residual.
/// Rounding: the residual is evaluated from differences of magnitude at most |U e_j| + |m| and
/// ||A|| (|p| + |c|); 16 u of those is far above the few roundings each term carries.
void fit_affine(const SubspaceModel& model, const std::vector<int>& vertices, double* maps, double* residuals) {
  const int r = model.mode_count();
  const auto& rest = model.mesh().vertices();
  Vector3d centre = Vector3d::Zero();
  double farthest = 0.0;
  for (int v : vertices) centre += rest[v];
  centre /= static_cast<double>(vertices.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (int v : vertices) {
    scatter += (rest[v] - centre) * (rest[v] - centre).transpose();
    farthest = std::max(farthest, rest[v].stableNorm());
  }
  scatter += (1e-6 * scatter.trace() + std::numeric_limits<double>::min()) * Eigen::Matrix3d::Identity();
  Eigen::Matrix3d inverse = scatter.inverse();
  if (!inverse.allFinite()) inverse.setZero();
  const auto displacement = [&](int v, int j) {
    return Vector3d(model.scaled_basis()(3 * v, j), model.scaled_basis()(3 * v + 1, j),
                    model.scaled_basis()(3 * v + 2, j));
  };
  for (int j = 0; j < r; ++j) {
    Vector3d mean = Vector3d::Zero();
    for (int v : vertices) mean += displacement(v, j);
    mean /= static_cast<double>(vertices.size());
    Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
    for (int v : vertices) moment += (displacement(v, j) - mean) * (rest[v] - centre).transpose();
    const Eigen::Matrix3d map = moment * inverse;
    double residual = 0.0, largest = 0.0;
    for (int v : vertices) {
      const Vector3d left = displacement(v, j) - mean - map * (rest[v] - centre);
      residual = std::max(residual, left.stableNorm());
      largest = std::max(largest, displacement(v, j).stableNorm());
    }
    const double magnitude = largest + mean.stableNorm() +
                             scaled_norm(9, [&](int k) { return map.data()[k]; }) * (farthest + centre.stableNorm());
    residuals[j] = residual * kSumSlack + 16.0 * kRoundoff * magnitude + kUnderflowAllowance;
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) maps[(3 * a + b) * r + j] = map(a, b);
    }
  }
}

}  // namespace

const double* DisplacementBounds::affine_maps(int n) const {
  return affine_index_[n] < 0 ? nullptr : &affine_maps_[static_cast<std::size_t>(affine_index_[n]) * 9 * modes_];
}

const double* DisplacementBounds::affine_residuals(int n) const {
  return affine_index_[n] < 0 ? nullptr : &affine_residuals_[static_cast<std::size_t>(affine_index_[n]) * modes_];
}

DisplacementBounds::DisplacementBounds(const SubspaceBvh& bvh) : modes_(bvh.model().mode_count()) {
  const SubspaceModel& model = bvh.model();
  const TriangleMesh& mesh = model.mesh();
  const int node_count = static_cast<int>(bvh.nodes().size());
  const std::vector<double> by_triangle = triangle_clearances(bvh);
  std::vector<int> counted;
  for (int n = 0; n < node_count; ++n) {
    const SubspaceBvh::Node& node = bvh.nodes()[n];
    if (node.triangle_end - node.triangle_begin >= kSmallestCountedNode) counted.push_back(n);
  }
  const std::size_t stride = counted.size() / kSampledNodes + 1;
  for (std::size_t k = 0; k < counted.size(); k += stride) sample_.push_back(counted[k]);
  clearance_.assign(node_count, kInfinity);
  spread_.assign(static_cast<std::size_t>(node_count) * modes_, 0.0);
  frobenius_spread_.assign(node_count, 0.0);
  std::vector<int> seen(mesh.vertex_count(), -1);
  affine_index_.assign(node_count, -1);
  std::vector<int> vertices;
  Eigen::VectorXd differences;
  for (int n = 0; n < node_count; ++n) {
    const SubspaceBvh::Node& node = bvh.nodes()[n];
    const auto mean = bvh.subspace_bound(n).mean_modes;
    double* spread = &spread_[static_cast<std::size_t>(n) * modes_];
    vertices.clear();
    for (int i = node.triangle_begin; i < node.triangle_end; ++i) {
      const int t = bvh.triangle_order()[i];
      clearance_[n] = std::min(clearance_[n], by_triangle[t]);
      for (int v : mesh.triangles()[t]) {
        if (seen[v] == n) continue;
        seen[v] = n;
        vertices.push_back(v);
        // Norms scaled against underflow (squares of differences below 1e-154 vanish) and
        // overflow; the differences' own rounding is relative, or absolute when subnormal.
        differences.resize(3 * modes_);
        for (int j = 0; j < modes_; ++j) {
          for (int k = 0; k < 3; ++k) differences[3 * j + k] = model.scaled_basis()(3 * v + k, j) - mean(k, j);
          spread[j] = std::max(spread[j], differences.segment<3>(3 * j).stableNorm() + kUnderflowAllowance);
        }
        frobenius_spread_[n] = std::max(frobenius_spread_[n], differences.stableNorm() + modes_ * kUnderflowAllowance);
      }
    }
    if (node.triangle_end - node.triangle_begin >= kSmallestAffineNode) {
      affine_index_[n] = static_cast<int>(affine_residuals_.size()) / std::max(modes_, 1);
      affine_maps_.resize(affine_maps_.size() + 9 * static_cast<std::size_t>(modes_));
      affine_residuals_.resize(affine_residuals_.size() + modes_);
      fit_affine(model, vertices, &affine_maps_[affine_maps_.size() - 9 * static_cast<std::size_t>(modes_)],
                 &affine_residuals_[affine_residuals_.size() - modes_]);
    }
  }
  largest_basis_entry_ = Eigen::VectorXd::Zero(modes_);
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    largest_rest_coordinate_ = std::max(largest_rest_coordinate_, mesh.vertices()[v].cwiseAbs().maxCoeff());
    for (int j = 0; j < modes_; ++j) {
      for (int k = 0; k < 3; ++k) {
        largest_basis_entry_[j] = std::max(largest_basis_entry_[j], std::abs(model.scaled_basis()(3 * v + k, j)));
      }
    }
  }
}

StepDisplacement::StepDisplacement(const DisplacementBounds& bounds, const SubspaceBvh& bvh,
                                   const Eigen::VectorXd& q_hat0, const Eigen::VectorXd& q_hat1, double separation)
    : bounds_(bounds),
      bvh_(bvh),
      q_hat0_(q_hat0),
      q_hat1_(q_hat1),
      magnitude0_(q_hat0.cwiseAbs()),
      magnitude1_(q_hat1.cwiseAbs()),
      norm_(std::max(q_hat0.stableNorm(), q_hat1.stableNorm())),
      reaches_(bvh.nodes().size()),
      centres_(bvh.nodes().size()) {
  const int r = static_cast<int>(q_hat0.size());
  const double reach_of_basis = bounds.largest_basis_entry().dot(magnitude0_.cwiseMax(magnitude1_));
  const double position_rounding =
      std::sqrt(3.0) * gamma(r + 1) * (bounds.largest_rest_coordinate() + reach_of_basis) * kSumSlack +
      kUnderflowAllowance;
  margin_ = 2.0 * position_rounding + separation;
}

double StepDisplacement::reach(int n) {
  return reaches_.get(n, [&](int m) {
    const Eigen::Map<const Eigen::VectorXd> spread(bounds_.spread(m), magnitude0_.size());
    const double by_mode = std::max(magnitude0_.dot(spread), magnitude1_.dot(spread));
    return std::min(by_mode, bounds_.frobenius_spread(m) * norm_) * kSumSlack;
  });
}

const StepDisplacement::Centres& StepDisplacement::centres(int n) {
  return centres_.get(n, [&](int m) {
    const auto mean = bvh_.subspace_bound(m).mean_modes;
    const int r = static_cast<int>(magnitude0_.size());
    const Eigen::Vector3d magnitude = mean.cwiseAbs() * magnitude0_.cwiseMax(magnitude1_);
    // Each component is an r-term sum: it rounds by at most gamma_r of its terms' magnitudes.
    return Centres{mean * q_hat0_, mean * q_hat1_,
                   gamma(r + 1) * magnitude.stableNorm() * kSumSlack + kUnderflowAllowance};
  });
}

bool StepDisplacement::node_apart(int n) {
  const double clearance = bounds_.clearance(n);
  return clearance > 0.0 && ((2.0 * reach(n) + margin_) * kSumSlack < clearance || affine_apart(n));
}

double StepDisplacement::apart_fraction() {
  const std::vector<int>& sample = bounds_.sample();
  if (sample.empty()) return 0.0;
  const auto apart = std::count_if(sample.begin(), sample.end(), [&](int n) { return node_apart(n); });
  return static_cast<double>(apart) / static_cast<double>(sample.size());
}

bool StepDisplacement::affine_apart(int n) const {
  const double* maps = bounds_.affine_maps(n);
  if (!maps) return false;
  const int r = static_cast<int>(q_hat0_.size());
  const Eigen::Map<const Eigen::Matrix<double, 9, Eigen::Dynamic, Eigen::RowMajor>> map(maps, 9, r);
  const Eigen::Map<const Eigen::VectorXd> residual(bounds_.affine_residuals(n), r);
  // ||A(q)||_F at each end, with the rounding of its r-term entries (gamma_{r+1} of their terms'
  // magnitudes) added.
  double stretch = 0.0, wander = 0.0;
  for (const auto& [q, magnitude] : {std::pair{&q_hat0_, &magnitude0_}, std::pair{&q_hat1_, &magnitude1_}}) {
    const Eigen::Matrix<double, 9, 1> entries = map * *q, terms = map.cwiseAbs() * *magnitude;
    stretch = std::max(stretch, entries.stableNorm() + gamma(r + 1) * terms.stableNorm() + kUnderflowAllowance);
#ifndef SSCC_MUTANT_AFFINE_NO_RESIDUAL
    wander = std::max(wander, magnitude->dot(residual) + kUnderflowAllowance);
#endif
  }
  stretch *= kSumSlack;
  if (!(stretch < 1.0)) return false;
  return (2.0 * wander + margin_) * kSumSlack * kSumSlack < (1.0 - stretch) * bounds_.clearance(n) / kSumSlack;
}

bool StepDisplacement::nodes_apart(int a, int b) {
  const double clearance = std::max(bounds_.clearance(a), bounds_.clearance(b));
  if (!(clearance > 0.0)) return false;
  const double reaches = reach(a) + reach(b) + margin_;
  if (!(reaches * kSumSlack < clearance)) return false;  // before the centres, which cost O(r)
  const Centres& ca = centres(a);
  const Centres& cb = centres(b);
#ifdef SSCC_MUTANT_DISPLACEMENT_NO_CENTRES
  const double apart = 0.0;
#else
  const double apart = std::max((ca.at0 - cb.at0).stableNorm(), (ca.at1 - cb.at1).stableNorm());
#endif
  return ((apart + ca.rounding + cb.rounding) * kSumSlack + reaches) * kSumSlack < clearance;
}

}  // namespace sscc::detail
