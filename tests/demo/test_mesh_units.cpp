#include <catch2/catch.hpp>

#include "demo/mesh_units.hpp"
#include "support/test_meshes.hpp"

namespace {

const double kUnitSphereDiagonal = 2.0 * std::sqrt(3.0);  // the box [-1, 1]^3

}  // namespace

TEST_CASE("mesh units: --scale auto makes the diagonal the reference's, S multiplies the positions", "[demo]") {
  const sscc::TriangleMesh sphere = sscc::test::uv_sphere(6, 12);
  REQUIRE(sphere.bounding_box_diagonal() == Approx(kUnitSphereDiagonal));
  const double reference = 1.6;
  const double automatic = sscc::validation::scale_factor("auto", sphere, reference);
  CHECK(sscc::validation::scaled(sphere, automatic).bounding_box_diagonal() == Approx(reference));
  CHECK(sscc::validation::scale_factor("0.01", sphere, reference) == 0.01);
  const sscc::TriangleMesh centimetres = sscc::validation::scaled(sphere, 100.0);
  CHECK(centimetres.triangles() == sphere.triangles());
  for (int v = 0; v < sphere.vertex_count(); ++v) CHECK(centimetres.vertices()[v] == 100.0 * sphere.vertices()[v]);
  for (const char* bad : {"", "0", "-2", "x", "2x", "inf", "nan"}) {
    INFO(bad);
    CHECK_THROWS_AS(sscc::validation::scale_factor(bad, sphere, reference), std::invalid_argument);
  }
}

TEST_CASE("mesh units: a mesh more than ten times larger or smaller than the reference is warned about", "[demo]") {
  const sscc::TriangleMesh sphere = sscc::test::uv_sphere(6, 12);
  const double d = kUnitSphereDiagonal;
  CHECK(sscc::validation::size_warning(sphere, d).empty());
  CHECK(sscc::validation::size_warning(sphere, d * 9.9).empty());
  CHECK(sscc::validation::size_warning(sphere, d / 9.9).empty());
  CHECK_FALSE(sscc::validation::size_warning(sphere, d * 10.5).empty());
  const std::string large = sscc::validation::size_warning(sphere, d / 100.0);
  CHECK(large.find("--scale auto") != std::string::npos);
}
