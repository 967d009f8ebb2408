// write_off then read_mesh gives back the mesh bit for bit, whatever finite doubles it holds:
// subnormal coordinates (once refused on reading as out of range), negative zero, the largest
// doubles and values decimal cannot write short.
#include <catch2/catch.hpp>

#include <cstring>
#include <fstream>
#include <limits>
#include <string>

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

TEST_CASE("mesh readers: a coordinate beyond the largest double is refused", "[mesh]") {
  const std::string path = std::string(SSCC_TEST_OUTPUT_DIR) + "/overflowing_coordinate.off";
  {
    std::ofstream out(path);
    out << "OFF\n3 1 0\n1e309 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  }
  CHECK_THROWS_WITH(sscc::read_mesh(path), Catch::Contains("not a finite double"));
}
