#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "sscc/mesh/mesh_io.hpp"
#include "support/shared_data.hpp"

namespace fs = std::filesystem;

namespace {

/// Writes `content` to a file with the given name in a fresh scratch folder.
std::string scratch_file(const std::string& name, const std::string& content) {
  const fs::path dir = fs::temp_directory_path() / "sscc-test-mesh";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path, std::ios::binary) << content;
  return path.string();
}

/// The reader's error message for a file with this name and content ("no error" if none).
std::string error_of(const std::string& name, const std::string& content) {
  try {
    sscc::read_mesh(scratch_file(name, content));
  } catch (const sscc::MeshFileError& e) {
    return std::string(e.what());
  }
  return std::string("no error");
}

const char* kCubeOff =
    "OFF\n"
    "# a unit cube with quad faces\n"
    "8 6 0\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

}  // namespace

TEST_CASE("OFF: a quad cube is triangulated, with its connectivity", "[mesh]") {
  sscc::MeshReadReport report;
  const sscc::TriangleMesh mesh = sscc::read_mesh(scratch_file("cube.off", kCubeOff), &report);
  CHECK(mesh.vertex_count() == 8);
  CHECK(mesh.triangle_count() == 12);
  CHECK(report.polygons_triangulated == 6);
  CHECK(report.zero_area_triangles.empty());
  CHECK(report.duplicate_triangles.empty());
  CHECK(mesh.edges().size() == 18);  // 12 cube edges and 6 face diagonals
  // Euler: V - E + F = 2 for a closed genus-0 surface.
  CHECK(mesh.vertex_count() - static_cast<int>(mesh.edges().size()) + mesh.triangle_count() == 2);
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const sscc::Edge& e = mesh.edges()[mesh.triangle_edges(t)[k]];
      const int a = mesh.triangles()[t][k];
      const int b = mesh.triangles()[t][(k + 1) % 3];
      CHECK(e == sscc::Edge{std::min(a, b), std::max(a, b)});
    }
  }
  int incident = 0;
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    for (const int* t = mesh.triangles_of_vertex_begin(v); t != mesh.triangles_of_vertex_end(v); ++t) {
      const auto& tri = mesh.triangles()[*t];
      CHECK((tri[0] == v || tri[1] == v || tri[2] == v));
      ++incident;
    }
  }
  CHECK(incident == 36);
  CHECK(mesh.adjacent(0, 0));
  CHECK(mesh.bounding_box_diagonal() == Approx(std::sqrt(3.0)));
  // Brute force: adjacent iff some vertex is shared.
  for (int a = 0; a < mesh.triangle_count(); ++a) {
    for (int b = 0; b < mesh.triangle_count(); ++b) {
      bool shared = false;
      for (int i : mesh.triangles()[a]) {
        for (int j : mesh.triangles()[b]) shared = shared || i == j;
      }
      CHECK(mesh.adjacent(a, b) == shared);
    }
  }
}

TEST_CASE("the bounding-box diagonal neither overflows nor underflows", "[mesh]") {
  // One triangle spanning (s, s, s) at each scale: the diagonal is sqrt(3) s. Squaring the
  // extents overflows above about 1e154 and underflows below about 1e-162.
  for (const double s : {1.0, 1e150, 1e200, 1e300, 1e-170, 1e-300}) {
    const sscc::TriangleMesh mesh({{0, 0, 0}, {s, 0, 0}, {s, s, s}}, {{0, 1, 2}});
    INFO("scale " << s);
    CHECK(std::isfinite(mesh.bounding_box_diagonal()));
    CHECK(mesh.bounding_box_diagonal() / s == Approx(std::sqrt(3.0)).epsilon(1e-14));
  }
}

TEST_CASE("OBJ: corner forms, negative indices, ignored statements", "[mesh]") {
  const std::string obj =
      "# comment\nmtllib x.mtl\no thing\n"
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\n"
      "f 1/1/1 2/1/1 3/1/1\nf -4//1 -2//1 -1//1\ns off\nf 1 3 4\n";
  sscc::MeshReadReport report;
  const sscc::TriangleMesh mesh = sscc::read_mesh(scratch_file("square.OBJ", obj), &report);
  CHECK(mesh.vertex_count() == 4);
  REQUIRE(mesh.triangle_count() == 3);
  CHECK(mesh.triangles()[1] == sscc::Triangle{0, 2, 3});
  REQUIRE(report.duplicate_triangles.size() == 1);
  CHECK(report.duplicate_triangles[0] == std::pair<int, int>{1, 2});
}

TEST_CASE("PLY: ASCII and both binary byte orders give the same mesh", "[mesh]") {
  const std::string header_tail =
      "element vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
      "property uchar red\nelement face 2\nproperty list uchar int vertex_indices\n"
      "element extra 1\nproperty float w\nend_header\n";
  const std::string ascii = "ply\nformat ascii 1.0\ncomment made by a test\n" + header_tail +
                            "0 0 0 9\n1 0 0 9\n1 1 0 9\n0 1 2.5 9\n3 0 1 2\n3 0 2 3\n7\n";
  const sscc::TriangleMesh reference = sscc::read_mesh(scratch_file("a.ply", ascii));
  for (const bool big : {false, true}) {
    std::string data;
    const auto put = [&](const void* p, std::size_t n) {
      std::string bytes(static_cast<const char*>(p), n);
      const std::uint16_t one = 1;
      const bool little_host = *reinterpret_cast<const unsigned char*>(&one) == 1;
      if (big == little_host) std::reverse(bytes.begin(), bytes.end());
      data += bytes;
    };
    const double xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 2.5}};
    for (const auto& p : xyz) {
      for (double c : p) put(&c, 8);
      const unsigned char red = 9;
      put(&red, 1);
    }
    const int faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
    for (const auto& f : faces) {
      const unsigned char n = 3;
      put(&n, 1);
      for (int i : f) put(&i, 4);
    }
    const float w = 7;
    put(&w, 4);
    const std::string file = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                             " 1.0\n" + header_tail + data;
    const sscc::TriangleMesh mesh = sscc::read_mesh(scratch_file(big ? "b.ply" : "l.ply", file));
    CHECK(mesh.vertices() == reference.vertices());
    CHECK(mesh.triangles() == reference.triangles());
  }
  CHECK(reference.vertices()[3].z() == 2.5);
}

TEST_CASE("zero-area triangles are reported", "[mesh]") {
  sscc::MeshReadReport report;
  sscc::read_mesh(scratch_file("flat.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n3 0 1 2\n3 0 1 3\n"), &report);
  REQUIRE(report.zero_area_triangles.size() == 1);
  CHECK(report.zero_area_triangles[0] == 0);
  CHECK(report.summary() == "0 polygons triangulated, 1 zero-area triangle, 0 duplicate triangles");
}

TEST_CASE("bad files are refused with the file, the line and the problem", "[mesh]") {
  CHECK_THAT(error_of("nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"),
             Catch::Contains("nan.off:4") && Catch::Contains("not a finite double"));
  CHECK_THAT(error_of("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"),
             Catch::Contains("range.off:6") && Catch::Contains("outside [0, 3)"));
  CHECK_THAT(error_of("short.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n"), Catch::Contains("file ends after 2 of 3 vertices"));
  CHECK_THAT(error_of("line.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n"),
             Catch::Contains("at least three vertices"));
  CHECK_THAT(error_of("repeat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2\n"),
             Catch::Contains("repeat.obj:4") && Catch::Contains("repeats a vertex"));
  CHECK_THAT(error_of("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), Catch::Contains("start at 1"));
  CHECK_THAT(error_of("points.obj", "v 0 0 0\nv 1 0 0\n"), Catch::Contains("no faces"));
  CHECK_THAT(error_of("text.off", "hello world\n"), Catch::Contains("expected the header 'OFF'"));
  CHECK_THAT(error_of("mesh.stl", "solid\n"), Catch::Contains("unknown mesh format"));
  CHECK_THAT(error_of("mesh", "OFF\n"), Catch::Contains("no file extension"));
  CHECK_THAT(error_of("cut.ply",
                      "ply\nformat binary_little_endian 1.0\nelement vertex 2\n"
                      "property float x\nproperty float y\nproperty float z\nend_header\nab"),
             Catch::Contains("binary data ends early"));
  CHECK_THAT(error_of("word.obj", "v 0 zero 0\n"), Catch::Contains("'zero' is not a number"));
  CHECK_THROWS_WITH(sscc::read_mesh("/nonexistent/x.off"), Catch::Contains("cannot open"));
}

TEST_CASE("hostile files end in an error, not a crash or a hang", "[mesh]") {
  // Lines of form feeds or carriage returns only are blank lines.
  CHECK(sscc::read_mesh(scratch_file("ff.off", "OFF\n\f\n3 1 0\n0 0 0\n\r\r\n1 0 0\n0 1 0\n3 0 1 2\n"))
            .triangle_count() == 1);
  CHECK(sscc::read_mesh(scratch_file("cr.obj", "v 0 0 0\n\v\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")).triangle_count() == 1);
  CHECK_THAT(error_of("huge.off", "OFF\n100000000000 1 0\n0 0 0\n"), Catch::Contains("file ends after 1 of"));
  CHECK_THAT(error_of("trunc.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 4294967296\n"),
             Catch::Contains("out of range"));
  CHECK_THAT(error_of("trunc.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4294967297\n"), Catch::Contains("out of range"));
  CHECK_THAT(error_of("count.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n9223372036854775807 0 1 2\n"),
             Catch::Contains("out of range"));
  const std::string ply_head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\n";
  CHECK_THAT(error_of("frac.ply", ply_head + "element face 1\nproperty list uchar float vertex_indices\n"
                                             "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1.5\n"),
             Catch::Contains("not an index"));
  // An element without properties has nothing to read, however large its count.
  CHECK(sscc::read_mesh(scratch_file("empty.ply", ply_head + "element nothing 9223372036854775807\n"
                                                             "element face 1\nproperty list uchar int vertex_indices\n"
                                                             "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"))
            .triangle_count() == 1);
}

TEST_CASE("the real meshes beside the repository load", "[mesh]") {
  const fs::path meshes = fs::path(SSCC_SOURCE_DIR) / ".." / "shared" / "data" / "meshes";
  if (!sscc::test::shared_data_present(meshes, "the real meshes")) return;
  sscc::MeshReadReport report;
  const sscc::TriangleMesh lion = sscc::read_mesh((meshes / "lion.off").string(), &report);
  CHECK(lion.vertex_count() == 7529);
  CHECK(lion.triangle_count() == 14859);
  CHECK(report.polygons_triangulated == 0);
}

TEST_CASE("one polygon of 100k vertices reads (and a repeat in it is found) in n log n", "[mesh]") {
  // A pairwise repeat check takes seconds here (4.9 MB, one face); sorting takes milliseconds.
  constexpr int kCorners = 100000;
  std::ostringstream obj;
  for (int i = 0; i < kCorners; ++i) {
    const double angle = 2.0 * M_PI * i / kCorners;
    obj << "v " << std::cos(angle) << ' ' << std::sin(angle) << " 0\n";
  }
  std::ostringstream face;
  face << "f";
  for (int i = 1; i <= kCorners; ++i) face << ' ' << i;
  sscc::MeshReadReport report;
  const sscc::TriangleMesh mesh = sscc::read_mesh(scratch_file("disc.obj", obj.str() + face.str() + "\n"), &report);
  CHECK(mesh.triangle_count() == kCorners - 2);
  CHECK(report.polygons_triangulated == 1);
  CHECK_THAT(error_of("disc_repeat.obj", obj.str() + face.str() + " 1\n"),
             Catch::Contains("disc_repeat.obj:" + std::to_string(kCorners + 1)) && Catch::Contains("repeats a vertex"));
}
