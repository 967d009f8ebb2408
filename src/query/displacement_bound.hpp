// Displacement culling for subspace queries: a proof, per node (or pair of nodes) of the
// hierarchy, that the deformation of one step moves its triangles too little, relative to one
// another, to close the gaps they have at rest. Unlike a certificate (a bound on ||q_hat||
// valid in every direction), it looks at the step's own coordinates mode by mode, so a
// deformation that is large where it happens (an ear swinging) leaves the rest of the mesh
// culled. Private to the library; SelfCcd's traversal calls it when
// SelfCcdOptions::use_displacement_bounds.
//
// THEOREM. Node n's vertices are x_v(t) = p_v + U_v q(t) (U_v: the 3 x r block of the scaled
// basis, q(t) = (1 - t) q0 + t q1 the scaled coordinates). Let C_n be any 3 x r matrix (the
// node's mean block, SubspaceBvh::subspace_bound) and w_nj >= max over the node's vertices of
// ||(U_v - C_n) e_j||, F_n >= max over them of ||U_v - C_n||_F. Every point of a triangle of
// n, x = sum_i l_i x_i with barycentric l, is p_x + C_n q(t) + u_x(t) with p_x = sum_i l_i p_i
// the same combination at rest and ||u_x(t)|| <= max_v ||(U_v - C_n) q(t)||, at most both
//   sum_j |q_j(t)| w_nj <= max(sum_j |q0_j| w_nj, sum_j |q1_j| w_nj)   and
//   F_n ||q(t)|| <= F_n max(||q0||, ||q1||)
// (sums of absolute values, and norms, of functions linear in t are convex: largest at an
// end); D_n is the smaller of the two (the first wins when few modes move, the second when
// many do). So for a
// point x of triangle T under node a and y of T' under node b at the same t,
//   ||x - y|| >= ||p_x - p_y|| - ||(C_a - C_b) q(t)|| - D_a - D_b
//            >= dist_rest(T, T') - G_ab - D_a - D_b,  G_ab := max over the ends of ||(C_a - C_b) q||
// (again a convex function of t). With clearance(T) a lower bound of T's rest distance to every
// triangle it is considered with, and clearance(n) the least over n's triangles:
//   (intra) 2 D_n < clearance(n): no two considered triangles under n come within 0 (or d);
//   (inter) D_a + D_b + G_ab < max(clearance(a), clearance(b)): no considered pair across a, b
// does (dist_rest(T, T') is at least both triangles' clearances). Any two nodes, not only
// siblings. Triangles touching at rest have clearance 0: nodes holding them are never culled.
//
// A node's motion about one translation includes its rotation, which moves far points a lot
// and changes no gap. So a node of at least kSmallestAffineNode triangles also gets, per mode
// j, a 3 x 3 matrix A_nj (a least-squares affine fit of the mode's displacements over the
// node's vertices; any matrix would do) and rho_nj >= max_v ||U_v e_j - m_nj - A_nj (p_v - c_n)||
// (m_nj: the mean displacement, c_n: the mean rest position). With A(t) = sum_j q_j(t) A_nj,
// two points of the node move to
//   x - y = (I + A(t)) (p_x - p_y) + (r_x - r_y),  ||r_x - r_y|| <= 2 sum_j |q_j(t)| rho_nj,
// and ||(I + A) v|| >= (1 - ||A||_F) ||v||, so with a_n := max over the ends of ||A(q)||_F < 1
// (a norm of a function linear in t: convex) and R_n := max over the ends of sum_j |q_j| rho_nj,
//   (intra, affine) (1 - a_n) clearance(n) - 2 R_n > 0: no considered pair under n touches.
// A linear field (a linearised rotation, a uniform strain) leaves no residual: only a_n counts.
//
// FLOATING POINT. The queries test the positions they compute, x~_v = fl(p_v + U_v q_hat),
// moving linearly: each differs from the exact x_v(t) by at most
//   E = sqrt(3) gamma_{r+1} (max |p| + sum_j max |U_.j| max(|q0_j|, |q1_j|))
// (an r-term dot product and one addition per coordinate, interpolated between the two ends),
// so every condition above is tested with 2 E added, and with the kernels' minimum separation d.
// The rest clearances are lower bounds by construction: a separating direction's gap with its
// rounding subtracted (displacement_bound.cpp); spreads are rounded up, sums of non-negative
// terms carry a relative slack far above their rounding (kSumSlack), and G_ab is computed from
// the node centres' displacements with their rounding bound added. Every bound also carries an
// absolute allowance for results in the subnormal range (kUnderflowAllowance), every norm is
// scaled against underflow and overflow (a square of a difference below 1e-154 would vanish),
// and an overflow or NaN anywhere fails the test (comparisons are written so), and the rest
// gaps' search never skips a subtree before it has found a bound. The relative slack kSumSlack
// covers r-term sums for r below about 10^5.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "query/sweep.hpp"
#include "sscc/bvh/subspace_bvh.hpp"

namespace sscc::detail {

/// Relative slack on computed sums of non-negative terms (r products and additions, relative
/// error at most gamma_{r+1}, about 1e-13 for r = 1000). Smaller than the rounding could cull a
/// pair that only rounding keeps apart; larger only culls less.
inline constexpr double kSumSlack = 1.0 + 1e-10;

/// What the cull needs from the rest shape and the basis, per node: built once per detector.
class DisplacementBounds {
 public:
  explicit DisplacementBounds(const SubspaceBvh& bvh);

  /// A lower bound of the rest distance from any triangle under node n to any triangle it is
  /// considered with (neither adjacent nor excluded), anywhere in the mesh; 0 when one touches
  /// another at rest, infinity when none is considered.
  double clearance(int n) const { return clearance_[n]; }
  /// spread(n)[j] >= max over node n's vertices v of ||(U_v - C_n) e_j||, r values.
  const double* spread(int n) const { return &spread_[static_cast<std::size_t>(n) * modes_]; }
  /// >= max over node n's vertices v of ||U_v - C_n||_F.
  double frobenius_spread(int n) const { return frobenius_spread_[n]; }
  /// Node n's affine fits, the 3 x 3 matrices A_nj as a 9 x r row-major block (entry (a, b) of
  /// A_nj at [(3 a + b) r + j]), and their residual bounds rho_nj (r values); null for nodes
  /// of fewer than kSmallestAffineNode triangles.
  const double* affine_maps(int n) const;
  const double* affine_residuals(int n) const;
  /// The largest absolute rest coordinate.
  double largest_rest_coordinate() const { return largest_rest_coordinate_; }
  /// Per mode j, the largest absolute entry of the scaled basis's column j.
  const Eigen::VectorXd& largest_basis_entry() const { return largest_basis_entry_; }
  /// At most kSampledNodes nodes of at least kSmallestCountedNode triangles, spread over the
  /// hierarchy: what StepDisplacement::apart_fraction tests.
  const std::vector<int>& sample() const { return sample_; }

 private:
  int modes_ = 0;
  std::vector<int> sample_;
  std::vector<double> clearance_;
  std::vector<double> spread_;
  std::vector<double> frobenius_spread_;
  std::vector<int> affine_index_;  // per node: its fits' index, -1 for none
  std::vector<double> affine_maps_, affine_residuals_;
  double largest_rest_coordinate_ = 0.0;
  Eigen::VectorXd largest_basis_entry_;
};

/// Nodes with fewer triangles get no affine fit: their motion about one translation is
/// small anyway (their size is a few triangles'), and 9 r numbers per node would dominate the
/// memory of the fits. Lower: more memory and fits; higher: fewer nodes culled at large steps.
inline constexpr int kSmallestAffineNode = 16;

/// The sample by which a step judges how much of the hierarchy the displacement bounds cull
/// (where they cull some, the normal cones are not used: self_ccd.cpp). 64 tests cost O(64 r),
/// a few microseconds.
inline constexpr int kSampledNodes = 64;
/// The nodes the per-step decisions on the cones count, here and for the certificates
/// (self_ccd.cpp): two leaves' worth of triangles or more, the sizes the cones try.
inline constexpr int kSmallestCountedNode = 2 * kMaxLeafTriangles;

/// The cull for one step q_hat0 -> q_hat1 (scaled coordinates); nothing here outlives it.
class StepDisplacement {
 public:
  StepDisplacement(const DisplacementBounds& bounds, const SubspaceBvh& bvh, const Eigen::VectorXd& q_hat0,
                   const Eigen::VectorXd& q_hat1, double separation);

  /// Whether no two considered triangles under node n come within the separation during the
  /// step. Not given up when it keeps failing (as the cones are): its tests cost O(r) and
  /// giving up classes lost culls at small steps (the dragon at 0.01: 22% more node tests)
  /// without a measurable gain at large ones.
  bool node_apart(int n);
  /// Whether no considered pair of a triangle under a and one under b does.
  bool nodes_apart(int a, int b);
  /// The fraction of the nodes of DisplacementBounds::sample() for which node_apart holds.
  double apart_fraction();

 private:
  /// D_n of the theorem, once per node.
  double reach(int n);
  /// Whether the affine test culls node n.
  bool affine_apart(int n) const;
  /// C_n q_hat at both ends, with the bound of their rounding, once per node.
  struct Centres {
    Eigen::Vector3d at0, at1;
    double rounding;
  };
  const Centres& centres(int n);

  const DisplacementBounds& bounds_;
  const SubspaceBvh& bvh_;
  Eigen::VectorXd q_hat0_, q_hat1_;
  Eigen::VectorXd magnitude0_, magnitude1_;  // |q_hat0|, |q_hat1| componentwise
  double norm_;                              // max(||q_hat0||, ||q_hat1||)
  double margin_;                            // 2 E plus the separation
  LazyBoxes<double> reaches_;
  LazyBoxes<Centres> centres_;
};

}  // namespace sscc::detail
