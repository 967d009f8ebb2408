// The precomputation split into shards, for several processes or machines, and their merge
// into the same certificates, byte for byte, as one precomputation's.
//
// The precomputation runs level by level, deepest first, and a node's work items need only
// its children's radii (src/certificates/precompute_driver.hpp), so the subtrees below one
// depth are independent. For `count` shards the split depth D is the shallowest depth with at
// least kSubtreesPerShard * count nodes (else the shallowest with count, else the widest
// level); the subtrees rooted there are dealt to the shards by triangle count, largest first,
// each to the shard with the fewest triangles so far (ties: the lower index). Shard i computes
// every node of its subtrees; Certificates::merge copies each shard's nodes and computes the
// levels above D. The layout depends only on the hierarchy and the count, so every process
// that builds the same hierarchy (same mesh, basis, weights and seed) agrees on it.
//
// The shard file, little-endian binary:
//   magic "SSCCPART", u32 format version, u32 byte-order mark 0x01020304,
//   i32 shard index, i32 shard count, i32 split depth, i64 subtree count K,
//   i32 subtree roots[K], f64 their smallest contact configurations found[K],
//   u64 byte count B, the certificate file (certificates.hpp: Certificates::write) of the
//   shard's nodes, every other entry 0 [B],
//   u64 FNV-1a checksum of everything before it.
// Everything a node's work items compute travels in the embedded certificate file, so a
// shard carries whatever that file holds.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sscc/certificates/certificates.hpp"

namespace sscc {

/// Subtrees per shard aimed at when choosing the split depth: the more, the better the shards
/// balance and the less the merge computes, but a deeper split depth leaves the merge more
/// levels (each of few nodes).
inline constexpr int kSubtreesPerShard = 4;

/// Which shard computes each node, for a hierarchy and a shard count.
struct ShardLayout {
  int count = 0;
  int split_depth = 0;
  /// Per node: the shard that computes it, -1 for the nodes above the split depth (the merge's).
  std::vector<int> shard_of;
  /// Per shard: the roots of its subtrees, in increasing order.
  std::vector<std::vector<int>> roots;
};

/// The layout of `count` shards (count >= 1; throws std::invalid_argument otherwise).
ShardLayout shard_layout(const SubspaceBvh& bvh, int count);

/// The results of one shard (Certificates::precompute_shard), to write to a file or keep in
/// memory until Certificates::merge.
class CertificateShard {
 public:
  int index() const { return index_; }
  int count() const { return count_; }
  int split_depth() const { return split_depth_; }
  /// The roots of the shard's subtrees.
  const std::vector<int>& subtree_roots() const { return roots_; }
  std::uint64_t key() const { return certificates_.key(); }
  const CertificateParameters& parameters() const { return certificates_.parameters(); }
  /// Statistics of the shard's precomputation (zero for shards read from bytes or a file).
  const PrecomputeStats& stats() const { return certificates_.stats(); }

  /// The shard file's bytes (above), e.g. to return from a remote task.
  std::string to_bytes() const;
  /// The shard in `bytes`, checked against bvh. Throws CertificateFileError, naming `source`,
  /// when they are truncated, corrupt, of another version, or computed for another mesh, basis,
  /// weights, tree or shard layout.
  static CertificateShard from_bytes(const std::string& bytes, const SubspaceBvh& bvh,
                                     const std::string& source = "(bytes)");
  /// Writes the shard file; throws std::runtime_error on I/O failure.
  void write(const std::string& path) const;
  /// Reads a shard file for bvh; throws CertificateFileError as from_bytes does, or when the
  /// file cannot be opened.
  static CertificateShard read(const std::string& path, const SubspaceBvh& bvh);

 private:
  friend class Certificates;
  CertificateShard(Certificates certificates, std::vector<double> contact, int index, int count, int split_depth,
                   std::vector<int> roots);

  Certificates certificates_;    // the shard's nodes' entries; 0 elsewhere
  std::vector<double> contact_;  // per subtree root
  int index_ = 0, count_ = 1, split_depth_ = 0;
  std::vector<int> roots_;
};

}  // namespace sscc
