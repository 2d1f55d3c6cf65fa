// FNV-1a, 64 bits: a fast checksum and fingerprint (render states, scene fingerprints), not a
// cryptographic hash.
#pragma once
#include <cstdint>
#include <string_view>

namespace eyetrace {

inline uint64_t fnv1a(std::string_view bytes, uint64_t h = 0xcbf29ce484222325ull) {
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  return h;
}

}  // namespace eyetrace
