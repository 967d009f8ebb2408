// The precomputation in shards and their merge (certificate_shards.hpp).
#include <algorithm>
#include <chrono>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "certificates/binary_io.hpp"
#include "certificates/precompute_driver.hpp"
#include "common/fnv1a.hpp"
#include "sscc/certificates/certificate_shards.hpp"
#include "sscc/common/timing.hpp"

namespace sscc {

namespace {

constexpr char kMagic[8] = {'S', 'S', 'C', 'C', 'P', 'A', 'R', 'T'};
constexpr std::uint32_t kFormatVersion = 1;
constexpr std::uint32_t kByteOrderMark = 0x01020304;

std::string shard_name(int index, int count) { return std::to_string(index) + "/" + std::to_string(count); }

bool same_parameters(const CertificateParameters& a, const CertificateParameters& b) {
  return a.epsilon == b.epsilon && a.global_radius_scale == b.global_radius_scale &&
         a.max_subdivision_depth == b.max_subdivision_depth && a.max_evaluations_per_pair == b.max_evaluations_per_pair;
}

std::string parameters_text(const CertificateParameters& p) {
  return "epsilon " + std::to_string(p.epsilon) + ", global radius scale " + std::to_string(p.global_radius_scale) +
         ", depth " + std::to_string(p.max_subdivision_depth) + ", evaluations " +
         std::to_string(p.max_evaluations_per_pair);
}

/// The shallowest depth with at least `wanted` nodes, or -1.
int shallowest_with(const std::vector<int>& width, long wanted) {
  for (std::size_t d = 0; d < width.size(); ++d) {
    if (width[d] >= wanted) return static_cast<int>(d);
  }
  return -1;
}

}  // namespace

ShardLayout shard_layout(const SubspaceBvh& bvh, int count) {
  if (count < 1)
    throw std::invalid_argument("certificates: the shard count must be at least 1, got " + std::to_string(count));
  const std::vector<SubspaceBvh::Node>& nodes = bvh.nodes();
  const std::vector<int> depth = bvh.node_depths();
  std::vector<int> width(*std::max_element(depth.begin(), depth.end()) + 1, 0);
  for (int d : depth) ++width[d];
  ShardLayout layout;
  layout.count = count;
  layout.split_depth = shallowest_with(width, static_cast<long>(kSubtreesPerShard) * count);
  if (layout.split_depth < 0) layout.split_depth = shallowest_with(width, count);
  if (layout.split_depth < 0) {
    layout.split_depth = static_cast<int>(std::max_element(width.begin(), width.end()) - width.begin());
  }
  std::vector<int> roots;
  for (int n = 0; n < static_cast<int>(nodes.size()); ++n) {
    if (depth[n] == layout.split_depth) roots.push_back(n);
  }
  const auto triangles = [&](int n) { return nodes[n].triangle_end - nodes[n].triangle_begin; };
  std::stable_sort(roots.begin(), roots.end(), [&](int a, int b) { return triangles(a) > triangles(b); });
  std::vector<long> load(count, 0);
  layout.roots.resize(count);
  layout.shard_of.assign(nodes.size(), -1);
  for (int root : roots) {
    const int shard = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    load[shard] += triangles(root);
    layout.roots[shard].push_back(root);
    std::vector<int> stack{root};
    while (!stack.empty()) {
      const int n = stack.back();
      stack.pop_back();
      layout.shard_of[n] = shard;
      for (int c = nodes[n].first_child; c < nodes[n].first_child + nodes[n].child_count; ++c) stack.push_back(c);
    }
  }
  for (std::vector<int>& shard_roots : layout.roots) std::sort(shard_roots.begin(), shard_roots.end());
  return layout;
}

CertificateShard::CertificateShard(Certificates certificates, std::vector<double> contact, int index, int count,
                                   int split_depth, std::vector<int> roots)
    : certificates_(std::move(certificates)),
      contact_(std::move(contact)),
      index_(index),
      count_(count),
      split_depth_(split_depth),
      roots_(std::move(roots)) {}

CertificateShard Certificates::precompute_shard(const SubspaceBvh& bvh, const CertificateParameters& parameters,
                                                int index, int count, const PrecomputeProgress& progress) {
  const auto start = std::chrono::steady_clock::now();
  if (index < 0 || index >= count) {
    throw std::invalid_argument("certificates: shard " + shard_name(index, count) + ": the index must lie in 0.." +
                                std::to_string(count - 1));
  }
  const ShardLayout layout = shard_layout(bvh, count);
  detail::PrecomputeState state = detail::PrecomputeDriver::start(bvh, parameters);
  std::vector<char> selected(bvh.nodes().size());
  for (std::size_t n = 0; n < selected.size(); ++n) selected[n] = layout.shard_of[n] == index;
  detail::PrecomputeDriver::run(bvh, selected, state, progress);
  detail::PrecomputeDriver::finish(state, seconds_since(start));
  std::vector<double> contact;
  for (int root : layout.roots[index]) contact.push_back(state.contact[root]);
  return CertificateShard(std::move(state.certificates), std::move(contact), index, count, layout.split_depth,
                          layout.roots[index]);
}

Certificates Certificates::merge(const SubspaceBvh& bvh, const std::vector<CertificateShard>& shards,
                                 const PrecomputeProgress& progress) {
  const auto start = std::chrono::steady_clock::now();
  if (shards.empty()) throw std::invalid_argument("certificates: nothing to merge (no shards given)");
  const CertificateShard& first = shards.front();
  const int count = first.count();
  for (const CertificateShard& shard : shards) {
    const std::string name = "certificates: shard " + shard_name(shard.index(), shard.count());
    if (shard.count() != count) {
      throw std::invalid_argument(name + " is one of " + std::to_string(shard.count()) + " shards, shard " +
                                  shard_name(first.index(), count) + " one of " + std::to_string(count));
    }
    if (!same_parameters(shard.parameters(), first.parameters())) {
      throw std::invalid_argument(name + " was computed with " + parameters_text(shard.parameters()) + ", shard " +
                                  shard_name(first.index(), count) + " with " + parameters_text(first.parameters()));
    }
    if (shard.key() != key_of(bvh, shard.parameters())) {
      throw std::invalid_argument(name +
                                  " was computed for another mesh, basis, weights or hierarchy, or another set of "
                                  "excluded pairs (key mismatch)");
    }
  }
  const ShardLayout layout = shard_layout(bvh, count);
  std::vector<int> given(count, 0);
  for (const CertificateShard& shard : shards) {
    if (shard.split_depth() != layout.split_depth || shard.subtree_roots() != layout.roots[shard.index()]) {
      throw std::invalid_argument("certificates: shard " + shard_name(shard.index(), count) +
                                  " holds other subtrees than this hierarchy's shard of that index (another version "
                                  "of the shard layout?)");
    }
    if (++given[shard.index()] > 1) {
      throw std::invalid_argument("certificates: shard " + shard_name(shard.index(), count) + " given twice");
    }
  }
  std::string missing;
  for (int i = 0; i < count; ++i) {
    if (!given[i]) missing += (missing.empty() ? "" : ", ") + shard_name(i, count);
  }
  if (!missing.empty()) throw std::invalid_argument("certificates: shards missing: " + missing);

  detail::PrecomputeState state = detail::PrecomputeDriver::start(bvh, first.parameters());
  for (const CertificateShard& shard : shards) {
    for (int n = 0; n < static_cast<int>(bvh.nodes().size()); ++n) {
      if (layout.shard_of[n] == shard.index()) {
        detail::PrecomputeDriver::copy_node(bvh, n, shard.certificates_, state);
      }
    }
    for (std::size_t k = 0; k < shard.roots_.size(); ++k) state.contact[shard.roots_[k]] = shard.contact_[k];
  }
  std::vector<char> selected(bvh.nodes().size());
  for (std::size_t n = 0; n < selected.size(); ++n) selected[n] = layout.shard_of[n] < 0;
  detail::PrecomputeDriver::run(bvh, selected, state, progress);
  detail::PrecomputeDriver::finish(state, seconds_since(start));
  return std::move(state.certificates);
}

std::string CertificateShard::to_bytes() const {
  detail::ByteWriter w;
  for (char c : kMagic) w.put(c);
  w.put(kFormatVersion);
  w.put(kByteOrderMark);
  w.put(static_cast<std::int32_t>(index_));
  w.put(static_cast<std::int32_t>(count_));
  w.put(static_cast<std::int32_t>(split_depth_));
  w.put(static_cast<std::int64_t>(roots_.size()));
  for (int root : roots_) w.put(static_cast<std::int32_t>(root));
  for (double c : contact_) w.put(c);
  const std::string certificates = certificates_.to_bytes();
  w.put(static_cast<std::uint64_t>(certificates.size()));
  w.put_bytes(certificates);
  Fnv1a checksum;
  checksum.add(w.bytes().data(), w.bytes().size());
  w.put(checksum.value());
  return w.bytes();
}

CertificateShard CertificateShard::from_bytes(const std::string& bytes, const SubspaceBvh& bvh,
                                              const std::string& source) {
  detail::ByteReader r(bytes, "certificate shard " + source);
  for (char c : kMagic) {
    if (r.get<char>("magic") != c) r.fail("not a certificate shard (bad magic)");
  }
  const auto version = r.get<std::uint32_t>("version");
  if (version != kFormatVersion) {
    r.fail("format version " + std::to_string(version) + ", this library reads version " +
           std::to_string(kFormatVersion));
  }
  if (r.get<std::uint32_t>("byte-order mark") != kByteOrderMark) r.fail("written on a machine of another byte order");
  if (bytes.size() < r.offset() + sizeof(std::uint64_t)) r.fail("truncated");
  Fnv1a checksum;
  checksum.add(bytes.data(), bytes.size() - sizeof(std::uint64_t));
  std::uint64_t stored;
  std::memcpy(&stored, bytes.data() + bytes.size() - sizeof(stored), sizeof(stored));
  if (stored != checksum.value()) r.fail("checksum mismatch (truncated or corrupt)");

  const int index = r.get<std::int32_t>("shard index");
  const int count = r.get<std::int32_t>("shard count");
  const int split_depth = r.get<std::int32_t>("split depth");
  if (count < 1 || index < 0 || index >= count) r.fail("shard " + shard_name(index, count) + " does not exist");
  const auto root_count = r.get<std::int64_t>("subtree count");
  if (root_count < 0 || root_count > static_cast<std::int64_t>(bvh.nodes().size())) {
    r.fail("holds " + std::to_string(root_count) + " subtrees, the hierarchy has " +
           std::to_string(bvh.nodes().size()) + " nodes");
  }
  std::vector<int> roots(root_count);
  for (int& root : roots) root = r.get<std::int32_t>("subtree roots");
  std::vector<double> contact(root_count);
  for (double& c : contact) {
    c = r.get<double>("contacts");
    if (!(c >= 0.0)) r.fail("invalid contact configuration");  // NaN fails; infinity means none found
  }
  const auto size = r.get<std::uint64_t>("certificate byte count");
  const std::string certificate_bytes = r.get_bytes(size, "certificates");
  if (r.offset() + sizeof(std::uint64_t) != bytes.size()) r.fail("unexpected bytes after the certificates");
  Certificates certificates = Certificates::from_bytes(certificate_bytes, bvh, source + " (its certificates)");
  const ShardLayout layout = shard_layout(bvh, count);
  if (split_depth != layout.split_depth || roots != layout.roots[index]) {
    r.fail("shard " + shard_name(index, count) +
           " holds other subtrees than this hierarchy's shard of that index (another version of the shard layout?)");
  }
  return CertificateShard(std::move(certificates), std::move(contact), index, count, split_depth, std::move(roots));
}

void CertificateShard::write(const std::string& path) const {
  const std::string bytes = to_bytes();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("certificate shard " + path + ": cannot open for writing");
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("certificate shard " + path + ": write failed");
}

CertificateShard CertificateShard::read(const std::string& path, const SubspaceBvh& bvh) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CertificateFileError("certificate shard " + path + ": cannot open");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return from_bytes(bytes, bvh, path);
}

}  // namespace sscc
