// Reader for the public handcrafted CCD query set (Wang et al. 2021), format in its
// FORMAT.md: CSV rows "x_num,x_den,y_num,y_den,z_num,z_den,truth", 8 rows a query.
#pragma once

#include <string>
#include <vector>

#include "query.hpp"

namespace sscc::validation {

struct LabelledQuery {
  Query query;
  bool truth = false;
};

struct QueryFile {
  std::string scene;  ///< e.g. "erleben-spikes"
  Kind kind;
  std::vector<LabelledQuery> queries;
};

/// All query files under `root` (<scene>/<vertex-face|edge-edge>/*.csv), sorted by scene.
/// Throws std::runtime_error naming the file and line on malformed input, and when `root`
/// holds no query files.
std::vector<QueryFile> read_query_set(const std::string& root);

/// The query-set folder beside the repository (../shared/data/ccd-sample-queries), or ""
/// when it is absent.
std::string default_query_set_path(const std::string& source_dir);

}  // namespace sscc::validation
