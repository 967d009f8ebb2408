// What the format readers share: a line reader that counts lines, number parsing with
// errors that name the file and line, and the faces-to-triangles step.
#pragma once

#include <Eigen/Core>

#include <istream>
#include <string>
#include <vector>

#include "sscc/mesh/mesh_io.hpp"

namespace sscc::mesh_parsing {

/// Polygons as read (vertex indices, 0-based), before triangulation.
struct RawMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<int>> faces;
  std::vector<int> face_lines;  ///< the line each face came from, for errors
};

class LineReader {
 public:
  LineReader(std::istream& in, std::string file) : in_(in), file_(std::move(file)) {}
  /// The next line that is neither blank (white space only) nor a comment starting with
  /// `comment` (0: none), or false at the end of the file. A returned line has a token.
  bool next(std::string& line, char comment);
  int line_number() const { return line_; }
  const std::string& file() const { return file_; }
  [[noreturn]] void fail(const std::string& problem) const;
  std::istream& stream() { return in_; }

 private:
  std::istream& in_;
  std::string file_;
  int line_ = 0;
};

double parse_coordinate(const std::string& token, const LineReader& reader);
long parse_integer(const std::string& token, const LineReader& reader);
/// An integer that fits in an int (vertex indices, list lengths).
int parse_index(const std::string& token, const LineReader& reader);
std::vector<std::string> split(const std::string& line);

RawMesh read_off(LineReader& reader);
RawMesh read_obj(LineReader& reader);
RawMesh read_ply(LineReader& reader);

}  // namespace sscc::mesh_parsing
