// Little-endian binary records in memory, for the certificate file and the shard files: values
// appended as their bytes, read back with a check that they are there.
#pragma once

#include <cstring>
#include <string>
#include <utility>

#include "sscc/certificates/certificates.hpp"

namespace sscc::detail {

class ByteWriter {
 public:
  template <typename T>
  void put(const T& value) {
    const auto* p = reinterpret_cast<const char*>(&value);
    bytes_.insert(bytes_.end(), p, p + sizeof(T));
  }
  void put_bytes(const std::string& bytes) { bytes_ += bytes; }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

/// Reads `bytes`; its errors are CertificateFileErrors "<what>: <problem>".
class ByteReader {
 public:
  ByteReader(const std::string& bytes, std::string what) : bytes_(bytes), what_(std::move(what)) {}
  template <typename T>
  T get(const char* field) {
    if (offset_ + sizeof(T) > bytes_.size()) fail(std::string("truncated (ends inside ") + field + ")");
    T value;
    std::memcpy(&value, bytes_.data() + offset_, sizeof(T));
    offset_ += sizeof(T);
    return value;
  }
  std::string get_bytes(std::size_t count, const char* field) {
    if (count > bytes_.size() - offset_) fail(std::string("truncated (ends inside ") + field + ")");
    offset_ += count;
    return bytes_.substr(offset_ - count, count);
  }
  std::size_t offset() const { return offset_; }
  [[noreturn]] void fail(const std::string& problem) const { throw CertificateFileError(what_ + ": " + problem); }

 private:
  const std::string& bytes_;
  std::string what_;
  std::size_t offset_ = 0;
};

}  // namespace sscc::detail
