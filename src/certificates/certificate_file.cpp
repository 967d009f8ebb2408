// The certificate file, little-endian binary:
//   magic "SSCCCERT", u32 format version, u32 byte-order mark 0x01020304,
//   u64 key (Certificates::key_of), parameters (f64 epsilon, f64 global radius scale,
//   i32 max depth, i32 max evaluations, f64 pair reach), i64 node count N, f64 R_global,
//   f64 R_n[N], f64 sibling radii[N][4], i32 sibling pair certificate index[N][4],
//   i64 pair certificate count P, (f64 radius, i32 first child)[P],
//   u64 FNV-1a checksum of everything before it.
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

#include "certificates/binary_io.hpp"
#include "common/fnv1a.hpp"
#include "query/descent.hpp"
#include "sscc/certificates/certificates.hpp"

namespace sscc {

namespace {

constexpr char kMagic[8] = {'S', 'S', 'C', 'C', 'C', 'E', 'R', 'T'};
// 2: the pair bounds pad the rounding of the positions a query computes; files of version 1
// were computed without it and are refused (recompute them).
// 3: pair certificates below the sibling pairs (and the pair reach among the parameters);
// files of version 2 have none and are refused (recompute them).
constexpr std::uint32_t kFormatVersion = 3;
constexpr std::uint32_t kByteOrderMark = 0x01020304;

using Reader = detail::ByteReader;
using Writer = detail::ByteWriter;

}  // namespace

std::uint64_t Certificates::key_of(const SubspaceBvh& bvh, const CertificateParameters& parameters) {
  const SubspaceModel& model = bvh.model();
  const TriangleMesh& mesh = model.mesh();
  Fnv1a hash;
  hash.add_value(kFormatVersion);
  hash.add_value(mesh.vertex_count());
  for (const Eigen::Vector3d& p : mesh.vertices()) hash.add(p.data(), 3 * sizeof(double));
  hash.add_value(mesh.triangle_count());
  hash.add(mesh.triangles().data(), mesh.triangles().size() * sizeof(Triangle));
  hash.add_value(model.mode_count());
  hash.add(model.scaled_basis().data(), static_cast<std::size_t>(model.scaled_basis().size()) * sizeof(double));
  // Only a non-empty set enters the key: files of models without one keep theirs.
  if (const ExcludedPairs& excluded = model.excluded_pairs(); !excluded.empty()) {
    hash.add_value(excluded.size());
    hash.add(excluded.pairs().data(), excluded.pairs().size() * sizeof(std::pair<int, int>));
  }
  for (const SubspaceBvh::Node& node : bvh.nodes()) {
    const int fields[4] = {node.first_child, node.child_count, node.triangle_begin, node.triangle_end};
    hash.add(fields, sizeof(fields));
  }
  hash.add(bvh.triangle_order().data(), bvh.triangle_order().size() * sizeof(int));
  hash.add_value(parameters.epsilon);
  hash.add_value(parameters.global_radius_scale);
  hash.add_value(parameters.max_subdivision_depth);
  hash.add_value(parameters.max_evaluations_per_pair);
  hash.add_value(parameters.pair_reach);
  return hash.value();
}

std::string Certificates::pair_certificate_problem(const SubspaceBvh& bvh) const {
  const auto count = static_cast<std::int64_t>(pairs_.size());
  const auto& nodes = bvh.nodes();
  // Walks the tree of pair k (nodes x, y), its children in the traversal's order.
  std::string problem;
  std::vector<char> seen(pairs_.size(), 0);  // each certificate belongs to one pair
  const auto walk = [&](const auto& self, std::int64_t k, int x, int y) -> void {
    if (!problem.empty()) return;
    if (seen[static_cast<std::size_t>(k)]++) {
      problem = "pair certificate " + std::to_string(k) + " reached twice";
      return;
    }
    const PairCertificate& pair = pairs_[static_cast<std::size_t>(k)];
    if (std::isnan(pair.radius) || pair.radius < 0.0 || pair.radius > global_radius_) {
      problem = "radius of pair certificate " + std::to_string(k);
      return;
    }
    if (pair.first_child < 0) return;
    const SubspaceBvh::Node& nx = nodes[x];
    const SubspaceBvh::Node& ny = nodes[y];
    if (nx.is_leaf() && ny.is_leaf()) {
      problem = "pair certificate " + std::to_string(k) + " of two leaves has children";
      return;
    }
    const bool split_x = detail::splits_first(nx, ny);
    const SubspaceBvh::Node& split = split_x ? nx : ny;
    if (pair.first_child <= k || pair.first_child + split.child_count > count) {
      problem = "children of pair certificate " + std::to_string(k) + " out of range";
      return;
    }
    for (int i = 0; i < split.child_count; ++i) {
      const int c = split.first_child + i;
      self(self, pair.first_child + i, split_x ? c : x, split_x ? y : c);
    }
  };
  for (int a = 0; a < static_cast<int>(nodes.size()) && problem.empty(); ++a) {
    for (int position = 0; position < kBranchingFactor; ++position) {
      const int k = sibling_tree_[a][position];
      if (k == -1) continue;
      const int b = first_sibling_[a] + position;
      if (a == 0 || k < 0 || k >= count || b == a || b >= static_cast<int>(nodes.size()) ||
          first_sibling_[b] != first_sibling_[a] || sibling_tree_[b][a - first_sibling_[a]] != k) {
        return "sibling pair certificate index of node " + std::to_string(a) + " invalid";
      }
      if (a < b) walk(walk, k, a, b);
    }
  }
  return problem;
}

std::vector<PairCertificate> Certificates::pair_tree(const SubspaceBvh& bvh, int a, int b) const {
  std::vector<PairCertificate> tree;
  const int root = sibling_pair_certificate(a, b);
  if (root < 0) return tree;
  // The same depth-first layout as the precomputation's: a pair's children block, then each
  // child's subtree in turn.
  const auto copy = [&](const auto& self, int from, std::size_t to, int x, int y) -> void {
    const int first = pairs_[static_cast<std::size_t>(from)].first_child;
    if (first < 0) return;
    const SubspaceBvh::Node& nx = bvh.nodes()[x];
    const SubspaceBvh::Node& ny = bvh.nodes()[y];
    const bool split_x = detail::splits_first(nx, ny);
    const SubspaceBvh::Node& split = split_x ? nx : ny;
    const std::size_t block = tree.size();
    tree[to].first_child = static_cast<std::int32_t>(block);
    for (int i = 0; i < split.child_count; ++i) tree.push_back(pairs_[static_cast<std::size_t>(first + i)]);
    for (int i = 0; i < split.child_count; ++i) {
      const int c = split.first_child + i;
      self(self, first + i, block + static_cast<std::size_t>(i), split_x ? c : x, split_x ? y : c);
    }
  };
  tree.push_back(pairs_[static_cast<std::size_t>(root)]);
  copy(copy, root, 0, a, b);
  return tree;
}

std::string Certificates::to_bytes() const {
  Writer w;
  for (char c : kMagic) w.put(c);
  w.put(kFormatVersion);
  w.put(kByteOrderMark);
  w.put(key_);
  w.put(parameters_.epsilon);
  w.put(parameters_.global_radius_scale);
  w.put(static_cast<std::int32_t>(parameters_.max_subdivision_depth));
  w.put(static_cast<std::int32_t>(parameters_.max_evaluations_per_pair));
  w.put(parameters_.pair_reach);
  w.put(static_cast<std::int64_t>(node_radius_.size()));
  w.put(global_radius_);
  for (double r : node_radius_) w.put(r);
  for (const auto& radii : sibling_radius_) {
    for (double r : radii) w.put(r);
  }
  for (const auto& trees : sibling_tree_) {
    for (int k : trees) w.put(static_cast<std::int32_t>(k));
  }
  w.put(static_cast<std::int64_t>(pairs_.size()));
  for (const PairCertificate& pair : pairs_) {
    w.put(pair.radius);
    w.put(pair.first_child);
  }
  Fnv1a checksum;
  checksum.add(w.bytes().data(), w.bytes().size());
  w.put(checksum.value());
  return w.bytes();
}

void Certificates::write(const std::string& path) const {
  const std::string bytes = to_bytes();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("certificate file " + path + ": cannot open for writing");
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("certificate file " + path + ": write failed");
}

Certificates Certificates::read(const std::string& path, const SubspaceBvh& bvh) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CertificateFileError("certificate file " + path + ": cannot open");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return from_bytes(bytes, bvh, path);
}

Certificates Certificates::from_bytes(const std::string& bytes, const SubspaceBvh& bvh, const std::string& source) {
  Reader r(bytes, "certificate file " + source);
  for (char c : kMagic) {
    if (r.get<char>("magic") != c) r.fail("not a certificate file (bad magic)");
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

  const auto key = r.get<std::uint64_t>("key");
  CertificateParameters parameters;
  parameters.epsilon = r.get<double>("parameters");
  parameters.global_radius_scale = r.get<double>("parameters");
  parameters.max_subdivision_depth = r.get<std::int32_t>("parameters");
  parameters.max_evaluations_per_pair = r.get<std::int32_t>("parameters");
  parameters.pair_reach = r.get<double>("parameters");
  if (const std::string problem = problem_with(parameters); !problem.empty()) r.fail("invalid parameters: " + problem);
  const auto node_count = r.get<std::int64_t>("node count");
  if (node_count != static_cast<std::int64_t>(bvh.nodes().size())) {
    r.fail("holds " + std::to_string(node_count) + " nodes, the hierarchy has " + std::to_string(bvh.nodes().size()) +
           " (stale: computed for another mesh, basis or hierarchy)");
  }
  Certificates certificates(bvh, parameters);
  if (certificates.key_ != key) {
    r.fail(
        "stale: computed for another mesh, basis, weights or hierarchy, or another set of excluded pairs "
        "(key mismatch; a model excluding its rest contacts and one that does not have different keys)");
  }
  const auto valid = [](double x) { return x >= 0.0; };  // NaN fails; infinity means never
  certificates.global_radius_ = r.get<double>("global radius");
  if (!valid(certificates.global_radius_)) r.fail("invalid global radius");
  for (double& radius : certificates.node_radius_) {
    radius = r.get<double>("node radii");
    if (!valid(radius) || radius > certificates.global_radius_) r.fail("invalid node radius");
  }
  for (auto& radii : certificates.sibling_radius_) {
    for (double& radius : radii) {
      radius = r.get<double>("sibling radii");
      if (!valid(radius) || radius > certificates.global_radius_) r.fail("invalid sibling radius");
    }
  }
  for (auto& trees : certificates.sibling_tree_) {
    for (int& k : trees) k = r.get<std::int32_t>("sibling pair certificates");
  }
  const auto pair_count = r.get<std::int64_t>("pair certificate count");
  if (pair_count < 0 || static_cast<std::uint64_t>(pair_count) > (bytes.size() - r.offset()) / 12) {
    r.fail("invalid pair certificate count " + std::to_string(pair_count));
  }
  certificates.pairs_.resize(static_cast<std::size_t>(pair_count));
  for (PairCertificate& pair : certificates.pairs_) {
    pair.radius = r.get<double>("pair certificates");
    pair.first_child = r.get<std::int32_t>("pair certificates");
  }
  if (const std::string problem = certificates.pair_certificate_problem(bvh); !problem.empty()) {
    r.fail("invalid pair certificates: " + problem);
  }
  if (r.offset() + sizeof(std::uint64_t) != bytes.size()) r.fail("unexpected bytes after the radii");
  return certificates;
}

}  // namespace sscc
