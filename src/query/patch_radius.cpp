#include "query/patch_radius.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <unordered_set>
#include <utility>

#include "common/parallel_tasks.hpp"
#include "common/scaled_norm.hpp"
#include "common/sorted_fraction.hpp"
#include "query/cone_axis.hpp"
#include "query/normal_cone.hpp"
#include "query/patch_cull.hpp"
#include "query/simple_contour.hpp"
#include "sscc/query/self_ccd.hpp"

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
      : bvh_(bvh),
        mesh_(bvh.model().mesh()),
        rest_(mesh_.vertices()),
        r_(bvh.model().mode_count()),
        modes_(bvh.model().scaled_basis().data()) {
    double largest_coordinate = 0.0, largest_block = 0.0;
    for (int v = 0; v < mesh_.vertex_count(); ++v) {
      largest_coordinate = std::max(largest_coordinate, rest_[v].cwiseAbs().maxCoeff());
      largest_block = std::max(largest_block, block(v).stableNorm());
    }
    if (largest_block > 0.0 && std::isfinite(largest_block) &&
        std::abs(std::ilogb(largest_block)) > kModeExponentRange) {
      scale_modes(std::ilogb(largest_block));
      if (mode_exponent_ != 0) largest_block = std::ldexp(largest_block, -mode_exponent_);
    }
    // Per coordinate, position() rounds an r-term dot product and one addition: within
    // (r + 2) u of |p| + ||U_hat_v|| ||q_hat||; sqrt(3) for the vector; doubled for room.
    const double per_unit = 2.0 * (r_ + 2) * kUnitRoundoff * kUp;
    eta0_ = per_unit * std::sqrt(3.0) * largest_coordinate;
    eta1_ = per_unit * largest_block;
    edge_norms_.resize(mesh_.edges().size());
    edge_grams_.resize(mesh_.edges().size());
    for (std::size_t e = 0; e < mesh_.edges().size(); ++e) {
      const auto rates = block(mesh_.edges()[e][0]) - block(mesh_.edges()[e][1]);
      edge_norms_[e] = rates.stableNorm() * kUp;
      // Only where projected_rate uses it: outside that range its entries could overflow.
      edge_grams_[e] =
          squares_in_range(edge_norms_[e]) ? Eigen::Matrix3d(rates * rates.transpose()) : Eigen::Matrix3d::Zero();
    }
    cross_grams_.resize(mesh_.triangle_count());
    for (int t = 0; t < mesh_.triangle_count(); ++t) {
      const Triangle& f = mesh_.triangles()[t];
      const auto e1 = block(f[1]) - block(f[0]);
      const auto e2 = block(f[2]) - block(f[0]);
      cross_grams_[t] = exact_quadratic_applies(t) ? Eigen::Matrix3d(e1 * e2.transpose()) : Eigen::Matrix3d::Zero();
    }
  }

  const Triangle& triangle(int t) const { return mesh_.triangles()[t]; }
  /// Triangle t's area-weighted normal at rest (e1 x e2).
  Vector3d rest_normal(int t) const {
    const Triangle& f = mesh_.triangles()[t];
    return (rest_[f[1]] - rest_[f[0]]).cross(rest_[f[2]] - rest_[f[0]]);
  }

  /// The positive root of hypothesis (i) for triangle t and direction d (0 when it fails at
  /// rest; infinity when the modes do not move the triangle's edges).
  /// The exact quadratic term (largest_quadratic) is formed only where the product bound's
  /// root falls below `below`: elsewhere it cannot lower the set's radius.
  double triangle_radius(const Vector3d& d, int t, double below) const {
    return radius_of_norm(scaled_triangle_radius(d, t, below));
  }
  /// The smaller of `cap` and the radius of hypothesis (ii) for a boundary cycle seen along d
  /// (0 when its projection is not certainly simple at rest): the vertex-edge pairs that
  /// cannot fall below the cap are not bounded (the cap applies to unscaled modes only).
  double contour_radius(const Vector3d& d, const std::vector<DirectedEdge>& chain, const std::vector<int>& small_fans,
                        double cap) const {
    const double scaled_cap = mode_exponent_ == 0 ? cap : std::numeric_limits<double>::infinity();
    return std::min(cap, radius_of_norm(scaled_contour_radius(d, chain, small_fans, scaled_cap)));
  }

 private:
  /// Modes' block norms outside 2^-this..2^this are scaled (the constructor): their squares
  /// and products stay well inside the double range. Lower: more models scaled (each
  /// costs a copy of the basis); higher: products that leave the range.
  static constexpr int kModeExponentRange = 200;

  /// Far from 1, the rates' products (the quadratic term, the discriminant) overflow or
  /// underflow: the radii are bounded for the modes times 2^-k instead, and a bound R' on the
  /// norm of the coordinates times 2^k is the bound R' 2^-k on s (radius_of_norm): the
  /// positions, and every quantity of the bounds, are the same products and sums of powers of
  /// two. Only when every entry scales exactly (none becomes subnormal); else unscaled.
  void scale_modes(int exponent) {
    const RowMajorMatrix& basis = bvh_.model().scaled_basis();
    scaled_modes_.resize(static_cast<std::size_t>(basis.size()));
    for (Eigen::Index i = 0; i < basis.size(); ++i) {
      const double entry = basis.data()[i];
      scaled_modes_[i] = std::ldexp(entry, -exponent);
      if (entry != 0.0 && !(std::abs(scaled_modes_[i]) >= std::numeric_limits<double>::min())) {
        scaled_modes_.clear();
        return;
      }
    }
    modes_ = scaled_modes_.data();
    mode_exponent_ = exponent;
  }

  /// A radius for the scaled modes as a bound on s: exact in the normal range; 0 below it
  /// (ldexp could round a subnormal up); infinity above it, where R' 2^-k exceeds every
  /// finite s.
  double radius_of_norm(double scaled_radius) const {
    // Below the normal range a radius errs absolutely, by more than kDown covers once scaled up.
    if (!(scaled_radius >= std::numeric_limits<double>::min())) return 0.0;
    if (std::isinf(scaled_radius) ||
        std::ilogb(scaled_radius) - mode_exponent_ >= std::numeric_limits<double>::max_exponent) {
      return std::numeric_limits<double>::infinity();  // without the overflow ldexp would raise
    }
    const double radius = std::ldexp(scaled_radius, -mode_exponent_);
    return radius >= std::numeric_limits<double>::min() ? radius : 0.0;
  }

  double scaled_triangle_radius(const Vector3d& d, int t, double below) const {
    const Triangle& f = mesh_.triangles()[t];
    const Vector3d e1 = rest_[f[1]] - rest_[f[0]];
    const Vector3d e2 = rest_[f[2]] - rest_[f[0]];
    const double l1 = e1.norm() * kUp, l2 = e2.norm() * kUp;
    // Edges (v0 v1) and (v2 v0) of the triangle: E1 and E2 (up to sign); E3 = E2 - E1 along
    // (v1 v2). (E1 q) x (E2 q) = (E1 q) x (E3 q) = (E2 q) x (E3 q): the two smallest bound it.
    const int edge1 = mesh_.triangle_edges(t)[0], edge2 = mesh_.triangle_edges(t)[2],
              edge3 = mesh_.triangle_edges(t)[1];
    const double m1 = edge_norms_[edge1], m2 = edge_norms_[edge2];
    const double l0_sum = l1 + l2, m_sum = m1 + m2;
    // The linear term's component along d, q_hat . (E2^T (d x e1) + E1^T (e2 x d)): at most
    // |g| s, computed with a margin for its rounding.
    const Vector3d w2 = d.cross(e1), w1 = e2.cross(d);
    const double *rows0 = row_data(f[0]), *rows1 = row_data(f[1]), *rows2 = row_data(f[2]);
    const double g_norm = scaled_norm(r_,
                                      [&](int k) {
                                        double g = 0.0;
                                        for (int i = 0; i < 3; ++i) {
                                          g += (rows2[i * r_ + k] - rows0[i * r_ + k]) * w2[i] +
                                               (rows1[i * r_ + k] - rows0[i * r_ + k]) * w1[i];
                                        }
                                        return g;
                                      }) *
                              kUp +
                          kRadiusMargin * (w2.norm() * m2 + w1.norm() * m1) + kUnderflowAllowance;
    const double constant = (2.0 * eta0_ * l0_sum + 4.0 * eta0_ * eta0_) * kUp;
    const double linear = (g_norm + 2.0 * eta0_ * m_sum + 2.0 * eta1_ * l0_sum + 8.0 * eta0_ * eta1_) * kUp;
    const Vector3d u = d.unitOrthogonal(), v = d.cross(u);
    const double p1 = projected_rate(edge1, u, v), p2 = projected_rate(edge2, u, v), p3 = projected_rate(edge3, u, v);
    // The smallest of the three products is the two smallest rates' (none overflows needlessly).
    const double smallest_product = std::min({p1, p2, p3}) * median_of_three(p1, p2, p3);
    const double slack = d.dot(e1.cross(e2)) - kRadiusMargin * l1 * l2 - constant;
    if (!(slack > 0.0)) return 0.0;
    const auto root = [&](double quadratic_rate) {
      const double quadratic = (quadratic_rate + 2.0 * eta1_ * m_sum + 4.0 * eta1_ * eta1_) * kUp +
                               kUnderflowAllowance;  // products of rates near 1e-160 underflow
      // hypot: linear^2 and 4 quadratic slack can underflow (coordinates near 1e-76 with modes
      // near 2^-200), and the root without them would be up to twice the true one.
      const double denominator = linear + std::hypot(linear, 2.0 * std::sqrt(quadratic) * std::sqrt(slack));
      return denominator > 0.0 ? kDown * 2.0 * slack / denominator : std::numeric_limits<double>::infinity();
    };
    const double product_root = root(smallest_product);
    if (!(radius_of_norm(product_root) < below) || !exact_quadratic_applies(t)) return product_root;
    const double exact = largest_quadratic(t, u, v);
    return exact < smallest_product ? root(exact) : product_root;  // NaN: the product's
  }

  double scaled_contour_radius(const Vector3d& d, const std::vector<DirectedEdge>& chain,
                               const std::vector<int>& small_fans, double cap) const {
    if (!stays_simple_in_projection(d, chain, rest_, rest_)) return 0.0;
    const int k = static_cast<int>(chain.size());
    // The vertex after each edge's end along the cycle, and whether a vertex's fan is small.
    std::vector<std::pair<int, int>> edge_from(k);
    for (int i = 0; i < k; ++i) edge_from[i] = {chain[i][0], i};
    std::sort(edge_from.begin(), edge_from.end());
    std::vector<int> after(k);
    for (int i = 0; i < k; ++i) {
      const auto next = std::lower_bound(edge_from.begin(), edge_from.end(), std::make_pair(chain[i][1], -1));
      after[i] = chain[next->second][1];
    }
    const auto small_fan = [&](int v) { return std::binary_search(small_fans.begin(), small_fans.end(), v); };
    // Each vertex's parting rate from the chain's mean block C bounds a pair's by the
    // triangle inequality: the exact rate is needed only where that bound would lower the
    // radius.
    // Row-major as the basis's blocks: Eigen 3.4.0's stableNorm of a column-major 3 x Dynamic
    // matrix fails an assertion of its own (Block.h) in builds without NDEBUG.
    using ModeBlock = Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>;
    ModeBlock mean = ModeBlock::Zero(3, r_);
    for (const DirectedEdge& e : chain) mean += block(e[0]);
    mean /= static_cast<double>(k);
    struct End {
      Vector3d projected;
      double magnitude, from_mean;  // largest |coordinate|; ||U_hat_v - C||_F (bounds the projected rate)
    };
    const auto end_of = [&](int v) {
      const ModeBlock difference = block(v) - mean;
      return End{rest_[v] - rest_[v].dot(d) * d, rest_[v].cwiseAbs().maxCoeff(), difference.stableNorm() * kUp};
    };
    std::vector<End> starts(k), ends(k);
    double largest_rate = 0.0, largest_magnitude = 0.0;
    for (int i = 0; i < k; ++i) {
      starts[i] = end_of(chain[i][0]);
      ends[i] = end_of(chain[i][1]);
      largest_rate = std::max(largest_rate, starts[i].from_mean);
      largest_magnitude = std::max(largest_magnitude, starts[i].magnitude);
    }
    // Vertices sorted along an axis u of the projection plane: a vertex whose u-distance to an
    // edge already gives it no smaller radius (its gap at least that distance, less the
    // margins; its rate at most twice the largest from C) is not visited.
    const Vector3d u = d.unitOrthogonal();
    std::vector<std::pair<double, int>> along_u(k);
    for (int j = 0; j < k; ++j) along_u[j] = {starts[j].projected.dot(u), j};
    std::sort(along_u.begin(), along_u.end());
    const double pair_rate_bound = (2.0 * largest_rate + 2.0 * eta1_) * kUp + kUnderflowAllowance;
    const double margins = 4.0 * kRadiusMargin * largest_magnitude + 2.0 * eta0_ * kUp;
    double radius = cap;
    for (int i = 0; i < k; ++i) {
      const int a = chain[i][0], b = chain[i][1];
      const double reach = radius * pair_rate_bound + margins;
      const double u_start = starts[i].projected.dot(u), u_end = ends[i].projected.dot(u);
      const double lo = std::min(u_start, u_end), hi = std::max(u_start, u_end);
      auto j_it = std::lower_bound(along_u.begin(), along_u.end(), std::make_pair(lo - reach, -1));
      for (; j_it != along_u.end() && j_it->first <= hi + reach; ++j_it) {
        const int j = j_it->second, p = chain[j][0];
        if (p == a || p == b) continue;
        // p next to the edge along the cycle, at a vertex of at most two triangles: implied by
        // hypothesis (i) (patch_radius.hpp, the small fans).
        if ((chain[j][1] == a && small_fan(a)) || (p == after[i] && small_fan(b))) continue;
        const double magnitude = starts[j].magnitude + starts[i].magnitude + ends[i].magnitude;
        const double gap = point_segment_distance(starts[j].projected, starts[i].projected, ends[i].projected) -
                           kRadiusMargin * magnitude - 2.0 * eta0_ * kUp;
        if (!(gap > 0.0)) return 0.0;
        const double bound =
            (starts[j].from_mean + std::max(starts[i].from_mean, ends[i].from_mean) + 2.0 * eta1_) * kUp +
            kUnderflowAllowance;
        if (kDown * gap >= radius * bound) continue;
        // ||U_hat_p - U_hat_e||_F through C, for pair_radius's margin on nu's rounding.
        const double apart_a = (starts[j].from_mean + starts[i].from_mean) * kUp;
        const double apart_b = (starts[j].from_mean + ends[i].from_mean) * kUp;
        radius = std::min(radius,
                          pair_radius(d, {starts[j].projected, p, 0.0}, {starts[i].projected, a, apart_a},
                                      {ends[i].projected, b, apart_b}, kRadiusMargin * magnitude + 2.0 * eta0_ * kUp));
      }
    }
    return radius;
  }

  /// Vertex v's scaled mode block (3 x r), times 2^-mode_exponent_.
  const double* row_data(int v) const { return modes_ + 3 * static_cast<std::ptrdiff_t>(v) * r_; }
  Eigen::Map<const Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>> block(int v) const {
    return {row_data(v), 3, r_};
  }
  /// A boundary vertex in pair_radius: its projected rest position, its index and, for an
  /// edge's end, a bound of ||U_hat_p - U_hat_e||_F.
  struct ContourPoint {
    Vector3d projected;
    int vertex;
    double apart;
  };
  /// The root of hypothesis (ii) for vertex p and edge (a, b) (`margins` the gaps'
  /// rounding): along the unit direction nu of the projection plane from p's closest point
  /// on the edge to p, p stays beyond both ends while each end's gap along nu exceeds its
  /// parting rate along nu, ||(U_hat_p - U_hat_e)^T nu||, times s.
  double pair_radius(const Vector3d& d, const ContourPoint& p, const ContourPoint& a, const ContourPoint& b,
                     double margins) const {
    const Vector3d ab = b.projected - a.projected;
    const double length2 = ab.squaredNorm();
    const double l = length2 > 0.0 ? std::clamp((p.projected - a.projected).dot(ab) / length2, 0.0, 1.0) : 0.0;
    Vector3d nu = p.projected - (a.projected + l * ab);
    nu -= nu.dot(d) * d;  // in the plane to rounding, whatever the coordinates' magnitude
    const double length = nu.norm();
    if (!(length > 0.0)) return 0.0;
    nu /= length;
    double radius = std::numeric_limits<double>::infinity();
    for (const ContourPoint* e : {&a, &b}) {
      const double gap = nu.dot(p.projected - e->projected) - margins;
      if (!(gap > 0.0)) return 0.0;
      radius = std::min(radius, kDown * gap / ((directional_rate(nu, p.vertex, *e) + 2.0 * eta1_) * kUp));
    }
    return radius;
  }

  /// ||(U_hat_p - U_hat_e)^T nu|| for the unit nu (nearly orthogonal to d), rounded up, plus
  /// kRadiusMargin ||U_hat_p - U_hat_e||_F (bounded by e.apart) for nu's rounding: how fast
  /// the two vertices part along nu.
  double directional_rate(const Vector3d& nu, int p, const ContourPoint& e) const {
    const double* rows_p = row_data(p);
    const double* rows_e = row_data(e.vertex);
    const auto along = [&](int k) {
      return nu[0] * (rows_p[k] - rows_e[k]) + nu[1] * (rows_p[r_ + k] - rows_e[r_ + k]) +
             nu[2] * (rows_p[2 * r_ + k] - rows_e[2 * r_ + k]);
    };
    return scaled_norm(r_, along) * kUp + kRadiusMargin * e.apart + kUnderflowAllowance;
  }

  /// ||P E||_2 for edge e's rates E (3 x r) and P the projection on the plane spanned by the
  /// orthonormal u and v (orthogonal to d): the largest |P E q| over unit q, the square root of
  /// the largest eigenvalue of the plane's 2 x 2 block of E E^T, rounded up. Each computed entry
  /// of E E^T errs by at most (r + 2) u ||E||_F^2, the eigenvalue's formula by a few u
  /// ||E||_F^2 more: kRadiusMargin ||E||_F^2 covers both many times over. At most ||E||_F,
  /// which is what rates whose squares leave the range (squares_in_range) get, and what a NaN
  /// would give way to.
  double projected_rate(int e, const Vector3d& u, const Vector3d& v) const {
    const double frobenius = edge_norms_[e];
    if (!squares_in_range(frobenius)) return frobenius;
    const Eigen::Matrix3d& gram = edge_grams_[e];
    const Vector3d gram_u = gram * u, gram_v = gram * v;
    const double uu = u.dot(gram_u), vv = v.dot(gram_v), uv = u.dot(gram_v);
    const double largest = 0.5 * (uu + vv) + std::hypot(0.5 * (uu - vv), uv);
    const double bound = std::sqrt(std::max(largest, 0.0) + kRadiusMargin * frobenius * frobenius) * kUp;
    return bound < frobenius ? bound : frobenius;
  }
  /// Whether the rates of triangle t's first two edges have squares in range, so that their
  /// Gram matrices and cross_grams_ hold their products (largest_quadratic applies).
  bool exact_quadratic_applies(int t) const {
    return squares_in_range(edge_norms_[mesh_.triangle_edges(t)[0]]) &&
           squares_in_range(edge_norms_[mesh_.triangle_edges(t)[2]]);
  }
  /// The largest |d . ((E1 q) x (E2 q))| over unit q (u, v an orthonormal basis of the plane
  /// across d, u x v = d), plus a margin for its rounding: hypothesis (i)'s quadratic term
  /// exactly (patch_radius.hpp). With the r-vectors a1 = E1^T u, a2 = E1^T v, b1 = E2^T u,
  /// b2 = E2^T v, the form is (a1 . q)(b2 . q) - (a2 . q)(b1 . q) = q^T W C W^T q for W = [a1 a2
  /// b1 b2] and C holding +1/2 at (0, 3) and (3, 0), -1/2 at (1, 2) and (2, 1); its nonzero
  /// eigenvalues are those of G^(1/2) C G^(1/2), G = W^T W the 4 x 4 Gram matrix, formed from
  /// the edges' Gram matrices and the triangle's E1 E2^T. A computed G within delta of the
  /// exact one (r + 2 roundings of each product: delta about (r + 2) u (||E1||_F^2 +
  /// ||E2||_F^2)) moves its square root by at most sqrt(delta) (the square root is only
  /// half-Hoelder continuous) and the eigenvalues by about ||G||^(1/2) sqrt(delta), that is
  /// sqrt((r + 2) u) (||E1||_F^2 + ||E2||_F^2): the margin is kQuadraticMarginFactor times
  /// that (measured in review: at most 2.8e-9 of ||E1||_F^2 + ||E2||_F^2 short of a long-double
  /// r x r solve over 200k random and adversarial cases, against a margin near 6e-7 for
  /// r = 27). An eigensolver that does not converge leaves the product bound (infinity here).
  double largest_quadratic(int t, const Vector3d& u, const Vector3d& v) const {
    const int edge1 = mesh_.triangle_edges(t)[0], edge2 = mesh_.triangle_edges(t)[2];
    const Eigen::Matrix3d &g1 = edge_grams_[edge1], &g2 = edge_grams_[edge2], &cross = cross_grams_[t];
    const Vector3d axes[2] = {u, v};
    Eigen::Matrix4d gram;
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        gram(i, j) = axes[i].dot(g1 * axes[j]);
        gram(2 + i, 2 + j) = axes[i].dot(g2 * axes[j]);
        gram(i, 2 + j) = gram(2 + j, i) = axes[i].dot(cross * axes[j]);
      }
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> gram_eigen(gram);
    if (gram_eigen.info() != Eigen::Success) return std::numeric_limits<double>::infinity();
    const Eigen::Matrix4d root = gram_eigen.eigenvectors() *
                                 gram_eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal() *
                                 gram_eigen.eigenvectors().transpose();
    Eigen::Matrix4d form = Eigen::Matrix4d::Zero();
    form(0, 3) = form(3, 0) = 0.5;
    form(1, 2) = form(2, 1) = -0.5;
    const Eigen::Matrix4d middle = root * form * root;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> middle_eigen(middle, Eigen::EigenvaluesOnly);
    if (middle_eigen.info() != Eigen::Success) return std::numeric_limits<double>::infinity();
    const double m1 = edge_norms_[edge1], m2 = edge_norms_[edge2];
    return middle_eigen.eigenvalues().cwiseAbs().maxCoeff() +
           kQuadraticMarginFactor * std::sqrt((r_ + 2) * kUnitRoundoff) * (m1 * m1 + m2 * m2);
  }
  /// largest_quadratic's margin over its rounding estimate (above). Smaller: a quadratic
  /// term that could fall below the exact one; larger: smaller radii where the projected
  /// rates nearly align.
  static constexpr double kQuadraticMarginFactor = 10.0;
  static double median_of_three(double a, double b, double c) {
    return std::max(std::min(a, b), std::min(std::max(a, b), c));
  }
  /// Rates whose norm lies outside this range keep their Frobenius norm in projected_rate:
  /// below it their squares may lose their relative accuracy to underflow, above it overflow
  /// (modes left unscaled, scale_modes, can reach 1e300). Narrower: looser bounds for extreme
  /// rates only; wider: squares that leave the double range.
  static constexpr double kSmallestSquaredRate = 1e-100;
  static constexpr double kLargestSquaredRate = 1e100;
  static bool squares_in_range(double norm) { return norm >= kSmallestSquaredRate && norm <= kLargestSquaredRate; }
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
  const double* modes_;               // the model's scaled basis, or scaled_modes_
  int mode_exponent_ = 0;             // k: modes_ holds the basis times 2^-k
  std::vector<double> scaled_modes_;  // empty when k = 0
  double eta0_ = 0.0, eta1_ = 0.0;
  std::vector<double> edge_norms_;            // ||E||_F of each edge's rates, rounded up
  std::vector<Eigen::Matrix3d> edge_grams_;   // E E^T of each edge's rates
  std::vector<Eigen::Matrix3d> cross_grams_;  // E1 E2^T of each triangle's first two edges (largest_quadratic)
};

/// A set's radius and the direction that proves it.
struct SetRadius {
  double radius = 0.0;
  bool along_mean = true;  ///< along the set's mean normal, else along a cone's axis
};

/// The radius of a set of triangles with boundary `chain` (a simple cycle) and normal sum
/// `normal_sum`: the smaller of its triangles' and its contour's along its mean normal, or
/// along the axis axis_to_try gives where that radius is larger (the mean on a tie); 0 when it
/// would not exceed `floor` (the contour, the costly part, is then not bounded).
template <typename Triangles>
SetRadius set_radius(const RadiusBounds& bounds, const Vector3d& normal_sum, const std::vector<DirectedEdge>& chain,
                     Triangles for_each_triangle, double floor = 0.0) {
  // d must be unit to rounding (FLOATING POINT in patch_radius.hpp): the norm of a sum whose
  // squares are subnormal errs by up to tens of percent.
  const double length2 = normal_sum.squaredNorm();
  if (!(length2 >= std::numeric_limits<double>::min()) || !std::isfinite(length2)) return {};
  std::vector<Vector3d> normals;
  std::vector<int> vertices;
  for_each_triangle([&](int t) {
    normals.push_back(bounds.rest_normal(t));
    for (const int v : bounds.triangle(t)) vertices.push_back(v);
  });
  // The vertices in at most two of the set's triangles, sorted.
  std::sort(vertices.begin(), vertices.end());
  std::vector<int> small_fans;
  for (std::size_t i = 0, j = 0; i < vertices.size(); i = j) {
    while (j < vertices.size() && vertices[j] == vertices[i]) ++j;
    if (j - i <= 2) small_fans.push_back(vertices[i]);
  }
  // The radius along d, 0 unless above `above`.
  const auto radius_along = [&](const Vector3d& d, double above) {
    double radius = std::numeric_limits<double>::infinity();
    for_each_triangle([&](int t) {
      if (radius > above) radius = std::min(radius, bounds.triangle_radius(d, t, radius));
    });
    if (!(radius > above)) return 0.0;
    const double with_contour = bounds.contour_radius(d, chain, small_fans, radius);
    return with_contour > above ? with_contour : 0.0;
  };
  const Vector3d mean = normal_sum / std::sqrt(length2);
  const double along_mean = radius_along(mean, floor);
  const Vector3d axis = axis_to_try(mean, normals);
  const double along_axis = axis.isZero() ? 0.0 : radius_along(axis, std::max(floor, along_mean));
  return along_axis > along_mean ? SetRadius{along_axis, false} : SetRadius{along_mean, true};
}

/// The triangles around the vertices two sets share (each visited by triangles_a and
/// triangles_b), less those in_either set, sorted: what bridges two nodes meeting at vertices
/// only, or pinched, into one patch (patch_radius.hpp).
template <typename TrianglesA, typename TrianglesB, typename InEither>
std::vector<int> bridging_triangles(const TriangleMesh& mesh, TrianglesA triangles_a, TrianglesB triangles_b,
                                    InEither in_either) {
  const auto vertices_of = [&](auto for_each_triangle) {
    std::vector<int> vertices;
    for_each_triangle([&](int t) {
      for (const int v : mesh.triangles()[t]) vertices.push_back(v);
    });
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    return vertices;
  };
  const std::vector<int> vertices_a = vertices_of(triangles_a), vertices_b = vertices_of(triangles_b);
  std::vector<int> shared;
  std::set_intersection(vertices_a.begin(), vertices_a.end(), vertices_b.begin(), vertices_b.end(),
                        std::back_inserter(shared));
  std::vector<int> bridge;
  for (const int v : shared) {
    for (const int* t = mesh.triangles_of_vertex_begin(v); t != mesh.triangles_of_vertex_end(v); ++t) {
      if (!in_either(*t)) bridge.push_back(*t);
    }
  }
  std::sort(bridge.begin(), bridge.end());
  bridge.erase(std::unique(bridge.begin(), bridge.end()), bridge.end());
  return bridge;
}

}  // namespace

PatchRadii::PatchRadii(const SubspaceBvh& bvh, const NodeBoundaries& boundaries)
    : node_radius_(bvh.nodes().size(), 0.0), along_mean_(bvh.nodes().size(), 0), patch_(bvh.nodes().size(), -1) {
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
  // The nodes' radii on every thread (each node's set alone), then the patches top-down.
  constexpr int kNodesPerTask = 16;
  run_tasks((node_count + kNodesPerTask - 1) / kNodesPerTask, resolve_threads(0), [&](int task, int) {
    for (int n = task * kNodesPerTask; n < std::min(node_count, (task + 1) * kNodesPerTask); ++n) {
      const SubspaceBvh::Node& node = nodes[n];
      if (node.triangle_end - node.triangle_begin >= kSmallestConeNode && boundaries.simple_cycle(n)) {
        const SetRadius set = set_radius(bounds, normal_sums[n], boundaries.chain(n), node_triangles(n));
        node_radius_[n] = set.radius;
        along_mean_[n] = set.radius > 0.0 && set.along_mean;
      }
    }
  });
  for (int n = 0; n < node_count; ++n) {
    const int parent = boundaries.parent(n);
    patch_[n] = parent >= 0 && patch_[parent] >= 0 ? patch_[parent] : node_radius_[n] > 0.0 ? n : -1;
    patch_count_ += patch_[n] == n;
  }

  // Pairs of patches whose triangles share an edge; and for two triangles sharing a vertex,
  // below their lowest common ancestor, every pair of their ancestors whose sizes the
  // traversal pairs (within kLargestUnionRatio), under patches or not, kept where their own
  // (bridged) union's radius exceeds their patches'. Leaves too (kSmallestPairPart): in a hash map their pairs,
  // which quadruple the table, had slowed its lookups more than their culls saved (the 75k
  // bunny at amplitude 0.01 8.0 ms with them against 5.5 without); PairRadiusTable's lists
  // cost less.
  const TriangleMesh& mesh = bvh.model().mesh();
  std::vector<int> leaf_of(mesh.triangle_count()), position_of(mesh.triangle_count());
  for (int n = 0; n < node_count; ++n) {
    for (int i = nodes[n].triangle_begin; nodes[n].is_leaf() && i < nodes[n].triangle_end; ++i) leaf_of[order[i]] = n;
  }
  for (int i = 0; i < mesh.triangle_count(); ++i) position_of[order[i]] = i;
  const auto key_of = [](int a, int b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
  };
  const auto in_node = [&](int n, int t) {
    return nodes[n].triangle_begin <= position_of[t] && position_of[t] < nodes[n].triangle_end;
  };
  // The set of a and b bridged by the stars of their shared vertices (patch_radius.hpp), when
  // its boundary is one simple cycle: its radius, else 0.
  const auto bridged_radius = [&](int a, int b, double floor, std::vector<DirectedEdge>& chain) {
    const std::vector<int> bridge = bridging_triangles(
        mesh, [&](auto visit) { node_triangles(a)(visit); }, [&](auto visit) { node_triangles(b)(visit); },
        [&](int t) { return in_node(a, t) || in_node(b, t); });
    if (bridge.empty()) return 0.0;
    // The two boundaries' sum, which the bridge's triangles then close.
    std::vector<DirectedEdge> edges(boundaries.chain(a).begin(), boundaries.chain(a).end());
    edges.insert(edges.end(), boundaries.chain(b).begin(), boundaries.chain(b).end());
    Vector3d normal_sum = normal_sums[a] + normal_sums[b];
    for (const int t : bridge) {
      const Triangle& f = mesh.triangles()[t];
      for (int k = 0; k < 3; ++k) edges.push_back({f[k], f[(k + 1) % 3]});
      normal_sum += bounds.rest_normal(t);
    }
    chain = boundary_chain(std::move(edges));
    if (!is_simple_cycle(chain)) return 0.0;
    return set_radius(
               bounds, normal_sum, chain,
               [&](auto visit) {
                 node_triangles(a)(visit);
                 node_triangles(b)(visit);
                 for (const int t : bridge) visit(t);
               },
               floor)
        .radius;
  };
  const auto union_radius = [&](int a, int b, double floor, std::vector<DirectedEdge>& union_chain) {
    if (!union_is_simple_cycle(boundaries.chain(a), boundaries.chain(b), union_chain)) {
      return bridged_radius(a, b, floor, union_chain);
    }
    return set_radius(
               bounds, normal_sums[a] + normal_sums[b], union_chain,
               [&](auto visit) {
                 node_triangles(a)(visit);
                 node_triangles(b)(visit);
               },
               floor)
        .radius;
  };
  const auto size = [&](int n) { return nodes[n].triangle_end - nodes[n].triangle_begin; };
  // The nodes holding triangle t but not triangle u, leaf first.
  const auto holding_only = [&](int t, int u, std::vector<int>& chain) {
    chain.clear();
    for (int n = leaf_of[t]; n >= 0; n = boundaries.parent(n)) {
      if (nodes[n].triangle_begin <= position_of[u] && position_of[u] < nodes[n].triangle_end) break;
      chain.push_back(n);
    }
  };
  std::unordered_set<std::uint64_t> patch_candidates, node_candidates;
  std::vector<int> chain_t, chain_u;
  // Each pair of triangles sharing a vertex, at the smallest vertex they share: that vertex
  // and how many they share.
  const auto shared_vertices = [&](int t, int u) {
    int smallest = -1, count = 0;
    for (const int v : mesh.triangles()[t]) {
      for (const int w : mesh.triangles()[u]) {
        if (v != w) continue;
        ++count;
        if (smallest < 0 || v < smallest) smallest = v;
      }
    }
    return std::make_pair(smallest, count);
  };
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    for (const int* t = mesh.triangles_of_vertex_begin(v); t != mesh.triangles_of_vertex_end(v); ++t) {
      for (const int* u = t + 1; u != mesh.triangles_of_vertex_end(v); ++u) {
        const auto [smallest, count] = shared_vertices(*t, *u);
        if (smallest != v) continue;
        const int patch_t = patch_[leaf_of[*t]], patch_u = patch_[leaf_of[*u]];
        if (patch_t >= 0 && patch_u >= 0 && patch_t != patch_u && count >= 2) {
          patch_candidates.insert(key_of(patch_t, patch_u));
        }
        holding_only(*t, *u, chain_t);
        holding_only(*u, *t, chain_u);
        for (int a : chain_t) {
          for (int b : chain_u) {
            // Each part a simple cycle: union_is_simple_cycle decides the union's boundary
            // only then (a node under a patch may be disconnected or pinched, on the lion and
            // the dragon; its union with a neighbour may then bound several cycles, which it accepts).
            if (boundaries.simple_cycle(a) && boundaries.simple_cycle(b) &&
                std::min(size(a), size(b)) >= kSmallestPairPart &&
                std::max(size(a), size(b)) <= kLargestUnionRatio * std::min(size(a), size(b))) {
              node_candidates.insert(key_of(a, b));
            }
          }
        }
      }
    }
  }
  // The unions' radii on every thread (the contours cost most of the construction): the
  // patches' first, which the node pairs must beat.
  const auto radii_of = [&](const std::unordered_set<std::uint64_t>& keys, auto floor_of) {
    const std::vector<std::uint64_t> ordered(keys.begin(), keys.end());
    std::vector<double> radii(ordered.size());
    const int threads = resolve_threads(0);
    std::vector<std::vector<DirectedEdge>> scratch(threads);
    constexpr int kPairsPerTask = 64;
    const int tasks = static_cast<int>((ordered.size() + kPairsPerTask - 1) / kPairsPerTask);
    run_tasks(tasks, threads, [&](int task, int thread) {
      const std::size_t end = std::min(ordered.size(), static_cast<std::size_t>(task + 1) * kPairsPerTask);
      for (std::size_t i = static_cast<std::size_t>(task) * kPairsPerTask; i < end; ++i) {
        const int a = static_cast<int>(ordered[i] >> 32), b = static_cast<int>(ordered[i] & 0xffffffffu);
        radii[i] = union_radius(a, b, floor_of(a, b), scratch[thread]);
      }
    });
    std::vector<std::pair<std::uint64_t, double>> result(ordered.size());
    for (std::size_t i = 0; i < ordered.size(); ++i) result[i] = {ordered[i], radii[i]};
    return result;
  };
  std::vector<std::pair<std::uint64_t, double>> kept;
  for (const auto& [key, radius] : radii_of(patch_candidates, [](int, int) { return 0.0; })) {
    if (radius > 0.0) kept.emplace_back(key, radius);
  }
  patch_pairs_ = PairRadiusTable(node_count, std::move(kept));
  kept.clear();
  const auto coarse = [&](int a, int b) { return patches_pair_radius(a, b); };
  for (const auto& [key, radius] : radii_of(node_candidates, coarse)) {
    if (radius > coarse(static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffu))) {
      kept.emplace_back(key, radius);
    }
  }
  node_pairs_ = PairRadiusTable(node_count, std::move(kept));
  largest_patch_pair_ = node_radius_;
  largest_node_pair_.assign(nodes.size(), 0.0);
  const auto note_largest = [](const PairRadiusTable& pairs, std::vector<double>& largest) {
    pairs.for_each([&](int a, int b, double radius) {
      largest[a] = std::max(largest[a], radius);
      largest[b] = std::max(largest[b], radius);
    });
  };
  note_largest(patch_pairs_, largest_patch_pair_);
  note_largest(node_pairs_, largest_node_pair_);
  for (int n = 0; n < node_count; ++n) {
    if (node_radius_[n] > 0.0) sorted_radii_.push_back(node_radius_[n]);
    if (patch_[n] == n) sorted_patch_radii_.push_back(node_radius_[n]);
  }
  std::sort(sorted_radii_.begin(), sorted_radii_.end());
  std::sort(sorted_patch_radii_.begin(), sorted_patch_radii_.end());
  for (int n = 0; n < node_count; ++n) {
    const int triangles = nodes[n].triangle_end - nodes[n].triangle_begin;
    if (patch_[n] == n && triangles > kRefitTriangleLimit) {
      large_patch_coverage_.emplace_back(node_radius_[n],
                                         static_cast<double>(triangles) / static_cast<double>(order.size()));
    }
  }
  std::sort(large_patch_coverage_.begin(), large_patch_coverage_.end());
  for (int i = static_cast<int>(large_patch_coverage_.size()) - 2; i >= 0; --i) {
    large_patch_coverage_[i].second += large_patch_coverage_[i + 1].second;
  }
  node_pairs_.for_each([&](int, int, double radius) { sorted_pair_radii_.push_back(radius); });
  std::sort(sorted_pair_radii_.begin(), sorted_pair_radii_.end());
}

double PatchRadii::fraction_above(double s) const { return detail::fraction_above(sorted_radii_, s); }

double PatchRadii::node_pair_fraction_above(double s) const { return detail::fraction_above(sorted_pair_radii_, s); }

double PatchRadii::patch_fraction_above(double s) const { return detail::fraction_above(sorted_patch_radii_, s); }

double PatchRadii::large_patch_coverage_above(double s) const {
  const auto first_above =
      std::upper_bound(large_patch_coverage_.begin(), large_patch_coverage_.end(), s,
                       [](double norm, const std::pair<double, double>& patch) { return norm < patch.first; });
  return first_above == large_patch_coverage_.end() ? 0.0 : first_above->second;
}

PairRadiusTable::PairRadiusTable(int node_count, std::vector<std::pair<std::uint64_t, double>> pairs)
    : offsets_(node_count + 1, 0) {
  std::sort(pairs.begin(), pairs.end());
  partners_.reserve(pairs.size());
  radii_.reserve(pairs.size());
  for (const auto& [key, radius] : pairs) {
    ++offsets_[(key >> 32) + 1];
    partners_.push_back(static_cast<int>(key & 0xffffffffu));
    radii_.push_back(radius);
  }
  for (int n = 0; n < node_count; ++n) offsets_[n + 1] += offsets_[n];
}

double PatchRadii::pair_radius(int a, int b) const {
  return std::max(patches_pair_radius(a, b), node_pair_radius(a, b));
}

}  // namespace sscc::detail
