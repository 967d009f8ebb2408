#include <catch2/catch.hpp>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>

#include "certificate_fixtures.hpp"
#include "common/fnv1a.hpp"

namespace {

std::string temporary_path(const std::string& name) { return std::string(SSCC_TEST_OUTPUT_DIR) + "/" + name; }

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

namespace {

/// 64-bit FNV-1a, written here independently of the library's: the checksum a forger would
/// recompute.
std::uint64_t fnv1a(const char* data, std::size_t size) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ static_cast<unsigned char>(data[i])) * 0x100000001b3ULL;
  return hash;
}

/// The file's bytes with `parameters` written in and key and checksum recomputed to match.
std::string with_parameters(std::string bytes, const sscc::SubspaceBvh& bvh, const sscc::CertificateParameters& p) {
  constexpr std::size_t kKeyOffset = 16;  // after the magic, version and byte-order mark
  const std::uint64_t key = sscc::Certificates::key_of(bvh, p);
  const std::int32_t depth = p.max_subdivision_depth, evaluations = p.max_evaluations_per_pair;
  std::memcpy(&bytes[kKeyOffset], &key, 8);
  std::memcpy(&bytes[kKeyOffset + 8], &p.epsilon, 8);
  std::memcpy(&bytes[kKeyOffset + 16], &p.global_radius_scale, 8);
  std::memcpy(&bytes[kKeyOffset + 24], &depth, 4);
  std::memcpy(&bytes[kKeyOffset + 28], &evaluations, 4);
  const std::uint64_t checksum = fnv1a(bytes.data(), bytes.size() - 8);
  std::memcpy(&bytes[bytes.size() - 8], &checksum, 8);
  return bytes;
}

}  // namespace

TEST_CASE("certificate file: parameters that precompute() refuses are refused on read", "[certificates]") {
  const auto m = sscc::test::certified_sheets(Eigen::Vector3d(1, 1, 1));
  const std::string path = temporary_path("sheets_parameters.sscc");
  m->certificates.write(path);
  const std::string bytes = read_bytes(path);

  // The forgery itself is faithful: the file's own parameters rewritten read back fine.
  write_bytes(path, with_parameters(bytes, m->bvh, m->certificates.parameters()));
  CHECK(error_of(path, m->bvh).empty());

  std::vector<sscc::CertificateParameters> invalid(4, m->certificates.parameters());
  invalid[0].epsilon = std::numeric_limits<double>::quiet_NaN();
  invalid[1].global_radius_scale = -1.0;
  invalid[2].max_subdivision_depth = -7;
  invalid[3].max_evaluations_per_pair = 0;
  for (const sscc::CertificateParameters& p : invalid) {
    REQUIRE_FALSE(sscc::problem_with(p).empty());
    CHECK_THROWS_AS(sscc::Certificates::precompute(m->bvh, p), std::invalid_argument);
    write_bytes(path, with_parameters(bytes, m->bvh, p));
    CHECK_THAT(error_of(path, m->bvh), Catch::Contains("invalid parameters"));
  }
}

namespace {

/// The file's bytes with the pair certificates' section changed by `damage`, then checksummed
/// again: only the structure checks can refuse it.
std::string with_pair_section(std::string bytes, int nodes, const std::function<void(char*, std::int64_t)>& damage) {
  // magic, version, byte-order mark, key, parameters, node count, R_global, node radii,
  // sibling radii, sibling pair certificate indices, pair count.
  const std::size_t at = 8 + 4 + 4 + 8 + (8 + 8 + 4 + 4 + 8) + 8 + 8 + 8 * static_cast<std::size_t>(nodes) +
                         (32 + 16) * static_cast<std::size_t>(nodes);
  std::int64_t count;
  std::memcpy(&count, bytes.data() + at, sizeof count);
  damage(bytes.data() + at + sizeof count, count);
  sscc::Fnv1a checksum;
  checksum.add(bytes.data(), bytes.size() - sizeof(std::uint64_t));
  const std::uint64_t value = checksum.value();
  std::memcpy(bytes.data() + bytes.size() - sizeof value, &value, sizeof value);
  return bytes;
}

}  // namespace

TEST_CASE("certificate file: pair certificates of a broken structure are refused, checksum or not", "[certificates]") {
  const auto m = sscc::test::certified_sphere();
  const sscc::Certificates& c = m->certificates;
  REQUIRE(c.pair_certificates().size() > 10);
  const std::string path = temporary_path("sphere-pairs.sscc");
  c.write(path);
  const std::string bytes = read_bytes(path);
  const int nodes = c.node_count();
  write_bytes(path, with_pair_section(bytes, nodes, [](char*, std::int64_t) {}));
  REQUIRE(error_of(path, m->bvh).empty());
  std::int64_t parent = -1;  // a pair certificate with children
  for (std::size_t k = 0; k < c.pair_certificates().size() && parent < 0; ++k) {
    if (c.pair_certificate(static_cast<int>(k)).first_child >= 0) parent = static_cast<std::int64_t>(k);
  }
  REQUIRE(parent >= 0);
  const auto entry = [&](char* pairs, std::int64_t k) { return pairs + 12 * k; };
  const auto refused = [&](const std::function<void(char*, std::int64_t)>& damage) {
    write_bytes(path, with_pair_section(bytes, nodes, damage));
    return error_of(path, m->bvh).find("pair certificate") != std::string::npos;
  };
  for (std::int32_t child : {std::int32_t(1 << 30), std::int32_t(0), static_cast<std::int32_t>(parent)}) {
    INFO("first child " << child);
    CHECK(refused([&](char* pairs, std::int64_t) { std::memcpy(entry(pairs, parent) + 8, &child, sizeof child); }));
  }
  for (double radius : {-1.0, std::numeric_limits<double>::quiet_NaN(), 2.0 * c.global_radius()}) {
    INFO("radius " << radius);
    CHECK(refused([&](char* pairs, std::int64_t) { std::memcpy(entry(pairs, parent), &radius, sizeof radius); }));
  }
}
