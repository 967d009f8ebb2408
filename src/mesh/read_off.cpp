// OFF: "OFF", then "vertices faces edges", one vertex per line, one face per line as
// "n i_1 ... i_n" (0-based). Comments start with '#'.
#include "mesh/mesh_parsing.hpp"

namespace sscc::mesh_parsing {

RawMesh read_off(LineReader& reader) {
  std::string line;
  if (!reader.next(line, '#')) reader.fail("empty file");
  std::vector<std::string> tokens = split(line);
  if (tokens[0] != "OFF") reader.fail("expected the header 'OFF', found '" + tokens[0] + "'");
  tokens.erase(tokens.begin());
  if (tokens.empty()) {  // the counts on their own line
    if (!reader.next(line, '#')) reader.fail("missing the counts line");
    tokens = split(line);
  }
  if (tokens.size() < 2) reader.fail("expected 'vertices faces [edges]'");
  const long vertex_count = parse_integer(tokens[0], reader);
  const long face_count = parse_integer(tokens[1], reader);
  if (vertex_count < 0 || face_count < 0) reader.fail("negative count");
  RawMesh mesh;
  for (long v = 0; v < vertex_count; ++v) {
    if (!reader.next(line, '#')) {
      reader.fail("file ends after " + std::to_string(v) + " of " + std::to_string(vertex_count) + " vertices");
    }
    tokens = split(line);
    if (tokens.size() < 3) reader.fail("a vertex needs three coordinates");
    mesh.vertices.emplace_back(parse_coordinate(tokens[0], reader), parse_coordinate(tokens[1], reader),
                               parse_coordinate(tokens[2], reader));
  }
  for (long f = 0; f < face_count; ++f) {
    if (!reader.next(line, '#')) {
      reader.fail("file ends after " + std::to_string(f) + " of " + std::to_string(face_count) + " faces");
    }
    tokens = split(line);
    const int n = parse_index(tokens[0], reader);
    if (n < 3) reader.fail("a face needs at least three vertices, this one has " + std::to_string(n));
    if (tokens.size() - 1 < static_cast<std::size_t>(n)) reader.fail("face lists fewer indices than its count");
    std::vector<int> face;
    for (int i = 1; i <= n; ++i) face.push_back(parse_index(tokens[i], reader));
    mesh.faces.push_back(std::move(face));
    mesh.face_lines.push_back(reader.line_number());
  }
  return mesh;
}

}  // namespace sscc::mesh_parsing
