#include "demo/sound_file.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#ifdef SSCC_WITH_SNDFILE
#include <sndfile.h>
#endif

namespace sscc::validation {

bool sound_files_supported() {
#ifdef SSCC_WITH_SNDFILE
  return true;
#else
  return false;
#endif
}

void write_wav(const std::string& path, const std::vector<double>& samples, int rate) {
#ifdef SSCC_WITH_SNDFILE
  double peak = 0.0;
  for (double x : samples) peak = std::max(peak, std::fabs(x));
  const double gain = peak > 0.0 ? kPeakLevel / peak : 0.0;
  std::vector<double> scaled(samples.size());
  std::transform(samples.begin(), samples.end(), scaled.begin(), [&](double x) { return gain * x; });
  SF_INFO info{};
  info.samplerate = rate;
  info.channels = 1;
  info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
  SNDFILE* file = sf_open(path.c_str(), SFM_WRITE, &info);
  if (file == nullptr) throw std::runtime_error("cannot write " + path + ": " + sf_strerror(nullptr));
  const sf_count_t written = sf_write_double(file, scaled.data(), static_cast<sf_count_t>(scaled.size()));
  const int closed = sf_close(file);
  if (written != static_cast<sf_count_t>(scaled.size()) || closed != 0) {
    throw std::runtime_error("cannot write " + path + ": short write");
  }
#else
  (void)samples, (void)rate;
  throw std::runtime_error("cannot write " + path + ": built without libsndfile (Debian: libsndfile1-dev)");
#endif
}

}  // namespace sscc::validation
