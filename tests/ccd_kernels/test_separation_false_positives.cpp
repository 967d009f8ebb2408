// Minimum separation must not invent proximity: primitives that stay a known distance h
// apart (held in a random orientation, translated together) are no contact for d below
// h / (1 + kSeparationRelativeTolerance), and the decision is made by the separation search
// itself, past the swept-box cull (the boxes overlap: the primitives cross obliquely).
#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <random>

#include "sscc/ccd/kernels.hpp"

namespace {

using V = Eigen::Vector3d;

struct RigidPair {
  std::array<V, 8> points;  // the kernels' argument order
  double distance;          // exact up to the rounding of the placement
};

/// A random orientation, and a translation at each end of the step (the pair moves rigidly).
struct Placement {
  Eigen::Matrix3d r0, r1;
  V t0, t1;
  V at0(const V& p) const { return r0 * p + t0; }
  V at1(const V& p) const { return r1 * p + t1; }
};

Placement random_placement(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  const auto random_rotation = [&] {
    return Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized().toRotationMatrix();
  };
  // Translated over the step, not turned: linear paths of turning points are not rigid.
  const Eigen::Matrix3d r = random_rotation();
  const V t0(normal(rng), normal(rng), normal(rng));
  return {r, r, t0, t0 + V(normal(rng), normal(rng), normal(rng))};
}

/// Two edges crossing at right angles, h apart along the local z axis; the closest points
/// are the edges' midpoints.
RigidPair crossing_edges(const Placement& p, double h) {
  const std::array<V, 4> local = {V(-1, 0, 0), V(1, 0, 0), V(0, -1, h), V(0, 1, h)};
  RigidPair pair{{}, h};
  for (int i = 0; i < 4; ++i) {
    pair.points[i] = p.at0(local[i]);
    pair.points[i + 4] = p.at1(local[i]);
  }
  return pair;
}

/// A vertex h above the centre of a triangle (the local z axis is its normal).
RigidPair vertex_over_face(const Placement& p, double h) {
  const std::array<V, 4> local = {V(0, 0, h), V(-1, -1, 0), V(2, -1, 0), V(-1, 2, 0)};
  RigidPair pair{{}, h};
  for (int i = 0; i < 4; ++i) {
    pair.points[i] = p.at0(local[i]);
    pair.points[i + 4] = p.at1(local[i]);
  }
  return pair;
}

sscc::ccd::CcdResult run(bool vertex_face, const std::array<V, 8>& x, double d) {
  sscc::ccd::CcdOptions options;
  options.minimum_separation = d;
  return vertex_face ? sscc::ccd::vertex_face_ccd(x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], options)
                     : sscc::ccd::edge_edge_ccd(x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], options);
}

}  // namespace

TEST_CASE("minimum separation: primitives held apart are no contact, decided past the box cull",
          "[kernels][separation]") {
  std::mt19937_64 rng(19);
  int searched = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Placement placement = random_placement(rng);
    // 1 down to 2^-8 of the primitives' size: much closer, the search's box budget
    // (kSeparationMaxBoxes) can run out, which reports a contact, as its guarantee allows.
    const double h = std::ldexp(1.0, -(trial % 9));
    for (bool vertex_face : {true, false}) {
      const RigidPair pair = vertex_face ? vertex_over_face(placement, h) : crossing_edges(placement, h);
      INFO("trial " << trial << (vertex_face ? " vertex-face" : " edge-edge") << " h " << h);
      // Well below h (placement rounding is ~1e-15): never a contact.
      for (double fraction : {0.4, 0.7, 0.95}) {
        const sscc::ccd::CcdResult far = run(vertex_face, pair.points, fraction * h);
        CHECK_FALSE(far.hit);
        searched += far.decided_by == sscc::ccd::DecidedBy::kSeparationSearch;
      }
      // Above h: always one, found by the search.
      const sscc::ccd::CcdResult near = run(vertex_face, pair.points, 1.05 * h);
      CHECK(near.hit);
      CHECK(near.decided_by == sscc::ccd::DecidedBy::kSeparationSearch);
    }
  }
  // Most far cases reach the search: the boxes of oblique primitives overlap.
  CHECK(searched >= 600);
}
