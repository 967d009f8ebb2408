// Reading triangle meshes from OFF, OBJ and PLY (ASCII or binary) files.
//
// Faces with more than three vertices are fan-triangulated (and counted in the report);
// zero-area and duplicate triangles are kept (the kernels handle them, and duplicates share
// vertices, so they are never reported as colliding) and listed in the report. A file that
// is not a mesh gets a MeshFileError naming the file, the line and the problem.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "sscc/mesh/triangle_mesh.hpp"

namespace sscc {

class MeshFileError : public std::runtime_error {
 public:
  /// line 0: the problem is not tied to one line.
  MeshFileError(const std::string& file, int line, const std::string& problem);
};

struct MeshReadReport {
  int polygons_triangulated = 0;                         ///< faces of 4+ vertices
  std::vector<int> zero_area_triangles;                  ///< triangle indices
  std::vector<std::pair<int, int>> duplicate_triangles;  ///< (first, repeat), same vertex set
  /// One line for people, e.g. "2 polygons triangulated, 1 zero-area triangle".
  std::string summary() const;
};

/// Reads a mesh; the format follows the extension (.off, .obj, .ply, any case).
TriangleMesh read_mesh(const std::string& path, MeshReadReport* report = nullptr);

}  // namespace sscc
