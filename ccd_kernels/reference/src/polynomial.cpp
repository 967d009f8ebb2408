#include "sscc/ccd/exact/polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace sscc::exact {

namespace {

int sign_of(const mpq_class& x) { return sgn(x); }

}  // namespace

Polynomial::Polynomial(std::vector<mpq_class> coefficients) : coefficients_(std::move(coefficients)) { trim(); }

Polynomial Polynomial::linear(const mpq_class& c0, const mpq_class& c1) { return Polynomial({c0, c1}); }

void Polynomial::trim() {
  while (!coefficients_.empty() && sgn(coefficients_.back()) == 0) coefficients_.pop_back();
}

mpq_class Polynomial::operator()(const mpq_class& t) const {
  mpq_class value = 0;
  for (auto it = coefficients_.rbegin(); it != coefficients_.rend(); ++it) {
    value = value * t + *it;
  }
  return value;
}

const std::vector<mpz_class>& Polynomial::integer_coefficients() const {
  if (integer_coefficients_.empty() && !coefficients_.empty()) {
    mpz_class common = 1;
    for (const mpq_class& c : coefficients_) mpz_lcm(common.get_mpz_t(), common.get_mpz_t(), c.get_den_mpz_t());
    for (const mpq_class& c : coefficients_) {
      integer_coefficients_.emplace_back(c.get_num() * (common / c.get_den()));
    }
  }
  return integer_coefficients_;
}

int Polynomial::sign_at(const mpq_class& t) const {
  // p(n/d) d^k = sum c_i n^i d^(k-i) with d > 0: Horner in integers, no canonicalisation.
  const std::vector<mpz_class>& c = integer_coefficients();
  if (c.empty()) return 0;
  const mpz_class& n = t.get_num();
  const mpz_class& d = t.get_den();
  mpz_class value = c.back();
  mpz_class d_power = 1;
  for (std::size_t i = c.size() - 1; i-- > 0;) {
    d_power *= d;
    value = value * n + c[i] * d_power;
  }
  return sgn(value);
}

Polynomial Polynomial::derivative() const {
  std::vector<mpq_class> d;
  for (std::size_t i = 1; i < coefficients_.size(); ++i) {
    d.emplace_back(coefficients_[i] * static_cast<long>(i));
  }
  return Polynomial(std::move(d));
}

Polynomial Polynomial::monic() const {
  if (is_zero()) return *this;
  std::vector<mpq_class> c = coefficients_;
  const mpq_class lead = c.back();
  for (auto& x : c) x /= lead;
  return Polynomial(std::move(c));
}

Polynomial operator+(const Polynomial& a, const Polynomial& b) {
  std::vector<mpq_class> c(std::max(a.coefficients_.size(), b.coefficients_.size()));
  for (std::size_t i = 0; i < a.coefficients_.size(); ++i) c[i] += a.coefficients_[i];
  for (std::size_t i = 0; i < b.coefficients_.size(); ++i) c[i] += b.coefficients_[i];
  return Polynomial(std::move(c));
}

Polynomial operator-(const Polynomial& a) {
  std::vector<mpq_class> c = a.coefficients_;
  for (auto& x : c) x = -x;
  return Polynomial(std::move(c));
}

Polynomial operator-(const Polynomial& a, const Polynomial& b) { return a + (-b); }

Polynomial operator*(const Polynomial& a, const Polynomial& b) {
  if (a.is_zero() || b.is_zero()) return Polynomial();
  std::vector<mpq_class> c(a.coefficients_.size() + b.coefficients_.size() - 1);
  for (std::size_t i = 0; i < a.coefficients_.size(); ++i) {
    for (std::size_t j = 0; j < b.coefficients_.size(); ++j) {
      c[i + j] += a.coefficients_[i] * b.coefficients_[j];
    }
  }
  return Polynomial(std::move(c));
}

void divide(const Polynomial& a, const Polynomial& b, Polynomial& quotient, Polynomial& remainder) {
  if (b.is_zero()) throw std::invalid_argument("sscc::exact::divide: division by zero");
  std::vector<mpq_class> r = a.coefficients();
  const int db = b.degree();
  std::vector<mpq_class> q(std::max(0, a.degree() - db + 1));
  for (int k = a.degree(); k >= db; --k) {
    const mpq_class factor = r[k] / b.leading();
    q[k - db] = factor;
    if (sgn(factor) == 0) continue;
    for (int j = 0; j <= db; ++j) r[k - db + j] -= factor * b.coefficients()[j];
  }
  quotient = Polynomial(std::move(q));
  remainder = Polynomial(std::move(r));
}

Polynomial gcd(const Polynomial& a, const Polynomial& b) {
  Polynomial x = a;
  Polynomial y = b;
  while (!y.is_zero()) {
    Polynomial q;
    Polynomial r;
    divide(x, y, q, r);
    x = std::move(y);
    y = std::move(r);
  }
  return x.monic();
}

Polynomial squarefree_part(const Polynomial& p) {
  if (p.degree() <= 0) return p.monic();
  const Polynomial g = gcd(p, p.derivative());
  Polynomial q;
  Polynomial r;
  divide(p, g, q, r);
  return q.monic();
}

SturmSequence::SturmSequence(const Polynomial& squarefree) {
  sequence_.push_back(squarefree);
  sequence_.push_back(squarefree.derivative());
  while (!sequence_.back().is_zero()) {
    Polynomial q;
    Polynomial r;
    divide(sequence_[sequence_.size() - 2], sequence_.back(), q, r);
    sequence_.push_back(-r);
  }
  sequence_.pop_back();
}

int SturmSequence::sign_variations(const mpq_class& x) const {
  int variations = 0;
  int previous = 0;
  for (const Polynomial& p : sequence_) {
    const int s = p.sign_at(x);
    if (s == 0) continue;
    if (previous != 0 && s != previous) ++variations;
    previous = s;
  }
  return variations;
}

int SturmSequence::count_roots(const mpq_class& lo, const mpq_class& hi) const {
  return sign_variations(lo) - sign_variations(hi);
}

namespace {

void isolate(const Polynomial& p, const SturmSequence& sturm, const mpq_class& lo, const mpq_class& hi,
             std::vector<RealRoot>& out) {
  const int hi_is_root = p.sign_at(hi) == 0 ? 1 : 0;
  const int count = sturm.count_roots(lo, hi) - hi_is_root;
  if (count == 0) return;
  if (count == 1 && hi_is_root == 0 && p.sign_at(lo) != 0) {
    out.push_back({p, lo, hi});
    return;
  }
  const mpq_class mid = (lo + hi) / 2;
  isolate(p, sturm, lo, mid, out);
  if (p.sign_at(mid) == 0) out.push_back({p, mid, mid});
  isolate(p, sturm, mid, hi, out);
}

}  // namespace

std::vector<RealRoot> roots_in_unit_interval(const Polynomial& p) {
  if (p.is_zero()) {
    throw std::invalid_argument("sscc::exact::roots_in_unit_interval: zero polynomial");
  }
  std::vector<RealRoot> roots;
  if (p.degree() == 0) return roots;
  const Polynomial q = squarefree_part(p);
  const SturmSequence sturm(q);
  const mpq_class zero = 0;
  const mpq_class one = 1;
  if (q.sign_at(zero) == 0) roots.push_back({q, zero, zero});
  isolate(q, sturm, zero, one, roots);
  if (q.sign_at(one) == 0) roots.push_back({q, one, one});
  return roots;
}

void bisect(RealRoot& root) {
  if (root.is_exact()) return;
  const mpq_class mid = (root.lo + root.hi) / 2;
  const int s_mid = root.polynomial.sign_at(mid);
  if (s_mid == 0) {
    root.lo = mid;
    root.hi = mid;
  } else if (s_mid == root.polynomial.sign_at(root.lo)) {
    root.lo = mid;
  } else {
    root.hi = mid;
  }
}

void refine(RealRoot& root, const mpq_class& width) {
  while (root.hi - root.lo > width) bisect(root);
}

int sign_at_root(const Polynomial& g, RealRoot& root) {
  if (g.is_zero()) return 0;
  if (root.is_exact()) return g.sign_at(root.lo);
  // g without a root in (lo, hi] has the sign it has at hi.
  const SturmSequence sturm(squarefree_part(g));
  if (sturm.count_roots(root.lo, root.hi) == 0) return g.sign_at(root.hi);
  // A common factor of g and the root's square-free polynomial has only simple roots, and
  // the root is the only one of them in (lo, hi): it vanishes there iff it changes sign.
  const Polynomial common = gcd(root.polynomial, g);
  if (common.degree() >= 1 && common.sign_at(root.lo) * common.sign_at(root.hi) < 0) return 0;
  // g is non-zero at the root: shrink the interval until g has no root in (lo, hi].
  while (!root.is_exact() && sturm.count_roots(root.lo, root.hi) != 0) bisect(root);
  return root.is_exact() ? g.sign_at(root.lo) : g.sign_at(root.hi);
}

int compare(const mpq_class& value, RealRoot& root) {
  while (true) {
    if (root.is_exact()) return sign_of(value - root.lo);
    if (value <= root.lo) return -1;
    if (value >= root.hi) return 1;
    if (root.polynomial.sign_at(value) == 0) return 0;
    bisect(root);
  }
}

int compare(RealRoot& a, RealRoot& b) {
  if (a.is_exact()) return compare(a.lo, b);
  if (b.is_exact()) return -compare(b.lo, a);
  // Equal iff a common factor (its roots simple, and each interval holding only its own
  // root) changes sign across the overlap of the two intervals.
  const Polynomial common = gcd(a.polynomial, b.polynomial);
  while (true) {
    if (a.is_exact()) return compare(a.lo, b);
    if (b.is_exact()) return -compare(b.lo, a);
    if (a.hi <= b.lo) return -1;
    if (b.hi <= a.lo) return 1;
    const mpq_class lo = std::max(a.lo, b.lo);
    const mpq_class hi = std::min(a.hi, b.hi);
    if (common.degree() >= 1 && common.sign_at(lo) * common.sign_at(hi) < 0) return 0;
    bisect(a);
    bisect(b);
  }
}

double round_down(const mpq_class& value) {
  double d = value.get_d();  // truncates toward zero
  if (mpq_class(d) > value) d = std::nextafter(d, -std::numeric_limits<double>::infinity());
  return d;
}

Vec3q to_rational(double x, double y, double z) { return {mpq_class(x), mpq_class(y), mpq_class(z)}; }

PolyVec3 linear_trajectory(const Vec3q& x0, const Vec3q& x1) {
  PolyVec3 x;
  for (int k = 0; k < 3; ++k) x[k] = Polynomial::linear(x0[k], x1[k] - x0[k]);
  return x;
}

PolyVec3 operator-(const PolyVec3& a, const PolyVec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

PolyVec3 cross(const PolyVec3& a, const PolyVec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Polynomial dot(const PolyVec3& a, const PolyVec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

bool is_zero(const PolyVec3& a) { return a[0].is_zero() && a[1].is_zero() && a[2].is_zero(); }

}  // namespace sscc::exact
