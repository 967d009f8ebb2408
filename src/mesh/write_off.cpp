#include "sscc/mesh/write_off.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace sscc {

void write_off(const std::string& path, const TriangleMesh& mesh) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot write the file");
  out << "OFF\n" << mesh.vertex_count() << ' ' << mesh.triangle_count() << " 0\n";
  char line[128];
  for (const Eigen::Vector3d& p : mesh.vertices()) {
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", p.x(), p.y(), p.z());
    out << line;
  }
  for (const Triangle& t : mesh.triangles()) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  out.flush();
  if (!out) throw std::runtime_error(path + ": writing failed (disk full?)");
}

}  // namespace sscc
