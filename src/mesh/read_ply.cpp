// PLY, ASCII or binary (either byte order): the "vertex" element's x, y, z and the "face"
// element's vertex_indices (or vertex_index) list; other elements and properties are read
// past and ignored.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>

#include "common/finite.hpp"
#include "mesh/mesh_parsing.hpp"

namespace sscc::mesh_parsing {

namespace {

enum class Format { kAscii, kLittleEndian, kBigEndian };

struct Property {
  std::string name;
  std::string type;        // value type (for lists: the item type)
  std::string count_type;  // lists only
  bool is_list = false;
};

struct Element {
  std::string name;
  long count = 0;
  std::vector<Property> properties;
};

int type_size(const std::string& type, const LineReader& reader) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  reader.fail("unknown PLY property type '" + type + "'");
}

/// Reads the values of one element record, in property order, as doubles (lists inline).
class ValueSource {
 public:
  ValueSource(LineReader& reader, Format format) : reader_(reader), format_(format) {}

  double read(const std::string& type) {
    if (format_ == Format::kAscii) {
      while (tokens_.empty()) {
        std::string line;
        if (!reader_.next(line, 0)) reader_.fail("file ends inside the data");
        for (auto& t : split(line)) tokens_.push_back(t);
        std::reverse(tokens_.begin(), tokens_.end());
      }
      const std::string token = tokens_.back();
      tokens_.pop_back();
      return parse_coordinate(token, reader_);
    }
    const int size = type_size(type, reader_);
    unsigned char bytes[8];
    if (!reader_.stream().read(reinterpret_cast<char*>(bytes), size)) {
      reader_.fail("binary data ends early");
    }
    const bool little_host = [] {
      const std::uint16_t one = 1;
      unsigned char first;
      std::memcpy(&first, &one, 1);
      return first == 1;
    }();
    if ((format_ == Format::kLittleEndian) != little_host) std::reverse(bytes, bytes + size);
    return decode(type, bytes);
  }

 private:
  static double decode(const std::string& type, const unsigned char* b) {
    const auto get = [b](auto value) {
      std::memcpy(&value, b, sizeof value);
      return static_cast<double>(value);
    };
    if (type == "char" || type == "int8") return get(std::int8_t{});
    if (type == "uchar" || type == "uint8") return get(std::uint8_t{});
    if (type == "short" || type == "int16") return get(std::int16_t{});
    if (type == "ushort" || type == "uint16") return get(std::uint16_t{});
    if (type == "int" || type == "int32") return get(std::int32_t{});
    if (type == "uint" || type == "uint32") return get(std::uint32_t{});
    if (type == "float" || type == "float32") return get(float{});
    return get(double{});
  }

  LineReader& reader_;
  Format format_;
  std::vector<std::string> tokens_;
};

}  // namespace

RawMesh read_ply(LineReader& reader) {
  std::string line;
  if (!reader.next(line, 0) || split(line) != std::vector<std::string>{"ply"}) {
    reader.fail("expected the header 'ply'");
  }
  Format format = Format::kAscii;
  std::vector<Element> elements;
  while (true) {
    if (!reader.next(line, 0)) reader.fail("file ends inside the header");
    const std::vector<std::string> t = split(line);
    if (t[0] == "end_header") break;
    if (t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "format") {
      if (t.size() < 2) reader.fail("incomplete format line");
      if (t[1] == "ascii")
        format = Format::kAscii;
      else if (t[1] == "binary_little_endian")
        format = Format::kLittleEndian;
      else if (t[1] == "binary_big_endian")
        format = Format::kBigEndian;
      else
        reader.fail("unknown PLY format '" + t[1] + "'");
    } else if (t[0] == "element") {
      if (t.size() != 3) reader.fail("expected 'element NAME COUNT'");
      elements.push_back({t[1], parse_integer(t[2], reader), {}});
      if (elements.back().count < 0) reader.fail("negative element count");
    } else if (t[0] == "property") {
      if (elements.empty()) reader.fail("property before any element");
      Property p;
      if (t.size() == 5 && t[1] == "list") {
        p = {t[4], t[3], t[2], true};
        type_size(t[2], reader);
      } else if (t.size() == 3) {
        p = {t[2], t[1], "", false};
      } else {
        reader.fail("malformed property line");
      }
      type_size(p.type, reader);
      elements.back().properties.push_back(p);
    } else {
      reader.fail("unknown header line '" + t[0] + "'");
    }
  }
  RawMesh mesh;
  ValueSource values(reader, format);
  for (const Element& e : elements) {
    if (e.properties.empty()) continue;  // nothing to read, however many there are
    for (long i = 0; i < e.count; ++i) {
      Eigen::Vector3d position = Eigen::Vector3d::Zero();
      for (const Property& p : e.properties) {
        if (p.is_list) {
          const double n = values.read(p.count_type);
          if (!(n >= 0 && n <= std::numeric_limits<int>::max()) || n != std::floor(n)) {
            reader.fail("bad list length");
          }
          std::vector<int> items;
          for (long k = 0; k < static_cast<long>(n); ++k) {
            const double item = values.read(p.type);
            if (item != std::floor(item) || std::fabs(item) > std::numeric_limits<int>::max()) {
              reader.fail("list item is not an index");
            }
            items.push_back(static_cast<int>(item));
          }
          if (e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index")) {
            if (items.size() < 3) reader.fail("a face needs at least three vertices");
            mesh.faces.push_back(std::move(items));
            mesh.face_lines.push_back(reader.line_number());
          }
          continue;
        }
        const double v = values.read(p.type);
        if (e.name == "vertex") {
          if (p.name == "x") position[0] = v;
          if (p.name == "y") position[1] = v;
          if (p.name == "z") position[2] = v;
        }
      }
      if (e.name == "vertex") {
        if (!all_finite(position)) reader.fail("vertex " + std::to_string(i) + " is not finite");
        mesh.vertices.push_back(position);
      }
    }
  }
  if (mesh.vertices.empty()) reader.fail("no 'vertex' element with x, y, z");
  return mesh;
}

}  // namespace sscc::mesh_parsing
