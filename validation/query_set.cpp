#include "query_set.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace sscc::validation {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const fs::path& file, int line, const std::string& problem) {
  throw std::runtime_error(file.string() + ":" + std::to_string(line) + ": " + problem);
}

double exact_double(const std::string& num, const std::string& den, const fs::path& file, int line) {
  mpq_class value;
  if (value.set_str(num + "/" + den, 10) != 0) fail(file, line, "not a rational: " + num + "/" + den);
  if (sgn(value.get_den()) == 0) fail(file, line, "zero denominator");
  value.canonicalize();
  const double d = value.get_d();
  if (mpq_class(d) != value) fail(file, line, "coordinate is not exactly a double");
  return d;
}

void read_file(const fs::path& path, QueryFile& out) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  std::string text;
  int line_number = 0;
  LabelledQuery current;
  int row = 0;
  while (std::getline(in, text)) {
    ++line_number;
    if (text.empty() || text == "\r") continue;
    std::stringstream fields(text);
    std::string f[7];
    int n = 0;
    while (n < 7 && std::getline(fields, f[n], ',')) ++n;
    std::string extra;
    if (n != 7 || std::getline(fields, extra, ',')) fail(path, line_number, "expected 7 columns");
    for (int k = 0; k < 3; ++k) {
      current.query.points[row][k] = exact_double(f[2 * k], f[2 * k + 1], path, line_number);
    }
    const bool truth = std::stoi(f[6]) != 0;
    if (row == 0) current.truth = truth;
    if (truth != current.truth) fail(path, line_number, "truth differs within one query");
    if (++row == 8) {
      current.query.kind = out.kind;
      out.queries.push_back(current);
      row = 0;
    }
  }
  if (row != 0) fail(path, line_number, "incomplete query (rows not a multiple of 8)");
}

}  // namespace

std::vector<QueryFile> read_query_set(const std::string& root) {
  if (!fs::is_directory(root)) throw std::runtime_error(root + ": not a directory");
  std::vector<QueryFile> files;
  std::vector<fs::path> scenes;
  for (const auto& entry : fs::directory_iterator(root)) {
    if (entry.is_directory()) scenes.push_back(entry.path());
  }
  std::sort(scenes.begin(), scenes.end());
  for (const fs::path& scene : scenes) {
    for (Kind kind : {Kind::kVertexFace, Kind::kEdgeEdge}) {
      const fs::path dir = scene / to_string(kind);
      if (!fs::is_directory(dir)) continue;
      std::vector<fs::path> csvs;
      for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() == ".csv") csvs.push_back(entry.path());
      }
      std::sort(csvs.begin(), csvs.end());
      QueryFile file{scene.filename().string(), kind, {}};
      for (const fs::path& csv : csvs) read_file(csv, file);
      if (!file.queries.empty()) files.push_back(std::move(file));
    }
  }
  if (files.empty()) throw std::runtime_error(root + ": no query files found");
  return files;
}

std::string default_query_set_path(const std::string& source_dir) {
  const fs::path p = fs::path(source_dir) / ".." / "shared" / "data" / "ccd-sample-queries";
  return fs::is_directory(p) ? fs::weakly_canonical(p).string() : std::string();
}

}  // namespace sscc::validation
