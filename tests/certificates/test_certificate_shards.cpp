#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <random>
#include <stdexcept>

#include "certificate_fixtures.hpp"
#include "sscc/certificates/certificate_shards.hpp"

namespace {

using sscc::Certificates;
using sscc::CertificateShard;

std::string temporary_path(const std::string& name) { return std::string(SSCC_TEST_OUTPUT_DIR) + "/" + name; }

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The bytes of the certificate file `certificates` write.
std::string file_bytes(const Certificates& certificates, const std::string& name) {
  const std::string path = temporary_path(name);
  certificates.write(path);
  return read_bytes(path);
}

std::vector<CertificateShard> all_shards(const sscc::SubspaceBvh& bvh, int count,
                                         const sscc::CertificateParameters& parameters = {}) {
  std::vector<CertificateShard> shards;
  for (int i = 0; i < count; ++i) shards.push_back(Certificates::precompute_shard(bvh, parameters, i, count));
  return shards;
}

std::string merge_error(const sscc::SubspaceBvh& bvh, const std::vector<CertificateShard>& shards) {
  try {
    Certificates::merge(bvh, shards);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::string read_error(const std::string& bytes, const sscc::SubspaceBvh& bvh) {
  try {
    CertificateShard::from_bytes(bytes, bvh, "part");
  } catch (const sscc::CertificateFileError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("certificate shards: the layout deals every subtree below the split depth to one shard", "[certificates]") {
  const auto m = sscc::test::certified_sphere();
  const std::vector<int> depth = m->bvh.node_depths();
  const auto& nodes = m->bvh.nodes();
  for (int count : {1, 2, 3, 5, 1000}) {
    INFO(count << " shards");
    const sscc::ShardLayout layout = sscc::shard_layout(m->bvh, count);
    REQUIRE(layout.roots.size() == static_cast<std::size_t>(count));
    const long at_split = std::count(depth.begin(), depth.end(), layout.split_depth);
    if (count < 1000) REQUIRE(at_split >= count);
    std::vector<long> triangles(count, 0);
    long largest_root = 0;
    for (int n = 0; n < static_cast<int>(nodes.size()); ++n) {
      // Above the split depth: the merge's; below: the shard of the subtree's root.
      REQUIRE((layout.shard_of[n] < 0) == (depth[n] < layout.split_depth));
      const int parent_shard = [&] {
        for (int p = 0; p < static_cast<int>(nodes.size()); ++p) {
          if (n >= nodes[p].first_child && n < nodes[p].first_child + nodes[p].child_count) return layout.shard_of[p];
        }
        return -1;
      }();
      if (depth[n] > layout.split_depth) REQUIRE(layout.shard_of[n] == parent_shard);
      if (depth[n] == layout.split_depth) {
        const auto& roots = layout.roots[layout.shard_of[n]];
        REQUIRE(std::count(roots.begin(), roots.end(), n) == 1);
        triangles[layout.shard_of[n]] += nodes[n].triangle_end - nodes[n].triangle_begin;
        largest_root = std::max<long>(largest_root, nodes[n].triangle_end - nodes[n].triangle_begin);
      }
    }
    // Greedy by size: no shard exceeds the lightest by more than one subtree.
    REQUIRE(*std::max_element(triangles.begin(), triangles.end()) -
                *std::min_element(triangles.begin(), triangles.end()) <=
            largest_root);
    const sscc::ShardLayout again = sscc::shard_layout(m->bvh, count);
    REQUIRE(again.shard_of == layout.shard_of);
  }
  REQUIRE_THROWS_WITH(sscc::shard_layout(m->bvh, 0), Catch::Contains("at least 1"));
}

TEST_CASE("certificate shards: merged, the certificate file of one precomputation, byte for byte", "[certificates]") {
  const auto sphere = sscc::test::certified_sphere();
  const auto touching = sscc::test::certified_touching_spheres();
  const auto sheets = sscc::test::certified_sheets(Eigen::Vector3d(1, 1, 1));
  std::mt19937_64 rng(7);
  for (const auto* m : {sphere.get(), touching.get(), sheets.get()}) {
    const std::string single = file_bytes(m->certificates, "single.sscc");
    for (int count : {1, 2, 3, 5, 40}) {
      if (count == 40 && m != sheets.get()) continue;  // more shards than subtrees: some empty
      INFO(m->bvh.model().mesh().triangle_count() << " triangles, " << count << " shards");
      std::vector<CertificateShard> shards = all_shards(m->bvh, count);
      std::shuffle(shards.begin(), shards.end(), rng);
      REQUIRE(file_bytes(Certificates::merge(m->bvh, shards), "merged.sscc") == single);
      // The same through the shards' bytes and files.
      std::vector<CertificateShard> read;
      for (const CertificateShard& shard : shards) {
        const std::string path = temporary_path("shard.sscc-part");
        shard.write(path);
        read.push_back(CertificateShard::read(path, m->bvh));
        REQUIRE(read.back().to_bytes() == shard.to_bytes());
      }
      std::reverse(read.begin(), read.end());
      REQUIRE(file_bytes(Certificates::merge(m->bvh, read), "merged.sscc") == single);
    }
  }
}

TEST_CASE("certificate shards: a missing, repeated, foreign or damaged shard is refused by name", "[certificates]") {
  const auto m = sscc::test::certified_sphere();
  const std::vector<CertificateShard> shards = all_shards(m->bvh, 3);

  SECTION("missing") {
    REQUIRE(merge_error(m->bvh, {shards[0], shards[2]}) == "certificates: shards missing: 1/3");
    REQUIRE(merge_error(m->bvh, {}) == "certificates: nothing to merge (no shards given)");
  }
  SECTION("repeated") {
    REQUIRE(merge_error(m->bvh, {shards[0], shards[1], shards[1], shards[2]}) == "certificates: shard 1/3 given twice");
  }
  SECTION("of another shard count") {
    const CertificateShard other = Certificates::precompute_shard(m->bvh, {}, 1, 2);
    REQUIRE_THAT(merge_error(m->bvh, {shards[0], other, shards[2]}),
                 Catch::Contains("shard 1/2 is one of 2 shards, shard 0/3 one of 3"));
  }
  SECTION("of other parameters") {
    sscc::CertificateParameters coarse;
    coarse.epsilon = 0.2;
    const CertificateShard other = Certificates::precompute_shard(m->bvh, coarse, 2, 3);
    REQUIRE_THAT(merge_error(m->bvh, {shards[0], shards[1], other}),
                 Catch::Contains("shard 2/3 was computed with epsilon 0.200000"));
  }
  SECTION("of another model") {
    const auto sheets = sscc::test::certified_sheets(Eigen::Vector3d(1, 1, 1));
    const std::vector<CertificateShard> foreign = all_shards(sheets->bvh, 3);
    REQUIRE_THAT(merge_error(m->bvh, {shards[0], foreign[1], shards[2]}),
                 Catch::Contains("shard 1/3 was computed for another mesh"));
    REQUIRE_THAT(read_error(foreign[1].to_bytes(), m->bvh), Catch::Contains("stale"));
  }
  SECTION("an index out of range") {
    REQUIRE_THROWS_WITH(Certificates::precompute_shard(m->bvh, {}, 3, 3), Catch::Contains("shard 3/3"));
    REQUIRE_THROWS_WITH(Certificates::precompute_shard(m->bvh, {}, -1, 3), Catch::Contains("shard -1/3"));
  }
  SECTION("damaged bytes") {
    const std::string bytes = shards[1].to_bytes();
    REQUIRE(read_error(bytes, m->bvh).empty());
    for (std::size_t at = 0; at < bytes.size(); at += 29) {
      std::string damaged = bytes;
      damaged[at] = static_cast<char>(damaged[at] ^ 0x10);
      INFO("byte " << at);
      REQUIRE_THAT(read_error(damaged, m->bvh), Catch::StartsWith("certificate shard part: "));
    }
    for (std::size_t keep : {std::size_t(0), std::size_t(7), std::size_t(30), bytes.size() / 2, bytes.size() - 1}) {
      INFO("kept " << keep << " bytes");
      REQUIRE_THAT(read_error(bytes.substr(0, keep), m->bvh), Catch::StartsWith("certificate shard part: "));
    }
    REQUIRE_THAT(read_error(file_bytes(m->certificates, "not_a_shard.sscc"), m->bvh), Catch::Contains("bad magic"));
    REQUIRE_THROWS_WITH(CertificateShard::read(temporary_path("no_such.sscc-part"), m->bvh),
                        Catch::Contains("cannot open"));
  }
}

TEST_CASE("certificates: the progress reaches every unit of work, and an exception it throws stops the work",
          "[certificates]") {
  const auto m = sscc::test::certified_sphere();
  std::vector<sscc::PrecomputeStatus> seen;
  const Certificates certificates =
      Certificates::precompute(m->bvh, {}, [&](const sscc::PrecomputeStatus& s) { seen.push_back(s); });
  REQUIRE_FALSE(seen.empty());
  for (std::size_t i = 1; i < seen.size(); ++i) {
    REQUIRE(seen[i].work_done >= seen[i - 1].work_done);
    REQUIRE(seen[i].levels_done >= seen[i - 1].levels_done);
    REQUIRE(seen[i].work == seen[0].work);
  }
  REQUIRE(seen.back().work_done == seen.back().work);
  REQUIRE(seen.back().levels_done == seen.back().levels);
  REQUIRE(seen.back().levels == m->bvh.build_stats().depth + 1);
  // The shards' work and the merge's add up to the whole.
  long shards_work = 0;
  for (int i = 0; i < 3; ++i) {
    Certificates::precompute_shard(m->bvh, {}, i, 3, [&](const sscc::PrecomputeStatus& s) {
      if (s.levels_done == s.levels) shards_work += s.work;
    });
  }
  long merge_work = 0;
  Certificates::merge(m->bvh, all_shards(m->bvh, 3), [&](const sscc::PrecomputeStatus& s) { merge_work = s.work; });
  REQUIRE(shards_work + merge_work == seen.back().work);

  struct Stop {};
  long calls = 0;
  REQUIRE_THROWS_AS(Certificates::precompute(m->bvh, {},
                                             [&](const sscc::PrecomputeStatus&) {
                                               ++calls;
                                               throw Stop{};
                                             }),
                    Stop);
  REQUIRE(calls == 1);
}
