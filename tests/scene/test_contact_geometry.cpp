// The contact points and normals of reported feature contacts (sscc/scene/contact_geometry.hpp)
// against the geometry of the step: at the reported time of impact the two contact points
// coincide, the weights are barycentrics and segment parameters, and the normal is the
// triangle's (or the edges') and points from the second side to where the first side started.
#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <random>

#include "sscc/query/position_ccd.hpp"
#include "sscc/scene/contact_geometry.hpp"
#include "support/test_meshes.hpp"

namespace {

using Points = std::array<Eigen::Vector3d, 4>;

Eigen::Vector3d weighted(const std::array<double, 4>& w, const Points& x) {
  return w[0] * x[0] + w[1] * x[1] + w[2] * x[2] + w[3] * x[3];
}

}  // namespace

TEST_CASE("contact geometry: every feature of a query meets at its time of impact", "[scene][contact_geometry]") {
  // Two spheres driven into each other, every vertex jittered: vertex-face and edge-edge
  // contacts of every kind of position.
  const sscc::TriangleMesh mesh = sscc::test::two_spheres(6, 9, Eigen::Vector3d(3.1, 0.13, -0.07));
  const sscc::PositionCcd ccd(mesh);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  int vertex_face = 0, edge_edge = 0;
  for (int trial = 0; trial < 4; ++trial) {
    std::vector<Eigen::Vector3d> x0 = mesh.vertices(), x1 = mesh.vertices();
    for (int v = 0; v < mesh.vertex_count(); ++v) {
      if (v >= mesh.vertex_count() / 2) x1[v].x() -= 1.4 + 0.2 * trial;  // the gap is 1.1
      x1[v] += Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
    }
    const sscc::SelfCcdReport report = ccd.query(x0, x1);
    REQUIRE(!report.features.empty());
    for (const sscc::FeatureContact& f : report.features) {
      const std::array<int, 4> v = sscc::contact_vertices(mesh, mesh, f.kind, f.first, f.second);
      Points start, end, at;
      double motion = 0.0;
      for (int i = 0; i < 4; ++i) {
        start[i] = x0[v[i]], end[i] = x1[v[i]];
        at[i] = (1 - f.toi) * start[i] + f.toi * end[i];
        motion = std::max(motion, (end[i] - start[i]).norm());
      }
      const sscc::ContactFrame c = sscc::contact_frame(f.kind, start, end, f.toi);
      INFO("kind " << int(f.kind) << " features " << f.first << ", " << f.second << " toi " << f.toi);
      // The two contact points coincide at toi, up to how far the features move within the
      // time-of-impact tolerance (toi is at most 1e-6 early) and rounding.
      CHECK(weighted(c.weights, at).norm() <= 4.0 * motion * sscc::ccd::kDefaultToiTolerance + 1e-12);
      CHECK(c.normal.norm() == Approx(1.0).epsilon(1e-12));
      // The first side starts on the positive side of the normal.
      CHECK(sscc::contact_gap(c, start) >= -1e-12);
      if (f.kind == sscc::FeatureKind::kVertexFace) {
        ++vertex_face;
        CHECK(c.weights[0] == 1.0);
        for (int i = 1; i < 4; ++i) CHECK((c.weights[i] <= 0.0 && c.weights[i] >= -1.0));
        CHECK(c.weights[1] + c.weights[2] + c.weights[3] == Approx(-1.0).margin(1e-12));
        const Eigen::Vector3d n = (at[2] - at[1]).cross(at[3] - at[1]).normalized();
        CHECK(std::abs(n.dot(c.normal)) == Approx(1.0).epsilon(1e-9));
      } else {
        ++edge_edge;
        for (int i = 0; i < 4; ++i) CHECK(std::abs(c.weights[i]) <= 1.0);
        CHECK(c.weights[0] + c.weights[1] == Approx(1.0).margin(1e-12));
        CHECK(c.weights[2] + c.weights[3] == Approx(-1.0).margin(1e-12));
        const Eigen::Vector3d n = (at[1] - at[0]).cross(at[3] - at[2]).normalized();
        CHECK(std::abs(n.dot(c.normal)) == Approx(1.0).epsilon(1e-9));
      }
    }
  }
  CHECK(vertex_face > 20);
  CHECK(edge_edge > 20);
}

TEST_CASE("contact geometry: a feature's vertices, in the frame's order", "[scene][contact_geometry]") {
  const sscc::TriangleMesh a = sscc::test::uv_sphere(3, 4);
  const sscc::TriangleMesh b = sscc::test::uv_sphere(4, 5);
  const std::array<int, 4> vf = sscc::contact_vertices(a, b, sscc::FeatureKind::kVertexFace, 2, 7);
  CHECK(vf == std::array<int, 4>{2, b.triangles()[7][0], b.triangles()[7][1], b.triangles()[7][2]});
  const std::array<int, 4> ee = sscc::contact_vertices(a, b, sscc::FeatureKind::kEdgeEdge, 3, 5);
  CHECK(ee == std::array<int, 4>{a.edges()[3][0], a.edges()[3][1], b.edges()[5][0], b.edges()[5][1]});
  CHECK_THROWS_AS(sscc::contact_vertices(a, b, sscc::FeatureKind::kVertexFace, a.vertex_count(), 0), std::out_of_range);
  CHECK_THROWS_AS(sscc::contact_vertices(a, b, sscc::FeatureKind::kVertexFace, 0, b.triangle_count()),
                  std::out_of_range);
  CHECK_THROWS_AS(sscc::contact_vertices(a, b, sscc::FeatureKind::kEdgeEdge, -1, 0), std::out_of_range);
}
