#include <catch2/catch.hpp>

#include "support/named_cases.hpp"

using sscc::validation::run_reference;

TEST_CASE("the exact reference answers the named cases", "[exact][reference]") {
  for (const auto& named : sscc::test::named_cases()) {
    INFO(named.name);
    auto contact = run_reference(named.query);
    REQUIRE(contact.has_value() == !named.expected_toi.empty());
    if (contact) CHECK(sscc::exact::compare(mpq_class(named.expected_toi), *contact) == 0);
  }
}
