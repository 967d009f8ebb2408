// OBJ: "v x y z [w]" and "f a b c ..." where each corner is "i", "i/t", "i//n" or "i/t/n",
// 1-based, or negative (relative to the vertices read so far). Other statements (normals,
// texture coordinates, groups, materials, lines) are ignored.
#include <limits>

#include "mesh/mesh_parsing.hpp"

namespace sscc::mesh_parsing {

RawMesh read_obj(LineReader& reader) {
  RawMesh mesh;
  std::string line;
  while (reader.next(line, '#')) {
    const std::vector<std::string> tokens = split(line);
    if (tokens[0] == "v") {
      if (tokens.size() < 4) reader.fail("a vertex needs three coordinates");
      mesh.vertices.emplace_back(parse_coordinate(tokens[1], reader), parse_coordinate(tokens[2], reader),
                                 parse_coordinate(tokens[3], reader));
    } else if (tokens[0] == "f") {
      if (tokens.size() < 4) reader.fail("a face needs at least three vertices");
      std::vector<int> face;
      for (std::size_t i = 1; i < tokens.size(); ++i) {
        const long index = parse_index(tokens[i].substr(0, tokens[i].find('/')), reader);
        if (index == 0) reader.fail("OBJ vertex indices start at 1 (found 0)");
        const long resolved = index > 0 ? index - 1 : static_cast<long>(mesh.vertices.size()) + index;
        if (resolved < 0 || resolved > std::numeric_limits<int>::max()) reader.fail("vertex index out of range");
        face.push_back(static_cast<int>(resolved));
      }
      mesh.faces.push_back(std::move(face));
      mesh.face_lines.push_back(reader.line_number());
    }
  }
  if (mesh.vertices.empty()) reader.fail("no vertices ('v' lines) found");
  return mesh;
}

}  // namespace sscc::mesh_parsing
