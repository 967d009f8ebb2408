// The directions d along which a set of triangles may be proven (patch_radius.hpp): the
// theorem holds for any unit d, and the radius it gives is limited by the triangles that lean
// farthest from d. The set's mean normal at rest leans far from some triangles of a curved set
// (a leg, a tusk, a fold), often past a right angle; the axis of a nearly smallest cone around
// the normals leans less from the farthest one. Which of the two proves the larger radius is
// the radius's to decide (patch_radius.cpp); nothing here needs to be exact, only unit to
// rounding. Private to the library.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace sscc::detail {

/// Iterations of cone_axis. Measured (a version that took the axis wherever its smallest
/// cosine was the larger, without comparing radii), node tests per step of the cones query at
/// amplitude 0.01 (20 steps) with 20 / 50 / 100 / 200 / 500 iterations: the lion 9.8k / 8.7k
/// / 8.3k / 7.7k / 7.5k, the elephant 11.4k / 10.7k / 10.2k / 9.8k / 9.6k (16.6k and 16.3k
/// with the mean normal alone), the construction's time growing with them. Lower: axes
/// farther from the smallest cone's; higher: a slower construction for little.
inline constexpr int kConeAxisIterations = 200;

/// The axis is tried only for sets with a triangle leaning more than 60 degrees from their
/// mean normal (smallest cosine below this): nearer the mean it gained nothing measured (as
/// above, the axis taken by its smallest cosine). Node tests per step of the cones query at
/// amplitude 0.01 (20 steps) and the time of SelfCcd::prepare for the `selfccd` command (one
/// thread), the axis tried always / below 0.5 / below 0.3 / below 0: the lion 7554 / 7554 /
/// 7560 / 8038 and 3.04 / 2.57 / 2.49 / 2.47 s, the elephant 9772 / 9772 / 9786 / 10521 and
/// 0.74 / 0.63 / 0.60 / 0.57 s, the dragon 29793 / 29781 / 29792 / 32806 and 3.13 / 2.78 /
/// 2.58 / 2.52 s. Higher: a slower construction; lower: sets left with a mean that leans too
/// far for a radius.
inline constexpr double kLargestCosineForAxis = 0.5;

/// The axis is tried only when it raises the smallest cosine with the normals by more than
/// this over the mean normal: an axis that gains less is the mean but for rounding, and
/// would only repeat its radius.
inline constexpr double kSmallestAxisGain = 1e-6;

/// The unit axis of a nearly smallest cone around the directions of `normals` (any lengths;
/// zero and non-finite vectors are skipped): Badoiu and Clarkson's iteration for the smallest
/// enclosing ball of the unit normals, from their mean. The normals are sorted first, so the
/// result depends on the set of normals only, not on their order. A zero vector when the
/// normals' mean or the iteration's centre comes near the origin (normals all around: no cone
/// narrower than a half-space holds them).
Eigen::Vector3d cone_axis(const std::vector<Eigen::Vector3d>& normals);

/// The direction to try besides the set's mean normal `mean` (unit): cone_axis(normals) when
/// some normal leans from `mean` by more than kLargestCosineForAxis allows and the axis raises
/// the smallest cosine by more than kSmallestAxisGain; else a zero vector (none).
Eigen::Vector3d axis_to_try(const Eigen::Vector3d& mean, const std::vector<Eigen::Vector3d>& normals);

}  // namespace sscc::detail
