// Any bytes as the body of a certificate file of a fixed small model (parameters, node
// count and radii), framed with the right magic, version, byte-order mark, key and checksum,
// so that the input reaches the validation of what a forged file holds: certificates whose
// radii are non-negative and at most the global radius, or a CertificateFileError.
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "fuzz_support.hpp"
#include "sscc/certificates/certificates.hpp"
#include "sscc/model/polynomial_basis.hpp"

namespace {

const sscc::SubspaceBvh& model_bvh() {
  static const auto bvh = [] {
    const sscc::TriangleMesh mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}},
                                  {{0, 1, 2}, {3, 4, 5}});
    return std::make_unique<sscc::SubspaceBvh>(
        sscc::SubspaceModel(mesh, sscc::polynomial_basis(mesh, 3), Eigen::VectorXd::Ones(3)));
  }();
  return *bvh;
}

std::uint64_t fnv1a(const std::string& bytes) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (unsigned char c : bytes) hash = (hash ^ c) * 0x100000001b3ULL;
  return hash;
}

template <typename T>
void append(std::string& bytes, const T& value) {
  bytes.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  constexpr std::size_t kParameterBytes = 24;  // f64 epsilon, f64 scale, i32 depth, i32 evaluations
  if (size < kParameterBytes) return 0;
  sscc::CertificateParameters parameters;
  std::memcpy(&parameters.epsilon, data, 8);
  std::memcpy(&parameters.global_radius_scale, data + 8, 8);
  std::memcpy(&parameters.max_subdivision_depth, data + 16, 4);
  std::memcpy(&parameters.max_evaluations_per_pair, data + 20, 4);
  std::string file("SSCCCERT", 8);
  append(file, std::uint32_t{2});  // the format version the library reads
  append(file, std::uint32_t{0x01020304});
  append(file, sscc::Certificates::key_of(model_bvh(), parameters));
  file.append(reinterpret_cast<const char*>(data), size);
  append(file, fnv1a(file));
  const std::string path =
      sscc::fuzz::scratch_file(reinterpret_cast<const std::uint8_t*>(file.data()), file.size(), ".sscc");
  try {
    const sscc::Certificates c = sscc::Certificates::read(path, model_bvh());
    if (!sscc::problem_with(c.parameters()).empty()) std::abort();
    for (int n = 0; n < c.node_count(); ++n) {
      if (!(c.node_radius(n) >= 0.0) || c.node_radius(n) > c.global_radius()) std::abort();
    }
  } catch (const sscc::CertificateFileError&) {
  }
  return 0;
}
