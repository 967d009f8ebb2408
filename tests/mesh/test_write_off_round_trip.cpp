// write_off then read_mesh gives back the mesh bit for bit, whatever finite doubles it holds:
// subnormal coordinates (once refused on reading as out of range), negative zero, the largest
// doubles and values decimal cannot write short.
#include <catch2/catch.hpp>

#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "sscc/mesh/mesh_io.hpp"
#include "sscc/mesh/write_off.hpp"

TEST_CASE("write_off: every finite double reads back bit for bit", "[mesh]") {
  const double smallest = std::numeric_limits<double>::denorm_min();
  const double largest = std::numeric_limits<double>::max();
  const sscc::TriangleMesh mesh(
      {{smallest, -0.0, largest}, {0.1, 1.0 / 3, -2.5e-300}, {7, 8, -largest}, {1e-310, 9007199254740993.0, -smallest}},
      {{0, 1, 2}, {1, 2, 3}});
  const std::string path = std::string(SSCC_TEST_OUTPUT_DIR) + "/write_off_round_trip.off";
  sscc::write_off(path, mesh);
  const sscc::TriangleMesh back = sscc::read_mesh(path);
  REQUIRE(back.vertex_count() == mesh.vertex_count());
  CHECK(back.triangles() == mesh.triangles());
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    for (int k = 0; k < 3; ++k) {
      INFO("vertex " << v << ", coordinate " << k);
      const double written = mesh.vertices()[v][k], read = back.vertices()[v][k];
      CHECK(std::memcmp(&written, &read, sizeof written) == 0);
    }
  }
}

TEST_CASE("mesh readers: zero-area triangles are found at any magnitude, without overflow", "[mesh]") {
  const double largest = std::numeric_limits<double>::max();
  const double smallest = std::numeric_limits<double>::denorm_min();
  // Triangles 0 and 2 are collinear (across the whole range of doubles, and among subnormals);
  // 1 and 3 are not.
  const sscc::TriangleMesh mesh({{-largest, 0, 0},
                                 {0, 0, 0},
                                 {largest, 0, 0},
                                 {0, largest, 0},
                                 {smallest, smallest, 0},
                                 {2 * smallest, 2 * smallest, 0},
                                 {2 * smallest, 0, 0}},
                                {{0, 1, 2}, {0, 1, 3}, {1, 4, 5}, {1, 4, 6}});
  const std::string path = std::string(SSCC_TEST_OUTPUT_DIR) + "/zero_area_extremes.off";
  sscc::write_off(path, mesh);
  sscc::MeshReadReport report;
  sscc::read_mesh(path, &report);
  CHECK(report.zero_area_triangles == std::vector<int>{0, 2});
}
