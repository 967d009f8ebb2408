// Exact univariate polynomials over the rationals (GMP), with the real-root machinery the
// exact deciders need: Sturm sequences, isolation of the real roots in [0, 1], and the
// exact sign of another polynomial at such a root.
//
// Guarantee: everything here is exact. Nothing is rounded; a real root is either an exact
// rational or an isolating open interval (lo, hi) of its square-free polynomial, with
// rational end points at which that polynomial is non-zero and of opposite signs.
#pragma once

#include <gmpxx.h>

#include <array>
#include <vector>

namespace sscc::exact {

/// A polynomial in t with rational coefficients, lowest degree first. The zero polynomial
/// has no coefficients; otherwise the leading coefficient is non-zero. Like a standard
/// container, one object may be read from several threads only once it has been evaluated
/// (sign_at fills a cache); distinct objects are independent.
class Polynomial {
 public:
  Polynomial() = default;
  explicit Polynomial(std::vector<mpq_class> coefficients);
  /// c0 + c1 t.
  static Polynomial linear(const mpq_class& c0, const mpq_class& c1);

  /// -1 for the zero polynomial.
  int degree() const { return static_cast<int>(coefficients_.size()) - 1; }
  bool is_zero() const { return coefficients_.empty(); }
  const std::vector<mpq_class>& coefficients() const { return coefficients_; }
  const mpq_class& leading() const { return coefficients_.back(); }

  mpq_class operator()(const mpq_class& t) const;
  /// Sign (-1, 0, +1) of the value at t.
  int sign_at(const mpq_class& t) const;
  Polynomial derivative() const;
  /// This polynomial divided by its leading coefficient (zero stays zero).
  Polynomial monic() const;

  friend Polynomial operator+(const Polynomial& a, const Polynomial& b);
  friend Polynomial operator-(const Polynomial& a, const Polynomial& b);
  friend Polynomial operator-(const Polynomial& a);
  friend Polynomial operator*(const Polynomial& a, const Polynomial& b);
  friend bool operator==(const Polynomial& a, const Polynomial& b) { return a.coefficients_ == b.coefficients_; }

 private:
  void trim();
  const std::vector<mpz_class>& integer_coefficients() const;
  std::vector<mpq_class> coefficients_;
  // A positive multiple with integer coefficients, for evaluating signs without the gcds
  // that every rational operation costs. Filled on first use; not shared across threads.
  mutable std::vector<mpz_class> integer_coefficients_;
};

/// Euclidean division a = q b + r with deg r < deg b. Precondition: b is not zero.
void divide(const Polynomial& a, const Polynomial& b, Polynomial& quotient, Polynomial& remainder);
/// Monic greatest common divisor (zero when both are zero).
Polynomial gcd(const Polynomial& a, const Polynomial& b);
/// The product of the distinct irreducible factors: p / gcd(p, p'), monic.
Polynomial squarefree_part(const Polynomial& p);

/// Sturm sequence of a square-free polynomial, counting its distinct real roots.
class SturmSequence {
 public:
  explicit SturmSequence(const Polynomial& squarefree);
  /// Number of distinct real roots in the half-open interval (lo, hi], lo < hi.
  int count_roots(const mpq_class& lo, const mpq_class& hi) const;

 private:
  int sign_variations(const mpq_class& x) const;
  std::vector<Polynomial> sequence_;
};

/// A real root of `polynomial` (square-free, monic). Exact when lo == hi; otherwise the
/// only root of `polynomial` in the open interval (lo, hi), with polynomial(lo) and
/// polynomial(hi) non-zero and of opposite signs.
struct RealRoot {
  Polynomial polynomial;
  mpq_class lo;
  mpq_class hi;
  bool is_exact() const { return lo == hi; }
};

/// The distinct real roots of p in the closed interval [0, 1], in increasing order.
/// Precondition: p is not the zero polynomial.
std::vector<RealRoot> roots_in_unit_interval(const Polynomial& p);
/// Halves the isolating interval (or finds the root exactly).
void bisect(RealRoot& root);
/// Refines until hi - lo <= width.
void refine(RealRoot& root, const mpq_class& width);
/// Exact sign of g at the root; refines the root's interval as needed.
int sign_at_root(const Polynomial& g, RealRoot& root);
/// Sign of (value - root): -1, 0 or +1. Refines the root's interval as needed.
int compare(const mpq_class& value, RealRoot& root);
/// Sign of (a - b) for two real roots. Refines both intervals as needed.
int compare(RealRoot& a, RealRoot& b);
/// The largest double not greater than the rational.
double round_down(const mpq_class& value);

/// Vectors of polynomials: positions and differences of linearly moving points.
using Vec3q = std::array<mpq_class, 3>;
using PolyVec3 = std::array<Polynomial, 3>;

/// A double point as exact rationals.
Vec3q to_rational(double x, double y, double z);
/// x(t) = x0 + t (x1 - x0), coordinate-wise.
PolyVec3 linear_trajectory(const Vec3q& x0, const Vec3q& x1);
PolyVec3 operator-(const PolyVec3& a, const PolyVec3& b);
PolyVec3 cross(const PolyVec3& a, const PolyVec3& b);
Polynomial dot(const PolyVec3& a, const PolyVec3& b);
bool is_zero(const PolyVec3& a);

}  // namespace sscc::exact
