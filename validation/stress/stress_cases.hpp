// The cases of `sscc stress`: what each builds (a model; building may throw, which counts
// as a refusal) and the reference its reports are held to.
#pragma once

#include <functional>
#include <random>
#include <string>
#include <vector>

#include "sscc/certificates/certificates.hpp"
#include "sscc/model/subspace_model.hpp"

namespace sscc::validation {

enum class StressReference {
  kBruteForce,   ///< feature_brute_force: every feature of every non-adjacent pair
  kExhaustive,   ///< SelfCcd::query_exhaustive (every triangle pair, the library's leaf code)
  kTraditional,  ///< the traditional query only (the largest meshes)
};

struct StressCase {
  std::string group;  ///< what the case stresses: "translation", "rank", ...
  std::string name;   ///< the condition: "2^40 x size", "r = 300", ...
  std::function<SubspaceModel(std::mt19937_64&)> build;
  StressReference reference = StressReference::kBruteForce;
  bool in_quick = false;  ///< also in the quick run
  /// The largest meshes trade the certificates' accuracy for a precomputation that fits the
  /// run's time: looser radii are as sound as tight ones.
  CertificateParameters certificates = {};
};

std::vector<StressCase> stress_cases();

}  // namespace sscc::validation
