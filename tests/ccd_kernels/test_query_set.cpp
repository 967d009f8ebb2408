#include <catch2/catch.hpp>

#include "agreement.hpp"
#include "query_set.hpp"
#include "support/shared_data.hpp"

TEST_CASE("the public handcrafted query set: no false negatives, no false positives", "[kernels][query-set]") {
  const auto beside = std::filesystem::path(SSCC_SOURCE_DIR) / ".." / "shared" / "data" / "ccd-sample-queries";
  if (!sscc::test::shared_data_present(beside, "the public CCD query set")) return;
  const std::string path = sscc::validation::default_query_set_path(SSCC_SOURCE_DIR);
  int queries = 0;
  for (const auto& file : sscc::validation::read_query_set(path)) {
    for (const auto& labelled : file.queries) {
      INFO(file.scene << " " << sscc::validation::to_string(file.kind) << " query " << queries);
      CHECK(sscc::validation::run_reference(labelled.query).has_value() == labelled.truth);
      CHECK(sscc::validation::run_kernel(labelled.query).hit == labelled.truth);
      CHECK(sscc::validation::disagreement_with_reference(labelled.query) == "");
      ++queries;
    }
  }
  CHECK(queries == 3085 + 4194);
}
