// 64-bit FNV-1a: identifies content (certificate keys, file checksums). Not cryptographic:
// it detects stale inputs and corruption, not tampering.
#pragma once

#include <cstddef>
#include <cstdint>

namespace sscc {

class Fnv1a {
 public:
  void add(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) hash_ = (hash_ ^ p[i]) * 0x100000001b3ULL;
  }
  template <typename T>
  void add_value(const T& value) {
    add(&value, sizeof(T));
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

}  // namespace sscc
