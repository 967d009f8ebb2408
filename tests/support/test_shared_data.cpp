// The switch between skipping and failing a test whose data beside the repository is absent
// (shared_data.hpp). Hidden: run only by the CTest tests shared_data_skipped and
// shared_data_required (tests/CMakeLists.txt), once without SSCC_REQUIRE_SHARED_DATA (the probe
// says SKIPPED) and once with it (the probe fails, naming the variable).
#include <catch2/catch.hpp>

#include <filesystem>

#include "support/shared_data.hpp"

TEST_CASE("shared data probe: a path that is never there", "[.shared_data_probe]") {
  const auto absent = std::filesystem::path(SSCC_SOURCE_DIR) / "no such directory" / "data";
  CHECK_FALSE(sscc::test::shared_data_present(absent, "the probe's absent data"));
}
