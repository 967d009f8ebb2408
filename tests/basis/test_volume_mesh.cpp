#include <catch2/catch.hpp>

#include "sscc/basis/volume_mesh.hpp"
#include "support/test_meshes.hpp"

namespace {

double total_volume(const sscc::VolumeMesh& volume) {
  double sum = 0.0;
  for (const auto& t : volume.tetrahedra) {
    const double v = sscc::signed_volume(volume.nodes, t);
    REQUIRE(v > 0.0);
    sum += v;
  }
  return sum;
}

/// Every surface vertex is reproduced by its embedding (rows sum to 1, and linear
/// functions, positions included, are interpolated exactly).
void check_embedding(const sscc::TriangleMesh& mesh, const sscc::VolumeMesh& volume) {
  REQUIRE(volume.embedding.rows() == mesh.vertex_count());
  REQUIRE(volume.embedding.cols() == static_cast<Eigen::Index>(volume.nodes.size()));
  Eigen::MatrixXd nodes(volume.nodes.size(), 3);
  for (std::size_t n = 0; n < volume.nodes.size(); ++n) nodes.row(n) = volume.nodes[n].transpose();
  const Eigen::MatrixXd embedded = volume.embedding * nodes;
  const Eigen::VectorXd row_sums = volume.embedding * Eigen::VectorXd::Ones(nodes.rows());
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    CHECK(row_sums[v] == Approx(1.0).margin(1e-12));
    CHECK((embedded.row(v).transpose() - mesh.vertices()[v]).norm() < 1e-12);
  }
}

}  // namespace

TEST_CASE("closed manifold detection", "[basis]") {
  const sscc::TriangleMesh box = sscc::test::box_surface({1, 2, 3}, {2, 2, 2});
  CHECK(sscc::is_closed_manifold(box));
  CHECK(sscc::is_closed_manifold(sscc::test::uv_sphere(6, 8)));
  std::vector<sscc::Triangle> open(box.triangles().begin() + 1, box.triangles().end());
  CHECK_FALSE(sscc::is_closed_manifold(sscc::TriangleMesh(box.vertices(), open)));
  std::vector<sscc::Triangle> flipped = box.triangles();
  std::swap(flipped[0][1], flipped[0][2]);
  CHECK_FALSE(sscc::is_closed_manifold(sscc::TriangleMesh(box.vertices(), flipped)));
  CHECK_FALSE(sscc::is_closed_manifold(sscc::test::parallel_sheets(2, 0.1)));
}

TEST_CASE("TetGen fills a closed surface exactly, keeping its vertices first", "[basis]") {
  const sscc::TriangleMesh box = sscc::test::box_surface({1, 0.5, 0.25}, {8, 4, 2});
  std::size_t coarse_count = 0;
  for (double max_volume : {0.0, 0.0001}) {
    const sscc::VolumeMesh volume = sscc::tetrahedralize_surface(box, 1.414, max_volume);
    CHECK(volume.method == "tetgen");
    CHECK(total_volume(volume) == Approx(0.125).epsilon(1e-12));
    for (int v = 0; v < box.vertex_count(); ++v) CHECK(volume.nodes[v] == box.vertices()[v]);
    check_embedding(box, volume);
    CHECK(sscc::connected_pieces(volume) == 1);
    // The volume bound refines the interior (the surface triangles, kept as they are, limit
    // the tetrahedra that touch them).
    if (max_volume == 0.0) coarse_count = volume.tetrahedra.size();
    if (max_volume > 0.0) {
      CHECK(volume.tetrahedra.size() > 2 * coarse_count);
      CHECK(0.125 / volume.tetrahedra.size() <= 2 * max_volume);
    }
  }
  CHECK_THROWS_WITH(sscc::tetrahedralize_surface(box, 0.5), Catch::Contains("quality"));
  CHECK_THROWS_WITH(sscc::tetrahedralize_surface(box, 1.414, -1.0), Catch::Contains("volume"));
}

TEST_CASE("voxels cover open surfaces and fill closed ones", "[basis]") {
  const sscc::TriangleMesh sphere = sscc::test::uv_sphere(12, 16);
  const sscc::VolumeMesh solid = sscc::voxelize_surface(sphere, 10);
  check_embedding(sphere, solid);
  // The solid covers the ball (volume 4.19) and at most one shell of cells beyond it.
  const double cell = 2.0 / 10;
  CHECK(total_volume(solid) > 4.0 / 3.0 * M_PI * std::pow(1.0 - 0.05, 3));
  CHECK(total_volume(solid) < 4.0 / 3.0 * M_PI * std::pow(1.0 + std::sqrt(3.0) * cell, 3));
  CHECK(sscc::connected_pieces(solid) == 1);

  // Two open sheets: a shell of cells around each, no filled inside.
  const sscc::TriangleMesh sheets = sscc::test::parallel_sheets(4, 0.5);
  const sscc::VolumeMesh shell = sscc::voxelize_surface(sheets, 8);
  check_embedding(sheets, shell);
  CHECK(total_volume(shell) < 2 * 1.0 * 2 * (1.0 / 8) + 1e-9);
  CHECK(sscc::connected_pieces(shell) == 2);
  CHECK_THROWS_WITH(sscc::voxelize_surface(sphere, 1), Catch::Contains("resolution"));
}

TEST_CASE("the automatic volume method falls back to voxels and says why", "[basis]") {
  const sscc::VolumeMesh closed = sscc::volume_mesh(sscc::test::box_surface({1, 1, 1}, {2, 2, 2}));
  CHECK(closed.method == "tetgen");
  CHECK(closed.note.empty());
  const sscc::VolumeMesh open = sscc::volume_mesh(sscc::test::parallel_sheets(3, 0.5));
  CHECK(open.method == "voxel");
  CHECK_THAT(open.note, Catch::Contains("not a closed"));
  CHECK(sscc::parse_volume_method("voxel") == sscc::VolumeMethod::voxel);
  CHECK_THROWS_WITH(sscc::parse_volume_method("hex"), Catch::Contains("'hex'"));
}

TEST_CASE("a closed surface that crosses itself is refused before TetGen sees it", "[basis]") {
  // Two boxes, each closed and oriented, the second pushed into the first.
  const sscc::TriangleMesh box = sscc::test::box_surface({1, 1, 1}, {2, 2, 2});
  std::vector<Eigen::Vector3d> vertices = box.vertices();
  std::vector<sscc::Triangle> triangles = box.triangles();
  const int offset = box.vertex_count();
  for (const auto& p : box.vertices()) vertices.push_back(p + Eigen::Vector3d(0.5, 0.3, 0.2));
  for (const auto& t : box.triangles()) triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const sscc::TriangleMesh crossing(vertices, triangles);
  REQUIRE(sscc::is_closed_manifold(crossing));
  CHECK_THROWS_WITH(sscc::tetrahedralize_surface(crossing, 1.414), Catch::Contains("intersects itself"));
  const sscc::VolumeMesh fallback = sscc::volume_mesh(crossing);
  CHECK(fallback.method == "voxel");
  CHECK_THAT(fallback.note, Catch::Contains("intersects itself"));
  check_embedding(crossing, fallback);
}
