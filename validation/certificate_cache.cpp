#include "certificate_cache.hpp"

#include <chrono>
#include <filesystem>

#include "progress_bar.hpp"
#include "sscc/common/timing.hpp"

namespace sscc::validation {

CachedCertificates read_or_precompute_certificates(const SubspaceBvh& bvh, const std::string& path, bool fresh,
                                                   const std::string& who, std::ostream& progress) {
  std::string why = "a fresh precomputation was asked for";
  if (!fresh) {
    try {
      CachedCertificates read{Certificates::read(path, bvh), 0.0};
      progress << who << ": certificates from the cache (" << path << ")\n";
      return read;
    } catch (const CertificateFileError& e) {
      why = e.what();
    }
  }
  progress << who << ": precomputing certificates (" << why << ")\n";
  const auto start = std::chrono::steady_clock::now();
  ProgressBar bar(progress, who + ": certificates");
  CachedCertificates made{Certificates::precompute(bvh, {}, precompute_progress(bar)), 0.0};
  bar.finish();
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  made.certificates.write(path);
  made.seconds = seconds_since(start);
  progress << who << ": certificates done in " << made.seconds << " s, cached in " << path << '\n';
  return made;
}

}  // namespace sscc::validation
