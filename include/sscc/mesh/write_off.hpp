// Writing a triangle mesh as an OFF file (the format read_mesh reads).
//
// Coordinates are written with 17 significant digits, so reading the file back gives the
// same doubles bit for bit: a mean shape written here and read again is the same rest mesh,
// and certificates tied to its hash (certificates.hpp) still belong to it.
#pragma once

#include <string>

#include "sscc/mesh/triangle_mesh.hpp"

namespace sscc {

/// Throws std::runtime_error naming the file when it cannot be written.
void write_off(const std::string& path, const TriangleMesh& mesh);

}  // namespace sscc
