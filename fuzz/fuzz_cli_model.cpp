// The command-line tool's file handling: what `sscc selfccd|precompute|certificates --mesh
// FILE --basis B --weights FILE --certificates FILE` loads, through the same function
// (validation/model_loading.cpp) and the certificate reader. The input is cut at "\n#--\n"
// into a mesh file (its format chosen by the first byte), a basis (a Vega .U file, a text
// matrix, or the text after "polynomial:"), a weights file and a certificate file. Each file
// loads or is refused with an exception; a model that loads and is small gets its hierarchy
// and the certificate file read against it (radii non-negative, or refused).
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz_support.hpp"
#include "model_loading.hpp"
#include "sscc/bvh/subspace_bvh.hpp"
#include "sscc/certificates/certificates.hpp"

namespace {

/// Models past these sizes are not built into a hierarchy (the fuzzer stays fast).
constexpr int kMaxTriangles = 64;
constexpr int kMaxModes = 8;

std::vector<std::string> split(const std::string& bytes, const std::string& separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t at; (at = bytes.find(separator, start)) != std::string::npos; start = at + separator.size()) {
    parts.push_back(bytes.substr(start, at - start));
  }
  parts.push_back(bytes.substr(start));
  return parts;
}

std::string scratch(const std::string& bytes, const std::string& extension) {
  return sscc::fuzz::scratch_file(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), extension);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const char* formats[] = {".off", ".obj", ".ply"};
  const std::uint8_t choice = data[0];
  std::vector<std::string> parts = split(std::string(reinterpret_cast<const char*>(data + 1), size - 1), "\n#--\n");
  parts.resize(4);
  sscc::validation::ModelSource source;
  source.mesh = scratch(parts[0], formats[choice % 3]);
  switch ((choice / 3) % 3) {
    case 0:
      if (parts[1].size() > 8) return 0;  // a mode count, not a novel
      source.basis = "polynomial:" + parts[1];
      break;
    case 1:
      source.basis = scratch(parts[1], ".U");
      break;
    default:
      source.basis = scratch(parts[1], ".basis.txt");
  }
  if (choice & 0x80) source.weights = scratch(parts[2], ".weights");
  try {
    std::ostringstream progress;
    const sscc::SubspaceModel model = sscc::validation::load_model(source, progress);
    if (model.mesh().triangle_count() > kMaxTriangles || model.mode_count() > kMaxModes) return 0;
    const sscc::SubspaceBvh bvh(model);
    const sscc::Certificates certificates = sscc::Certificates::read(scratch(parts[3], ".sscc"), bvh);
    for (int n = 0; n < certificates.node_count(); ++n) {
      if (!(certificates.node_radius(n) >= 0)) std::abort();
    }
  } catch (const std::exception&) {  // refused: a file that is not what it should be
  }
  return 0;
}
