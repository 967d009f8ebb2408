// Shared by the fuzz targets: the readers take paths, so each input is written to a
// per-process scratch file with the extension the reader dispatches on.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

namespace sscc::fuzz {

/// Writes `data` to a scratch file ending in `extension` (".off", ".U", ...) and returns its path.
inline std::string scratch_file(const std::uint8_t* data, std::size_t size, const std::string& extension) {
  const std::string path = "/tmp/sscc_fuzz_" + std::to_string(getpid()) + extension;
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

}  // namespace sscc::fuzz
