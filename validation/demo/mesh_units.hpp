// Units of a demo mesh. The demo's materials, gravity and impulses are in SI units and
// sized for the default bunny (data/bunny15k.off); a mesh modelled in other units (a
// 229-unit-wide model read as 229 metres) makes another experiment altogether: a huge
// rubber object whose every step collides. `--scale auto|S` rescales the rest positions
// before anything is computed from them, and a mesh far from the bunny's size is warned
// about.
#pragma once

#include <string>

#include "sscc/mesh/triangle_mesh.hpp"

namespace sscc::validation {

/// A mesh whose bounding-box diagonal is more than this factor larger or smaller than the
/// default bunny's is warned about: the scene's material and impulses were chosen for
/// objects of about the bunny's size (a factor 10 in size is a factor 1000 in mass, and the
/// modes' frequencies move by 10), so the run stops looking like the scene it is named for.
inline constexpr double kSizeWarningFactor = 10.0;

/// The factor --scale asks for: "auto" (reference_diagonal over the mesh's bounding-box
/// diagonal) or a positive number. Throws std::invalid_argument for anything else.
double scale_factor(const std::string& option, const TriangleMesh& mesh, double reference_diagonal);

/// The mesh with its rest positions multiplied by `factor` (about the origin).
TriangleMesh scaled(const TriangleMesh& mesh, double factor);

/// A warning (one line) when the mesh's diagonal is more than kSizeWarningFactor times
/// reference_diagonal (the bunny's), or less than its 1 / kSizeWarningFactor; "" otherwise.
std::string size_warning(const TriangleMesh& mesh, double reference_diagonal);

}  // namespace sscc::validation
