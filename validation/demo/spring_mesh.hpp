// The demo's spring: a double helix, as one closed tube. Two interleaved helices of the
// same hand (offset by half a turn, so neighbouring coils belong to different helices and
// stand half a pitch apart), joined at the top and at the bottom by a bridge across the
// axis into one loop; the centre line is smoothed at the joints and resampled evenly, and a
// circle is swept along it with rotation-minimising frames (the residual twist spread over
// the loop so the tube closes). The surface is a closed, oriented torus-like manifold with
// no self-intersection, axis along z, from z = 0 to the height.
#pragma once

#include "sscc/mesh/triangle_mesh.hpp"

namespace sscc::validation {

struct SpringShape {
  double coil_radius = 0.5;   ///< m, axis to centre line
  double pitch = 0.5;         ///< m per turn of one helix (neighbouring coils: pitch / 2 apart)
  int turns = 4;              ///< per helix
  double tube_radius = 0.07;  ///< m; below pitch / 4, so that coils do not touch at rest
  int rings = 500;            ///< cross-sections along the loop
  int segments = 16;          ///< vertices per cross-section: 2 rings segments triangles
};

/// Throws std::invalid_argument when the tube would touch itself at rest.
TriangleMesh double_helix_spring(const SpringShape& shape = {});

}  // namespace sscc::validation
