#include "mesh/mesh_parsing.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace sscc::mesh_parsing {

bool LineReader::next(std::string& line, char comment) {
  while (std::getline(in_, line)) {
    ++line_;
    const auto first = line.find_first_not_of(" \t\r\n\f\v");
    if (first == std::string::npos) continue;  // blank, whatever the white space
    if (comment != 0 && line[first] == comment) continue;
    return true;
  }
  return false;
}

void LineReader::fail(const std::string& problem) const { throw MeshFileError(file_, line_, problem); }

double parse_coordinate(const std::string& token, const LineReader& reader) {
  char* end = nullptr;
  const double value = std::strtod(token.c_str(), &end);
  if (end == token.c_str() || *end != '\0') reader.fail("'" + token + "' is not a number");
  // Overflow gives infinity; underflow (ERANGE with a subnormal or zero) is the correctly
  // rounded value of the text, which write_off writes for subnormal coordinates: accepted.
  if (!std::isfinite(value)) reader.fail("coordinate '" + token + "' is not a finite double");
  return value;
}

long parse_integer(const std::string& token, const LineReader& reader) {
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(token.c_str(), &end, 10);
  if (end == token.c_str() || *end != '\0' || errno == ERANGE) {
    reader.fail("'" + token + "' is not an integer");
  }
  return value;
}

int parse_index(const std::string& token, const LineReader& reader) {
  const long value = parse_integer(token, reader);
  if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max()) {
    reader.fail("index '" + token + "' is out of range");
  }
  return static_cast<int>(value);
}

std::vector<std::string> split(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> tokens;
  std::string token;
  while (in >> token) tokens.push_back(token);
  return tokens;
}

}  // namespace sscc::mesh_parsing
