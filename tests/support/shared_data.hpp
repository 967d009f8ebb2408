// Data beside the repository (../shared/data), which a checkout alone does not have. A test
// that needs it asks shared_data_present(): when the data is absent the test is skipped and
// says so ("SKIPPED: ..."; ctest reports the test as skipped, see tests/CMakeLists.txt), or
// fails when SSCC_REQUIRE_SHARED_DATA is set (on machines that are meant to hold the data).
#pragma once

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace sscc::test {

/// Whether `path` exists; when it does not, reports the skip (or fails, see above).
inline bool shared_data_present(const std::filesystem::path& path, const std::string& what) {
  if (std::filesystem::exists(path)) return true;
  if (std::getenv("SSCC_REQUIRE_SHARED_DATA") != nullptr) {
    FAIL(what << " (" << path.string() << ") is absent, and SSCC_REQUIRE_SHARED_DATA is set");
  }
  WARN("SKIPPED: " << what << " (" << path.string() << ") is not beside the repository");
  return false;
}

}  // namespace sscc::test
