#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "sscc/ccd/exact/polynomial.hpp"

using sscc::exact::Polynomial;
using sscc::exact::RealRoot;

namespace {

Polynomial from_roots(const std::vector<mpq_class>& roots, const mpq_class& scale = 1) {
  Polynomial p({scale});
  for (const mpq_class& r : roots) p = p * Polynomial::linear(-r, 1);
  return p;
}

}  // namespace

TEST_CASE("polynomial arithmetic and division", "[exact][polynomial]") {
  const Polynomial a = from_roots({1, 2, 3});
  const Polynomial b = from_roots({2, mpq_class(1, 2)});
  Polynomial q;
  Polynomial r;
  sscc::exact::divide(a, b, q, r);
  CHECK(q * b + r == a);
  CHECK(r.degree() < b.degree());
  CHECK(sscc::exact::gcd(a, b) == from_roots({2}));
  CHECK(sscc::exact::squarefree_part(from_roots({1, 1, 3, 3, 3})) == from_roots({1, 3}));
  CHECK((a - a).is_zero());
  CHECK(a.derivative() == Polynomial({11, -12, 3}));
}

TEST_CASE("roots in [0, 1] of polynomials with known rational roots", "[exact][polynomial]") {
  std::mt19937_64 rng(20261122);
  std::uniform_int_distribution<int> numerator(-4, 12);
  std::uniform_int_distribution<int> count(1, 4);
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<mpq_class> roots;
    const int n = count(rng);
    for (int i = 0; i < n; ++i) roots.emplace_back(numerator(rng), 8);
    for (auto& x : roots) x.canonicalize();
    // An irreducible factor t^2 + 1 adds no real root.
    Polynomial p = from_roots(roots, mpq_class(-3, 7));
    if (trial % 3 == 0) p = p * Polynomial({1, 0, 1});
    std::vector<mpq_class> expected;
    for (const auto& x : roots) {
      if (x >= 0 && x <= 1) expected.push_back(x);
    }
    std::sort(expected.begin(), expected.end());
    expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
    std::vector<RealRoot> found = sscc::exact::roots_in_unit_interval(p);
    REQUIRE(found.size() == expected.size());
    for (std::size_t i = 0; i < found.size(); ++i) {
      CHECK(sscc::exact::compare(expected[i], found[i]) == 0);
      CHECK(sscc::exact::sign_at_root(p, found[i]) == 0);
    }
  }
}

TEST_CASE("irrational roots: isolation, signs and comparison", "[exact][polynomial]") {
  const Polynomial half_square = Polynomial({mpq_class(-1, 2), 0, 1});  // t^2 - 1/2
  std::vector<RealRoot> roots = sscc::exact::roots_in_unit_interval(half_square);
  REQUIRE(roots.size() == 1);
  RealRoot root = roots[0];
  CHECK_FALSE(root.is_exact());
  CHECK(sscc::exact::sign_at_root(Polynomial::linear(mpq_class(-7, 10), 1), root) == 1);
  CHECK(sscc::exact::sign_at_root(Polynomial::linear(mpq_class(-71, 100), 1), root) == -1);
  CHECK(sscc::exact::sign_at_root(half_square * Polynomial({5, 1}), root) == 0);
  CHECK(sscc::exact::compare(mpq_class(7071, 10000), root) < 0);
  CHECK(sscc::exact::compare(mpq_class(7072, 10000), root) > 0);
  // The same number as a root of another polynomial compares equal.
  std::vector<RealRoot> other = sscc::exact::roots_in_unit_interval(half_square * from_roots({mpq_class(9, 10)}));
  REQUIRE(other.size() == 2);
  CHECK(sscc::exact::compare(other[0], root) == 0);
  CHECK(sscc::exact::compare(other[1], root) > 0);
  sscc::exact::refine(root, mpq_class(1, 1000000));
  CHECK(root.hi - root.lo <= mpq_class(1, 1000000));
  CHECK(root.lo.get_d() < std::sqrt(0.5));
  CHECK(root.hi.get_d() > std::sqrt(0.5) - 1e-15);
}

TEST_CASE("roots at the ends of [0, 1] and double roots", "[exact][polynomial]") {
  const auto roots = sscc::exact::roots_in_unit_interval(from_roots({0, 1, 1, mpq_class(1, 2)}));
  REQUIRE(roots.size() == 3);
  CHECK((roots[0].is_exact() && roots[0].lo == 0));
  CHECK((roots[2].is_exact() && roots[2].lo == 1));
  CHECK(sscc::exact::roots_in_unit_interval(Polynomial({3})).empty());
}

TEST_CASE("round_down gives the largest double not above the rational", "[exact]") {
  for (const mpq_class& x : {mpq_class(1, 3), mpq_class(-1, 3), mpq_class(1, 2), mpq_class(-7, 10)}) {
    const double d = sscc::exact::round_down(x);
    CHECK(mpq_class(d) <= x);
    CHECK(mpq_class(std::nextafter(d, INFINITY)) > x);
  }
}
