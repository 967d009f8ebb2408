// Contact parameters at a given time, in floating point (approximate, for reporting):
// the barycentric weights of f1 and f2 of the triangle point closest to the vertex, or the
// parameters of the closest points of two segments. Degenerate shapes are handled by
// clamping, so the parameters always lie in their domains.
#pragma once

#include "four_point_motion.hpp"

namespace sscc::ccd {

void contact_params_at(const FourPointMotion& motion, double t, double params[2]);

}  // namespace sscc::ccd
