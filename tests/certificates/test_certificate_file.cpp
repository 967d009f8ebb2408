#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <iterator>

#include "certificate_fixtures.hpp"

namespace {

std::string temporary_path(const std::string& name) {
  return std::string(SSCC_TEST_OUTPUT_DIR) + "/" + name;
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string error_of(const std::string& path, const sscc::SubspaceBvh& bvh) {
  try {
    sscc::Certificates::read(path, bvh);
  } catch (const sscc::CertificateFileError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("certificate file: round trip, and every damaged or stale file refused", "[certificates]") {
  const auto m = sscc::test::certified_sheets(Eigen::Vector3d(1, 1, 1));
  const std::string path = temporary_path("sheets.sscc");
  m->certificates.write(path);
  const sscc::Certificates read = sscc::Certificates::read(path, m->bvh);
  REQUIRE(read.key() == m->certificates.key());
  REQUIRE(read.global_radius() == m->certificates.global_radius());
  for (int n = 0; n < read.node_count(); ++n) REQUIRE(read.node_radius(n) == m->certificates.node_radius(n));
  const auto& nodes = m->bvh.nodes();
  for (int a = nodes[0].first_child; a < nodes[0].first_child + nodes[0].child_count; ++a) {
    for (int b = nodes[0].first_child; b < nodes[0].first_child + nodes[0].child_count; ++b) {
      REQUIRE(read.sibling_radius(a, b) == m->certificates.sibling_radius(a, b));
    }
  }
  const std::string bytes = read_bytes(path);

  SECTION("truncated") {
    for (std::size_t keep : {std::size_t(0), std::size_t(5), std::size_t(20), bytes.size() / 2, bytes.size() - 1}) {
      write_bytes(path, bytes.substr(0, keep));
      INFO("kept " << keep << " bytes");
      REQUIRE_FALSE(error_of(path, m->bvh).empty());
    }
  }
  SECTION("a flipped byte anywhere") {
    for (std::size_t at = 16; at < bytes.size(); at += 37) {
      std::string damaged = bytes;
      damaged[at] = static_cast<char>(damaged[at] ^ 0x10);
      write_bytes(path, damaged);
      INFO("byte " << at);
      REQUIRE_THAT(error_of(path, m->bvh), Catch::Contains("checksum"));
    }
  }
  SECTION("another format version") {
    std::string other = bytes;
    other[8] = 7;
    write_bytes(path, other);
    REQUIRE_THAT(error_of(path, m->bvh), Catch::Contains("version"));
  }
  SECTION("not a certificate file") {
    write_bytes(path, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    REQUIRE_THAT(error_of(path, m->bvh), Catch::Contains("not a certificate file"));
  }
  SECTION("missing") { REQUIRE_THAT(error_of(temporary_path("absent.sscc"), m->bvh), Catch::Contains("cannot open")); }
  SECTION("stale: other weights, other basis") {
    const auto reweighted = sscc::test::certified_sheets(Eigen::Vector3d(1, 1, 3));
    REQUIRE_THAT(error_of(path, reweighted->bvh), Catch::Contains("stale"));
    const sscc::SubspaceModel moved(m->model.mesh(), 2.0 * sscc::test::sheet_basis(m->model.mesh()),
                                    Eigen::Vector3d(1, 1, 1));
    const sscc::SubspaceBvh moved_bvh(moved);
    REQUIRE_THAT(error_of(path, moved_bvh), Catch::Contains("stale"));
  }
  std::remove(path.c_str());
}
