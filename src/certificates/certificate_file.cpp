// The certificate file, little-endian binary:
//   magic "SSCCCERT", u32 format version, u32 byte-order mark 0x01020304,
//   u64 key (Certificates::key_of), parameters (f64 epsilon, f64 global radius scale,
//   i32 max depth, i32 max evaluations), i64 node count N, f64 R_global,
//   f64 R_n[N], f64 sibling radii[N][4], u64 FNV-1a checksum of everything before it.
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include "certificates/binary_io.hpp"
#include "common/fnv1a.hpp"
#include "sscc/certificates/certificates.hpp"

namespace sscc {

namespace {

constexpr char kMagic[8] = {'S', 'S', 'C', 'C', 'C', 'E', 'R', 'T'};
// 2: the pair bounds pad the rounding of the positions a query computes; files of version 1
// were computed without it and are refused (recompute them).
constexpr std::uint32_t kFormatVersion = 2;
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
  return hash.value();
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
  w.put(static_cast<std::int64_t>(node_radius_.size()));
  w.put(global_radius_);
  for (double r : node_radius_) w.put(r);
  for (const auto& radii : sibling_radius_) {
    for (double r : radii) w.put(r);
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
  if (r.offset() + sizeof(std::uint64_t) != bytes.size()) r.fail("unexpected bytes after the radii");
  return certificates;
}

}  // namespace sscc
