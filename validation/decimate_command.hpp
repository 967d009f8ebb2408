// `sscc decimate`: quadric-error edge collapse (OpenMesh's decimater, Garland and Heckbert
// 1997) of a triangle mesh down to a triangle count, for making demo-sized meshes from
// large scans (the shipped demo bunny came from bunny00.off this way). Prints
//   decimate: input_triangles=N output_triangles=N time_s=X
#pragma once

#include <ostream>
#include <string>

namespace sscc::validation {

struct DecimateCommandOptions {
  std::string mesh;
  std::string output;  ///< any format OpenMesh writes (by extension), e.g. .off
  int triangles = 15000;
};

long run_decimate(const DecimateCommandOptions& options, std::ostream& out, std::ostream& progress);

}  // namespace sscc::validation
