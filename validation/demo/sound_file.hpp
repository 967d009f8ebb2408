// The demo's sound as a WAV file: 16-bit PCM, one channel, written with libsndfile when the
// build found it (Debian's libsndfile1-dev), so that the library itself never depends on it.
#pragma once

#include <string>
#include <vector>

namespace sscc::validation {

/// Whether this build can write sound files.
bool sound_files_supported();

/// Writes `samples` (any scale: normalised so that the loudest is kPeakLevel of full scale)
/// at `rate` Hz. Throws std::runtime_error when the file cannot be written or the build has
/// no libsndfile.
void write_wav(const std::string& path, const std::vector<double>& samples, int rate);

/// The loudest sample's level, a fraction of 16-bit full scale: headroom against clipping
/// when the file is resampled or mixed.
inline constexpr double kPeakLevel = 0.9;

}  // namespace sscc::validation
