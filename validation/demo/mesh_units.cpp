#include "demo/mesh_units.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sscc::validation {

double scale_factor(const std::string& option, const TriangleMesh& mesh, double reference_diagonal) {
  if (option == "auto") {
    const double diagonal = mesh.bounding_box_diagonal();
    if (!(diagonal > 0.0)) throw std::invalid_argument("--scale auto: the mesh has no extent");
    return reference_diagonal / diagonal;
  }
  std::size_t used = 0;
  double factor = 0.0;
  try {
    factor = std::stod(option, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  // isfinite before any ordered comparison: comparing a NaN raises the invalid-operation flag.
  if (used == 0 || used != option.size() || !std::isfinite(factor) || factor <= 0.0) {
    throw std::invalid_argument("--scale expects auto or a positive number, got '" + option + "'");
  }
  return factor;
}

TriangleMesh scaled(const TriangleMesh& mesh, double factor) {
  std::vector<Eigen::Vector3d> vertices = mesh.vertices();
  for (Eigen::Vector3d& p : vertices) p *= factor;
  return TriangleMesh(std::move(vertices), mesh.triangles());
}

std::string size_warning(const TriangleMesh& mesh, double reference_diagonal) {
  const double ratio = mesh.bounding_box_diagonal() / reference_diagonal;
  if (ratio <= kSizeWarningFactor && ratio >= 1.0 / kSizeWarningFactor) return "";
  std::ostringstream text;
  text << "warning: the mesh is " << mesh.bounding_box_diagonal() << " m across (bounding-box diagonal), " << ratio
       << " times the bunny the scene's material and impulses are made for; if it was modelled in other units, "
          "pass --scale auto (bunny-sized) or --scale S";
  return text.str();
}

}  // namespace sscc::validation
