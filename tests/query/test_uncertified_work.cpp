#include <catch2/catch.hpp>

#include <limits>

#include "certificates/certificate_fixtures.hpp"
#include "query/uncertified_work.hpp"

TEST_CASE("uncertified work: none below every radius, every leaf past all of them, growing in between", "[query]") {
  const auto m = sscc::test::certified_sphere();
  const sscc::detail::UncertifiedWork work(m->bvh, m->certificates);
  double smallest = std::numeric_limits<double>::infinity();
  for (int n = 0; n < m->certificates.node_count(); ++n) smallest = std::min(smallest, m->certificates.node_radius(n));
  for (const sscc::PairCertificate& pair : m->certificates.pair_certificates())
    smallest = std::min(smallest, pair.radius);
  REQUIRE(smallest > 0.0);
  CHECK(work.fraction(0.5 * smallest) == 0.0);
  // Past every certificate every leaf's own pairs are traversed: at least the whole mesh.
  CHECK(work.fraction(std::numeric_limits<double>::max()) >= 1.0);
  double previous = 0.0;
  const double global = m->certificates.global_radius();
  for (int k = 0; k <= 100; ++k) {
    const double fraction = work.fraction(global * k / 50.0);
    CHECK(fraction >= previous);
    previous = fraction;
  }
}
