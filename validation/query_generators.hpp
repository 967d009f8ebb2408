// Seeded generators of CCD queries for tests and validation.
//
// random_query: generic positions, each point uniform in [-1, 1]^3 at t = 0 and displaced
//   by a uniform vector in [-1, 1]^3 at t = 1 (the primitives overlap in space often, so
//   most queries reach the coplanarity stages).
// near_degenerate_query: the cases floating point gets wrong. Coordinates on a small
//   integer grid (exactly coplanar, collinear and parallel configurations, contact at
//   t = 0 or t = 1, zero motion, zero-area triangles), planar motion, and configurations
//   built to touch exactly at a dyadic time on an edge, a vertex or inside the face; then
//   optionally perturbed by a few units in the last place or by 2^-k, and scaled by a
//   power of two or of ten (coordinates from about 1e-6 to 1e6).
#pragma once

#include <random>

#include "query.hpp"

namespace sscc::validation {

Query random_query(Kind kind, std::mt19937_64& rng);
Query near_degenerate_query(Kind kind, std::mt19937_64& rng);
/// All 24 coordinates uniform integers in {-range, ..., range} (grid-aligned models, tests).
Query integer_grid_query(Kind kind, std::mt19937_64& rng, int range = 2);
/// Resting contact: every point in the plane z = 0 at both ends of the step, at uniform
/// positions in [-1, 1]^2 (a vertex, or an edge, sliding on a face's plane).
Query resting_contact_query(Kind kind, std::mt19937_64& rng);

}  // namespace sscc::validation
