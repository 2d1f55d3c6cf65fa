// Hashing for samplers: every random decision a sampler makes is a hash of (pixel, sample
// index, dimension, seed), never of a shared generator's state, so that images do not depend
// on how work is spread over threads.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace eyetrace {

// 64-bit finaliser (Stafford's "Mix13" variant of MurmurHash3's fmix64, as pbrt-v4's MixBits):
// every input bit affects every output bit with probability close to 1/2.
inline uint64_t mix_bits(uint64_t v) {
  v ^= v >> 31;
  v *= 0x7fb5d329728ea185ull;
  v ^= v >> 27;
  v *= 0x81dadef4bc2dd44dull;
  v ^= v >> 33;
  return v;
}

// Austin Appleby's MurmurHash64A (public domain) over a byte buffer.
inline uint64_t murmur_hash64a(const unsigned char* key, size_t len, uint64_t seed) {
  const uint64_t m = 0xc6a4a7935bd1e995ull;
  const int r = 47;
  uint64_t h = seed ^ (len * m);
  const unsigned char* end = key + 8 * (len / 8);
  for (; key != end; key += 8) {
    uint64_t k;
    std::memcpy(&k, key, sizeof(k));
    k *= m;
    k ^= k >> r;
    k *= m;
    h ^= k;
    h *= m;
  }
  size_t tail = len & 7;
  if (tail > 0) {
    for (size_t i = tail; i-- > 0;) h ^= uint64_t(key[i]) << (8 * i);
    h *= m;
  }
  h ^= h >> r;
  h *= m;
  h ^= h >> r;
  return h;
}

// Hash of the bytes of several trivially copyable values, packed without padding.
template <typename... Args>
uint64_t hash_values(Args... args) {
  static_assert((std::is_trivially_copyable_v<Args> && ...));
  constexpr size_t size = (sizeof(Args) + ... + 0);
  unsigned char buf[size > 0 ? size : 1];
  size_t offset = 0;
  ((std::memcpy(buf + offset, &args, sizeof(Args)), offset += sizeof(Args)), ...);
  return murmur_hash64a(buf, size, 0);
}

// A hash of the values as a float uniform in [0, 1) (24 bits: every value exact in a float and
// below 1): pbrt-v4's HashFloat, for the decisions a renderer makes per ray or per point.
template <typename... Args>
float hash_float(Args... args) {
  return float(hash_values(args...) >> 40) * 0x1p-24f;
}

// The i-th element of a pseudo-random permutation of [0, n) chosen by `seed`, without
// storing the permutation (Kensler 2013, "Correlated Multi-Jittered Sampling"): a bijective
// hash on the next power of two, cycle-walked until it lands below n.
inline uint32_t permutation_element(uint32_t i, uint32_t n, uint32_t seed) {
  uint32_t w = n - 1;
  w |= w >> 1;
  w |= w >> 2;
  w |= w >> 4;
  w |= w >> 8;
  w |= w >> 16;
  do {
    i ^= seed;
    i *= 0xe170893d;
    i ^= seed >> 16;
    i ^= (i & w) >> 4;
    i ^= seed >> 8;
    i *= 0x0929eb3f;
    i ^= seed >> 23;
    i ^= (i & w) >> 1;
    i *= 1 | seed >> 27;
    i *= 0x6935fa69;
    i ^= (i & w) >> 11;
    i *= 0x74dcb303;
    i ^= (i & w) >> 2;
    i *= 0x9e501cc3;
    i ^= (i & w) >> 2;
    i *= 0xc860a3df;
    i &= w;
    i ^= i >> 5;
  } while (i >= n);
  return (i + seed) % n;
}

// A uniform float in [0, 1) from the high bits of a hash.
inline float hash_to_unit_float(uint64_t h) {
  float u = float(uint32_t(h >> 40)) * 0x1p-24f;
  return u < 0x1.fffffep-1f ? u : 0x1.fffffep-1f;
}

}  // namespace eyetrace
