#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <utility>

#include "sscc/ccd/kernels.hpp"
#include "sscc/certificates/triangle_pair_bound.hpp"
#include "support/contact_search.hpp"
#include "support/overflow_allowed.hpp"

namespace {

using sscc::ModalTriangle;
using sscc::test::OverflowAllowed;

struct PairMaker {
  std::mt19937_64 rng;
  std::normal_distribution<double> normal;
  explicit PairMaker(std::uint64_t seed) : rng(seed) {}

  Eigen::Vector3d point(double spread) {
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k) p[k] = spread * normal(rng);
    return p;
  }

  /// r random linear and quadratic fields (the quadratic ones scaled by `quadratic_scale`).
  std::pair<std::vector<Eigen::Matrix3d>, std::vector<Eigen::Matrix3d>> fields(int r, double quadratic_scale) {
    std::vector<Eigen::Matrix3d> linear(r), quadratic(r);
    for (int j = 0; j < r; ++j) {
      linear[j] = Eigen::Matrix3d::NullaryExpr([&] { return normal(rng); });
      quadratic[j] = Eigen::Matrix3d::NullaryExpr([&] { return quadratic_scale * normal(rng); });
    }
    return {linear, quadratic};
  }

  /// Modes: random, or smooth (a random linear and quadratic field of the position, as
  /// real bases are), r columns.
  ModalTriangle with_modes(const std::array<Eigen::Vector3d, 3>& rest, const std::vector<Eigen::Matrix3d>& linear,
                           const std::vector<Eigen::Matrix3d>& quadratic, bool smooth, double noise) {
    ModalTriangle t;
    t.rest = rest;
    const int r = static_cast<int>(linear.size());
    for (int i = 0; i < 3; ++i) {
      t.modes[i].resize(3, r);
      for (int j = 0; j < r; ++j) {
        const Eigen::Vector3d& x = rest[i];
        Eigen::Vector3d u = linear[j] * x + quadratic[j] * x.cwiseProduct(x);
        if (!smooth) u = point(1.0);
        t.modes[i].col(j) = u + noise * point(1.0);
      }
    }
    return t;
  }
};

}  // namespace

TEST_CASE("triangle-pair radius: the lower bound never exceeds a searched contact, and meets epsilon",
          "[certificates]") {
  PairMaker m(11);
  int tested = 0, accurate = 0;
  for (int trial = 0; trial < 240; ++trial) {
    const int r = 1 + trial % 8;
    const auto [linear, quadratic] = m.fields(r, 0.5);
    std::array<Eigen::Vector3d, 3> a{m.point(0.3), m.point(0.3), m.point(0.3)};
    std::array<Eigen::Vector3d, 3> b;
    const Eigen::Vector3d offset = m.point(0.4);
    switch (trial % 4) {
      case 0:  // random
        b = {a[0] + offset + m.point(0.2), a[1] + offset + m.point(0.2), a[2] + offset + m.point(0.2)};
        break;
      case 1: {  // nearly parallel, a small gap along the normal
        const Eigen::Vector3d n = (a[1] - a[0]).cross(a[2] - a[0]).normalized();
        const Eigen::Vector3d shift = 1e-3 * n + 0.05 * offset.cross(n);
        b = {a[0] + shift, a[1] + shift, a[2] + shift};
        break;
      }
      case 2:  // a needle
        b = {a[0] + offset, a[0] + offset + m.point(0.3), a[0] + offset + m.point(1e-7)};
        break;
      default:  // touching at rest: b's first vertex on a's face
        b = {0.3 * a[0] + 0.3 * a[1] + 0.4 * a[2], a[0] + offset, a[1] + offset + m.point(0.1)};
        break;
    }
    const bool touching = trial % 4 == 3;
    if (!touching && sscc::ccd::triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2])) continue;
    const bool smooth = trial % 3 != 0;
    const ModalTriangle ta = m.with_modes(a, linear, quadratic, smooth, 0.01);
    const ModalTriangle tb = m.with_modes(b, linear, quadratic, smooth, 0.01);
    sscc::TrianglePairRadiusOptions options;
    const sscc::TrianglePairRadius bound = sscc::triangle_pair_radius(ta, tb, options);
    const double searched = sscc::test::searched_contact_norm(ta, tb, 10, trial);
    INFO("trial " << trial << " r " << r << " lower " << bound.lower << " upper " << bound.upper << " searched "
                  << searched);
    ++tested;
    REQUIRE(bound.lower >= 0.0);
    REQUIRE(bound.lower <= searched * (1.0 + 1e-12));
    REQUIRE(bound.lower <= bound.upper);
    REQUIRE(sscc::one_dimensional_radius(ta, tb) <= searched * (1.0 + 1e-12));
    if (touching) REQUIRE(bound.lower == 0.0);
    // Refinement stops accurate or exhausted; near-parallel pairs close together (the
    // second kind) and pairs no motion can close (r < 3) typically exhaust the budget.
    const bool exhausted = bound.evaluations + 4 > options.max_evaluations || bound.depth >= options.max_depth;
    if (!touching && !exhausted) {
      REQUIRE(bound.lower >= (1.0 - options.epsilon) * bound.upper * (1.0 - 1e-12));
      ++accurate;
    }
  }
  REQUIRE(tested > 200);
  REQUIRE(accurate > tested / 3);
}

TEST_CASE("triangle-pair radius: invariant under a common scaling of positions and modes", "[certificates]") {
  PairMaker m(3);
  ModalTriangle a, b;
  a.rest = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};
  b.rest = {Eigen::Vector3d(0.2, 0.2, 0.5), Eigen::Vector3d(1.1, 0.1, 0.6), Eigen::Vector3d(0.1, 1.2, 0.4)};
  for (int i = 0; i < 3; ++i) {
    a.modes[i] = Eigen::MatrixXd::NullaryExpr(3, 5, [&] { return m.normal(m.rng); });
    b.modes[i] = Eigen::MatrixXd::NullaryExpr(3, 5, [&] { return m.normal(m.rng); });
  }
  const double reference = sscc::triangle_pair_radius(a, b).lower;
  REQUIRE(reference > 0.0);
  for (double scale : {1e-6, 1e-3, 1e3, 1e6}) {
    ModalTriangle sa = a, sb = b;
    for (int i = 0; i < 3; ++i) {
      sa.rest[i] *= scale, sb.rest[i] *= scale;
      sa.modes[i] *= scale, sb.modes[i] *= scale;
    }
    REQUIRE(sscc::triangle_pair_radius(sa, sb).lower == Approx(reference).epsilon(1e-6));
  }
}

TEST_CASE("triangle-pair radius: a known contact, and modes that cannot close the gap", "[certificates]") {
  // b lies 1 above a; mode 0 moves b down by 1 per unit: contact at exactly ||q_hat|| = 1.
  ModalTriangle a, b;
  a.rest = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};
  b.rest = {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 1), Eigen::Vector3d(0, 1, 1)};
  for (int i = 0; i < 3; ++i) {
    a.modes[i] = Eigen::MatrixXd::Zero(3, 2);
    b.modes[i] = Eigen::MatrixXd::Zero(3, 2);
    b.modes[i](2, 0) = -1.0;
    a.modes[i](0, 1) = b.modes[i](0, 1) = 1.0;  // a common sideways translation: no help
  }
  const sscc::TrianglePairRadius bound = sscc::triangle_pair_radius(a, b);
  REQUIRE(bound.lower <= 1.0);
  REQUIRE(bound.lower >= 0.9);
  REQUIRE(bound.upper == Approx(1.0));
  for (int i = 0; i < 3; ++i) b.modes[i](2, 0) = 0.0;  // now nothing moves them apart or together
  // Only the rounding of the computed positions (a few units of roundoff of ||q_hat||) could
  // close the gap of 1: the bound is that far out, beyond any global radius.
  const double unreachable = sscc::triangle_pair_radius(a, b).lower;
  REQUIRE(unreachable > 1e13);
  REQUIRE(unreachable < 1.0 / std::numeric_limits<double>::epsilon());
}

TEST_CASE("1D bound: its rounding never lifts it above the true radius (parallel faces, far from the origin)",
          "[certificates]") {
  // b lies at height h above a along (1, 1, 0) / sqrt 2 and moves towards it at unit rate
  // per unit q_hat (mode (-s, -s, 0), s = fl(sqrt 0.5)): the radius is h / s exactly in real
  // arithmetic, while the triangles span thousands of units sideways.
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<long long> coordinate(-1000, 1000);
  const double s = std::sqrt(0.5);
  for (int bits : {10, 20, 30}) {
    const double h = std::ldexp(1.0, -bits);
    const long double truth = static_cast<long double>(h) / static_cast<long double>(s);
    for (int trial = 0; trial < 4000; ++trial) {
      ModalTriangle a, b;
      for (int i = 0; i < 3; ++i) {
        const double x = 4.0 * coordinate(rng), z = 4.0 * coordinate(rng);
        a.rest[i] = Eigen::Vector3d(x + 64.0, -x - 64.0, z);
        a.modes[i] = Eigen::MatrixXd::Zero(3, 1);
        b.modes[i] = -Eigen::Vector3d(s, s, 0.0);
      }
      for (int i = 0; i < 3; ++i)
        b.rest[i] = (a.rest[0] + a.rest[1] + a.rest[2] + a.rest[i]) / 4.0 + Eigen::Vector3d(h, h, 0);
      INFO("bits " << bits << " trial " << trial);
      REQUIRE(static_cast<long double>(sscc::one_dimensional_radius(a, b)) <= truth);
    }
  }
}

TEST_CASE("triangle-pair radius: the Gram rounding pad covers the rounding of r-term dot products",
          "[certificates][rounding]") {
  const double u = std::numeric_limits<double>::epsilon() / 2;  // unit roundoff
  // The standard bound on an r-term dot product's rounding (Higham, Theorem 3.5) is
  // gamma_r = r u / (1 - r u) times the product of the norms; the pad must exceed it for every
  // r (a fixed pad stops covering it past a few hundred modes).
  for (int r : {1, 10, 64, 100, 256, 300, 1000, 10000, 100000, 1000000}) {
    INFO("r = " << r);
    CHECK(sscc::gram_rounding_pad(r) >= r * u / (1 - r * u));
  }
  // Observed: the rounding of Gram entries of random mode blocks, against long double sums.
  std::mt19937_64 rng(41);
  std::normal_distribution<double> normal;
  for (int r : {3, 30, 300, 3000}) {
    Eigen::Matrix<double, 6, Eigen::Dynamic> rows(6, r);
    for (int i = 0; i < 6; ++i) {
      for (int k = 0; k < r; ++k) rows(i, k) = normal(rng) + (i % 2 ? 10.0 : 0.0);  // some same-sign rows
    }
    const Eigen::Matrix<double, 6, 6> gram = rows.lazyProduct(rows.transpose());
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) {
        long double exact = 0.0L;
        for (int k = 0; k < r; ++k) exact += static_cast<long double>(rows(i, k)) * rows(j, k);
        const double scale = rows.row(i).norm() * rows.row(j).norm();
        CHECK(std::fabs(static_cast<double>(gram(i, j) - exact)) <= sscc::gram_rounding_pad(r) * scale);
      }
    }
  }
}

TEST_CASE("1D floor: never above the 1D bound, and the cut answers as the 1D bound does", "[certificates][floor]") {
  PairMaker m(29);
  int compared = 0, informative = 0, floor_answerable = 0, quick_answered = 0, quick_informative = 0,
      projected_answered = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int r = 1 + trial % 40;
    const auto [linear, quadratic] = m.fields(r, 1.0);
    // Neighbours (the pairs the precomputation meets most), far pairs, and pairs far from
    // the origin (large rest coordinates, where the rounding allowances matter).
    const double size = trial % 3 == 0 ? 0.05 : 0.3;
    const Eigen::Vector3d origin = trial % 5 == 0 ? m.point(1e6) : Eigen::Vector3d::Zero();
    std::array<Eigen::Vector3d, 3> a, b;
    const Eigen::Vector3d offset = m.point(trial % 2 == 0 ? 2.0 * size : 1.0);
    for (int i = 0; i < 3; ++i) {
      a[i] = origin + m.point(size);
      b[i] = origin + offset + m.point(size);
    }
    const bool smooth = trial % 4 != 0;
    const double noise = trial % 7 == 0 ? 0.0 : 0.01;
    ModalTriangle ta = m.with_modes(a, linear, quadratic, smooth, noise);
    ModalTriangle tb = m.with_modes(b, linear, quadratic, smooth, noise);
    // Some pairs with modes near the ends of the range, where squares underflow or overflow,
    // and of the projected floor's (floats below FLT_MIN, blocks near its largest).
    const double extreme[] = {1.0, 1e-160, 1e-155, 1e150, 1e154, 1e-41, 2e10};
    const OverflowAllowed overflow;  // the 1D bound's squares at 1e154
    for (int i = 0; i < 3; ++i) {
      ta.modes[i] *= extreme[trial % 11 < 7 ? trial % 11 : 0];
      tb.modes[i] *= extreme[trial % 11 < 7 ? trial % 11 : 0];
    }
    const sscc::TriangleSummary sa = sscc::summarize(ta), sb = sscc::summarize(tb);
    const double bound = sscc::one_dimensional_radius(ta, tb);
    const double floor = sscc::one_dimensional_radius_floor(ta, tb, sa, sb);
    INFO("trial " << trial << " r " << r << " 1D " << bound << " floor " << floor);
    REQUIRE(floor >= 0.0);
    REQUIRE(floor <= bound);
    // With a cut: the 1D bound itself below the floor's reach, at least the cut above it.
    // Cuts just below and above the floor (2^-42 relative), where the comparison with it
    // decides; the least positive normal one, where the quick floor answers whenever it reaches
    // it (at most the floor: it bounds every vertex pair's floor; strictly below it, the quick
    // floor answered, since the nine floors give the floor's own bits).
    // And cuts at and just below the 1D bound, where the projected floor (the vertex pairs'
    // norms without the bound's slacks, padded) decides: above the floor, it must not reach
    // above the bound.
    for (double cut :
         {std::numeric_limits<double>::min(), 0.5 * floor, floor * (1.0 - 0x1p-42), floor, floor * (1.0 + 0x1p-42),
          1.5 * floor + 1e-300, 0.99 * bound, bound * (1.0 - 0x1p-42), bound, 2.0 * bound}) {
      const double answer = sscc::one_dimensional_radius(ta, tb, sa, sb, cut);
      REQUIRE(answer <= bound);
      REQUIRE((answer >= cut) == (bound >= cut));
      if (!(bound >= cut)) REQUIRE(answer == bound);
      if (floor >= cut && floor > 0.0) REQUIRE(answer <= floor);  // 0: the floor abstains
      if (cut == 0.99 * bound && answer >= cut && answer > floor && answer < bound) ++projected_answered;
      if (floor >= cut && floor > 0.0 && cut == std::numeric_limits<double>::min()) {
        ++floor_answerable;
        if (answer < floor) ++quick_answered;
        if (answer < floor && answer >= 0.25 * floor) ++quick_informative;
      }
    }
    if (bound > 0.0) {
      ++compared;
      if (floor >= 0.25 * bound) ++informative;
    }
  }
  // Parallel triangles a unit apart along x, r = 1, where the triangle inequality the floor
  // uses is an equality: only the allowances keep it below, also where squares underflow
  // (s near 1e-160) or the 1D bound's overflow (s near 1e154), and where the projected floor's
  // floats are subnormal (1e-40, 1e-45) or its blocks near the largest it takes (1e11).
  for (double scale :
       {1.0, 1e-20, 1e-40, 1e-45, 1e-100, 1e-158, 1.5e-162, 1e-200, 1e-310, 1e11, 1e150, 5.5e153, 1e200, 1e300}) {
    ModalTriangle a, b;
    a.rest = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)};
    b.rest = {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(1, 0, 1)};
    const double along_a[] = {-1.0, 0.5, 0.5}, along_b[] = {2.0, 0.5, 0.5};
    for (int i = 0; i < 3; ++i) {
      a.modes[i] = Eigen::Vector3d(scale * along_a[i], 0.0, 0.0);
      b.modes[i] = Eigen::Vector3d(scale * along_b[i], 0.0, 0.0);
    }
    const OverflowAllowed overflow;  // the 1D bound's squares (and the summaries') from 5.5e153
    const double bound = sscc::one_dimensional_radius(a, b);
    const sscc::TriangleSummary sa = sscc::summarize(a), sb = sscc::summarize(b);
    const double floor = sscc::one_dimensional_radius_floor(a, b, sa, sb);
    INFO("scale " << scale << " 1D " << bound << " floor " << floor);
    REQUIRE(floor <= bound);
    if (scale == 1.0) REQUIRE(floor >= 0.999 * bound);
    // The quick and projected floors, where the triangle inequality is an equality too.
    for (double cut : {std::numeric_limits<double>::min(), 0.99 * bound, bound * (1.0 - 0x1p-42), bound}) {
      const double answer = sscc::one_dimensional_radius(a, b, sa, sb, cut);
      REQUIRE(answer <= bound);
      REQUIRE((answer >= cut) == (bound >= cut));
    }
  }
  // The same with 2048 modes, the first column L and the others s just under half a unit of
  // the float square 9 L^2 (the pair's difference is 3 times a column): each lane's sum keeps
  // 9 L^2 and drops every later square, about 6e-6 of the norm, which only the projected
  // floor's growth covers (its block allowance is 1e-6 of it). And blocks of 2^40 and more,
  // where the projected floor abstains and the floors alone answer.
  for (double scale : {1.0, 0x1p40, 1e13}) {
    const int r = 2048;
    const double large = scale, small = 0.9 * 0x1p-12 * scale;
    ModalTriangle a, b;
    a.rest = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)};
    b.rest = {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(1, 0, 1)};
    const double along_a[] = {-1.0, 0.5, 0.5}, along_b[] = {2.0, 0.5, 0.5};
    for (int i = 0; i < 3; ++i) {
      a.modes[i] = Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, r);
      b.modes[i] = Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, r);
      for (int c = 0; c < r; ++c) {
        a.modes[i](0, c) = along_a[i] * (c == 0 ? large : small);
        b.modes[i](0, c) = along_b[i] * (c == 0 ? large : small);
      }
    }
    const double bound = sscc::one_dimensional_radius(a, b);
    const sscc::TriangleSummary sa = sscc::summarize(a), sb = sscc::summarize(b);
    INFO("scale " << scale << " 1D " << bound);
    REQUIRE(sa.vertex_rows.cols() == (scale < 0x1p40 ? r : 0));
    for (double cut : {0.99 * bound, bound * (1.0 - 0x1p-42), bound}) {
      const double answer = sscc::one_dimensional_radius(a, b, sa, sb, cut);
      REQUIRE(answer <= bound);
      REQUIRE((answer >= cut) == (bound >= cut));
    }
  }
  // The floor earns its place only when it is close to the 1D bound on most pairs.
  REQUIRE(compared > 1000);
  REQUIRE(informative > compared / 2);
  // And the quick floor only when it answers in place of the nine floors, mostly within 4x
  // of them.
  INFO("quick floor answered " << quick_answered << " of " << floor_answerable << ", " << quick_informative
                               << " within 4x of the floor");
  REQUIRE(quick_answered > floor_answerable / 2);
  REQUIRE(quick_informative > quick_answered / 2);
  // The projected floor answers where the floors fall short of a cut near the bound.
  INFO("projected floor answered " << projected_answered << " of " << compared);
  REQUIRE(projected_answered > compared / 4);
}

TEST_CASE("group floor: never above the 1D bound of any pair of its two groups", "[certificates][floor][group_floor]") {
  PairMaker m(31);
  int pairs = 0, positive = 0, informative = 0, near_positive = 0;
  for (int trial = 0; trial < 800; ++trial) {
    const int r = 1 + trial % 30;
    const auto [linear, quadratic] = m.fields(r, trial % 3 == 0 ? 0.0 : 1.0);
    // Groups of up to four triangles (the hierarchy's leaves) and of sixteen, from touching to
    // many of their sizes apart, some far from the origin, with modes near the ends of the
    // range where the floor abstains or its margins matter.
    // Some groups of tiny coordinates, where the squares of the vertices' distances from their
    // centroids underflow (the floor abstains below 2^-400).
    const double units = trial % 17 == 3 ? 0x1p-537 : trial % 17 == 8 ? 0x1p-390 : 1.0;
    const double size = (trial % 2 == 0 ? 0.05 : 0.2) * units;
    const int count = trial % 5 == 1 ? 16 : 1 + trial % 4;
    const Eigen::Vector3d origin = trial % 5 == 0 ? m.point(1e6) : Eigen::Vector3d::Zero();
    const Eigen::Vector3d offset = m.point(size * (0.5 + 2.0 * (trial % 13)));
    const bool smooth = trial % 4 != 0;
    const double noise = trial % 7 == 0 ? 0.0 : 0.01;
    // And modes whose squares underflow (0x1p-537: near 2^-1074), where only the floor's
    // underflow terms keep it below the 1D bound.
    const double extreme[] = {1.0, 1.0, 1.0, 1e-150, 1e100, 1e-41, 0x1p-537, 1e-170};
    const double mode_scale = extreme[trial % 8];
    std::array<std::vector<ModalTriangle>, 2> triangles;
    std::array<std::vector<sscc::TriangleSummary>, 2> summaries;
    std::array<Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>, 2> reference;
    std::array<sscc::TriangleGroupSummary, 2> groups;
    for (int g = 0; g < 2; ++g) {
      reference[g] = Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>::Zero(3, r);
      for (int t = 0; t < count; ++t) {
        const Eigen::Vector3d centre = origin + (g == 1 ? offset : Eigen::Vector3d::Zero()) + m.point(size);
        std::array<Eigen::Vector3d, 3> rest;
        for (Eigen::Vector3d& p : rest) p = centre + m.point(0.5 * size);
        ModalTriangle x = m.with_modes(rest, linear, quadratic, smooth, noise);
        for (auto& block : x.modes) {
          block *= mode_scale;
          reference[g] += block / (3.0 * count);
        }
        triangles[g].push_back(x);
        summaries[g].push_back(sscc::summarize(x));
      }
      // Any reference is sound: the vertices' mean (the hierarchy's), or none at all.
      if (trial % 6 == 5) reference[g].setZero();
      groups[g] = sscc::summarize_group(triangles[g].data(), summaries[g].data(), count, reference[g]);
    }
    const double floor = sscc::group_pair_floor(groups[0], groups[1], reference[0], reference[1]);
    INFO("trial " << trial << " r " << r << " count " << count << " floor " << floor);
    REQUIRE(floor >= 0.0);
    double least = INFINITY;
    for (int s = 0; s < count; ++s) {
      for (int t = 0; t < count; ++t) {
        const ModalTriangle &a = triangles[0][s], &b = triangles[1][t];
        const double bound = sscc::one_dimensional_radius(a, b);
        least = std::min(least, bound);
        ++pairs;
        REQUIRE(floor <= bound);
        // The screening at a cut the floor reaches leaves the pair out (answers the cut or above).
        if (floor > 0.0) REQUIRE(sscc::one_dimensional_radius(a, b, summaries[0][s], summaries[1][t], floor) >= floor);
      }
    }
    if (floor > 0.0) {
      ++positive;
      if (offset.norm() < 4.0 * size) ++near_positive;
      if (floor >= 0.25 * least) ++informative;
    }
  }
  // Two single-triangle groups the review of the floor built: (a) coordinates near 2^-537,
  // where the squares of the vertices' distances from their centroids round to 0 and the
  // centroids' distance rounds up, while the triangles overlap along the axis (1D bound 0); (b)
  // one block's squares on the edge of rounding up to 2^-1074 in the 1D bound's sums, down to
  // 0 in the floor's Gram matrix.
  {
    const double h = 0x1p-537;
    ModalTriangle s, t;
    s.rest = {Eigen::Vector3d(0.7 * h, 0, 0), Eigen::Vector3d(-0.35 * h, 0.6 * h, 0),
              Eigen::Vector3d(-0.35 * h, -0.6 * h, 0)};
    t.rest = {Eigen::Vector3d(0.5 * h, 0, 0.3 * h), Eigen::Vector3d(1.55 * h, 0.6 * h, -0.15 * h),
              Eigen::Vector3d(1.55 * h, -0.6 * h, -0.15 * h)};
    for (int i = 0; i < 3; ++i) {
      s.modes[i] = Eigen::Matrix<double, 3, 2>::Zero();
      t.modes[i] = Eigen::Matrix<double, 3, 2>::Identity();
    }
    const sscc::TriangleSummary ss = sscc::summarize(s), st = sscc::summarize(t);
    const Eigen::Matrix<double, 3, 2, Eigen::RowMajor> rs = Eigen::Matrix<double, 3, 2>::Zero(),
                                                       rt = Eigen::Matrix<double, 3, 2>::Identity();
    const double floor =
        sscc::group_pair_floor(sscc::summarize_group(&s, &ss, 1, rs), sscc::summarize_group(&t, &st, 1, rt), rs, rt);
    CHECK(floor <= sscc::one_dimensional_radius(s, t));
  }
  {
    constexpr double u = std::numeric_limits<double>::epsilon();
    const double w = std::sqrt(2.0) * 0x1p-538 * (1.0 - 2.5 * u), v = 0x1p-537;
    ModalTriangle s, t;
    s.rest = {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(-0.5, 0.5, 0), Eigen::Vector3d(-0.5, -0.5, 0)};
    t.rest = {Eigen::Vector3d(4, 0, 0), Eigen::Vector3d(6, 0, 0.5), Eigen::Vector3d(6, 0, -0.5)};
    Eigen::Matrix<double, 3, 2> block = Eigen::Matrix<double, 3, 2>::Zero();
    block(0, 0) = w;
    block(0, 1) = v;
    for (int i = 0; i < 3; ++i) {
      s.modes[i] = Eigen::Matrix<double, 3, 2>::Zero();
      t.modes[i] = block;
    }
    const sscc::TriangleSummary ss = sscc::summarize(s), st = sscc::summarize(t);
    const Eigen::Matrix<double, 3, 2, Eigen::RowMajor> rs = Eigen::Matrix<double, 3, 2>::Zero(), rt = block;
    const double floor =
        sscc::group_pair_floor(sscc::summarize_group(&s, &ss, 1, rs), sscc::summarize_group(&t, &st, 1, rt), rs, rt);
    INFO("floor " << floor << " 1D " << sscc::one_dimensional_radius(s, t));
    CHECK(floor > 0.0);
    CHECK(floor <= sscc::one_dimensional_radius(s, t));
  }
  // Not vacuous: the floor is positive for most groups apart, near ones included, and is mostly
  // within a factor of four of their least 1D bound.
  INFO("pairs " << pairs << " positive " << positive << " near " << near_positive << " informative " << informative);
  CHECK(positive > 400);
  CHECK(near_positive > 12);
  CHECK(informative > positive / 2);
}

TEST_CASE("1D bound: the values of the column-by-column loop it replaced, across its column chunks",
          "[certificates][floor]") {
  // Recorded from the build before the columns went in chunks of 32 (0a4a45a), whose loop
  // took one column at a time: the precomputation's certificate files stay the same only
  // while these do. Inputs from a fixed 64-bit LCG (no library distribution), so every
  // standard library gives the same ones.
  struct Lcg {
    std::uint64_t state;
    double next() {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      return static_cast<double>(state >> 11) * 0x1p-53 * 2.0 - 1.0;
    }
  };
  const std::pair<int, double> recorded[] = {{1, 0x1.97b2c9ebce381p+4},
                                             {31, 0x1.2687eb203a54ap+2},
                                             {32, 0x1.dfaf22ad71a73p+1},
                                             {33, 0x1.3b72498bc5dc7p+2},
                                             {65, 0x1.8ed1e5629fd57p+1}};
  for (const auto& [r, value] : recorded) {
    Lcg lcg{static_cast<std::uint64_t>(r)};
    // Coordinates drawn z, y, x, one statement each (the order of the recording; a
    // constructor's arguments may be evaluated in any order).
    const auto point = [&lcg] {
      const double z = lcg.next();
      const double y = lcg.next();
      const double x = lcg.next();
      return Eigen::Vector3d(x, y, z);
    };
    ModalTriangle a, b;
    for (int i = 0; i < 3; ++i) {
      a.rest[i] = point();
      b.rest[i] = point() + Eigen::Vector3d(3.0, 0.0, 0.0);
      a.modes[i].resize(3, r);
      b.modes[i].resize(3, r);
      for (int c = 0; c < r; ++c) {
        for (int k = 0; k < 3; ++k) {
          a.modes[i](k, c) = 0.1 * lcg.next();
          b.modes[i](k, c) = 0.1 * lcg.next();
        }
      }
    }
    INFO("r " << r);
    REQUIRE(sscc::one_dimensional_radius(a, b) == value);
    REQUIRE(sscc::one_dimensional_radius(a, b, sscc::summarize(a), sscc::summarize(b)) == value);
  }
}
