#include "sscc/mesh/mesh_io.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>

#include <Eigen/Geometry>

#include "mesh/mesh_parsing.hpp"

namespace sscc {

MeshFileError::MeshFileError(const std::string& file, int line, const std::string& problem)
    : std::runtime_error(file + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + problem) {}

std::string MeshReadReport::summary() const {
  const auto count = [](std::size_t n, const char* what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
  };
  return count(polygons_triangulated, "polygon") + " triangulated, " +
         count(zero_area_triangles.size(), "zero-area triangle") + ", " +
         count(duplicate_triangles.size(), "duplicate triangle");
}

namespace {

/// Whether the corners are collinear (a zero cross product), computed on the corners scaled
/// by one power of two so that the largest coordinate is below 1: the differences and
/// products then cannot overflow, whatever finite coordinates a file holds.
bool has_zero_area(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const double largest = std::max({a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff(), c.cwiseAbs().maxCoeff()});
  if (largest == 0.0) return true;
  const int shift = -std::ilogb(largest) - 1;
  const auto scaled = [shift](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(std::ldexp(x.x(), shift), std::ldexp(x.y(), shift), std::ldexp(x.z(), shift));
  };
  const Eigen::Vector3d p = scaled(a);
  return (scaled(b) - p).cross(scaled(c) - p) == Eigen::Vector3d::Zero();
}

std::string lower_extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

/// Whether a polygon lists a vertex twice: sorted copy, O(k log k) in its size k (a
/// pairwise check is quadratic, seconds for one 100k-vertex polygon).
bool repeats_a_vertex(const std::vector<int>& face) {
  std::vector<int> sorted = face;
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
}

}  // namespace

TriangleMesh read_mesh(const std::string& path, MeshReadReport* report) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshFileError(path, 0, "cannot open the file");
  mesh_parsing::LineReader reader(in, path);
  const std::string ext = lower_extension(path);
  mesh_parsing::RawMesh raw;
  if (ext == "off") {
    raw = mesh_parsing::read_off(reader);
  } else if (ext == "obj") {
    raw = mesh_parsing::read_obj(reader);
  } else if (ext == "ply") {
    raw = mesh_parsing::read_ply(reader);
  } else {
    throw MeshFileError(path, 0,
                        (ext.empty() ? std::string("no file extension") : "unknown mesh format '." + ext + "'") +
                            " (expected .off, .obj or .ply)");
  }
  MeshReadReport local;
  MeshReadReport& r = report ? *report : local;
  r = {};
  std::vector<Triangle> triangles;
  const int n = static_cast<int>(raw.vertices.size());
  for (std::size_t f = 0; f < raw.faces.size(); ++f) {
    const std::vector<int>& face = raw.faces[f];
    for (int v : face) {
      if (v < 0 || v >= n) {
        throw MeshFileError(path, raw.face_lines[f],
                            "vertex index " + std::to_string(v) + " outside [0, " + std::to_string(n) + ")");
      }
    }
    if (repeats_a_vertex(face)) throw MeshFileError(path, raw.face_lines[f], "a face repeats a vertex");
    if (face.size() > 3) ++r.polygons_triangulated;
    for (std::size_t i = 1; i + 1 < face.size(); ++i) triangles.push_back({face[0], face[i], face[i + 1]});
  }
  if (triangles.empty()) throw MeshFileError(path, 0, "no faces: not a surface mesh");
  std::map<std::array<int, 3>, int> seen;
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    const Triangle& tri = triangles[t];
    if (has_zero_area(raw.vertices[tri[0]], raw.vertices[tri[1]], raw.vertices[tri[2]])) {
      r.zero_area_triangles.push_back(t);
    }
    std::array<int, 3> key = tri;
    std::sort(key.begin(), key.end());
    const auto [it, inserted] = seen.emplace(key, t);
    if (!inserted) r.duplicate_triangles.push_back({it->second, t});
  }
  return TriangleMesh(std::move(raw.vertices), std::move(triangles));
}

}  // namespace sscc
