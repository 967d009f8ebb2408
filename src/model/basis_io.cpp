#include "sscc/model/basis_io.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "common/finite.hpp"

namespace sscc {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
  throw std::runtime_error(path + ": " + problem);
}

void require_finite(const Eigen::MatrixXd& m, const std::string& path) {
  if (!all_finite(m)) fail(path, "contains a NaN or infinity");
}

}  // namespace

Eigen::MatrixXd read_vega_basis(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) fail(path, "cannot open the file");
  const std::streamoff size = in.tellg();
  in.seekg(0);
  std::int32_t rows = 0;
  std::int32_t cols = 0;
  if (!in.read(reinterpret_cast<char*>(&rows), 4) || !in.read(reinterpret_cast<char*>(&cols), 4)) {
    fail(path, "too short for a .U header (two 4-byte integers)");
  }
  if (rows <= 0 || cols <= 0) {
    fail(path, "not a .U basis: header says " + std::to_string(rows) + " x " + std::to_string(cols));
  }
  const std::uint64_t entries = static_cast<std::uint64_t>(rows) * static_cast<std::uint64_t>(cols);
  if (size < 8 || entries != static_cast<std::uint64_t>(size - 8) / 8 || (size - 8) % 8 != 0) {
    fail(path, "size " + std::to_string(size) + " bytes does not match its " + std::to_string(rows) + " x " +
                   std::to_string(cols) + " header (" + std::to_string(8 + 8 * entries) + " bytes)");
  }
  Eigen::MatrixXd m(rows, cols);  // column-major, like the file
  in.read(reinterpret_cast<char*>(m.data()), 8 * static_cast<std::streamoff>(rows) * cols);
  require_finite(m, path);
  return m;
}

void write_vega_basis(const std::string& path, const Eigen::MatrixXd& basis) {
  std::ofstream out(path, std::ios::binary);
  if (!out) fail(path, "cannot write the file");
  const std::int32_t rows = static_cast<std::int32_t>(basis.rows());
  const std::int32_t cols = static_cast<std::int32_t>(basis.cols());
  out.write(reinterpret_cast<const char*>(&rows), 4);
  out.write(reinterpret_cast<const char*>(&cols), 4);
  out.write(reinterpret_cast<const char*>(basis.data()), 8 * basis.size());
  if (!out) fail(path, "write failed");
}

Eigen::MatrixXd read_text_matrix(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail(path, "cannot open the file");
  std::vector<std::vector<double>> rows;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream fields(line);
    std::vector<double> row;
    std::string token;
    while (fields >> token) {
      char* end = nullptr;
      const double v = std::strtod(token.c_str(), &end);
      if (end == token.c_str() || *end != '\0') {
        fail(path, "line " + std::to_string(number) + ": '" + token + "' is not a number");
      }
      row.push_back(v);
    }
    if (row.empty()) continue;
    if (!rows.empty() && row.size() != rows.front().size()) {
      fail(path, "line " + std::to_string(number) + " has " + std::to_string(row.size()) + " numbers, the first row " +
                     std::to_string(rows.front().size()));
    }
    rows.push_back(std::move(row));
  }
  if (rows.empty()) fail(path, "no numbers: not a matrix");
  Eigen::MatrixXd m(rows.size(), rows.front().size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (std::size_t j = 0; j < rows[i].size(); ++j) m(i, j) = rows[i][j];
  }
  require_finite(m, path);
  return m;
}

Eigen::VectorXd read_weights(const std::string& path) {
  const Eigen::MatrixXd m = read_text_matrix(path);
  Eigen::VectorXd w = m.reshaped<Eigen::RowMajor>();
  return w;
}

void write_weights(const std::string& path, const Eigen::VectorXd& weights) {
  std::ofstream out(path);
  if (!out) fail(path, "cannot write the file");
  out.precision(std::numeric_limits<double>::max_digits10);
  for (long i = 0; i < weights.size(); ++i) out << weights[i] << '\n';
  if (!out) fail(path, "write failed");
}

Eigen::MatrixXd read_basis(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  if (ext == "U" || ext == "u") return read_vega_basis(path);
  return read_text_matrix(path);
}

}  // namespace sscc
