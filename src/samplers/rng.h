// PCG32 (O'Neill 2014, PCG-XSH-RR 64/32): small state, many independent streams, and
// O(log n) skip-ahead, which lets a sampler jump straight to (sample index, dimension).
#pragma once
#include <cstdint>

#include "samplers/hash.h"

namespace eyetrace {

class Pcg32 {
 public:
  Pcg32() = default;
  Pcg32(uint64_t sequence, uint64_t seed) { set_sequence(sequence, seed); }

  // As the reference pcg32_srandom_r(seed, sequence).
  void set_sequence(uint64_t sequence, uint64_t seed) {
    state_ = 0u;
    inc_ = (sequence << 1u) | 1u;
    next_u32();
    state_ += seed;
    next_u32();
  }
  void set_sequence(uint64_t sequence) { set_sequence(sequence, mix_bits(sequence)); }

  uint32_t next_u32() {
    uint64_t old = state_;
    state_ = old * kMultiplier + inc_;
    uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31));
  }

  // Uniform in [0, 1): 32 random bits scaled, clamped below 1 after rounding to float.
  float next_float() {
    float u = float(next_u32()) * 0x1p-32f;
    return u < 0x1.fffffep-1f ? u : 0x1.fffffep-1f;
  }

  // Jumps `delta` steps ahead (Brown 1994, "Random number generation with arbitrary strides").
  void advance(uint64_t delta) {
    uint64_t cur_mult = kMultiplier, cur_plus = inc_, acc_mult = 1u, acc_plus = 0u;
    while (delta > 0) {
      if (delta & 1) {
        acc_mult *= cur_mult;
        acc_plus = acc_plus * cur_mult + cur_plus;
      }
      cur_plus = (cur_mult + 1) * cur_plus;
      cur_mult *= cur_mult;
      delta /= 2;
    }
    state_ = acc_mult * state_ + acc_plus;
  }

  bool operator==(const Pcg32&) const = default;

 private:
  static constexpr uint64_t kMultiplier = 0x5851f42d4c957f2dull;
  uint64_t state_ = 0x853c49e6748fea9bull;
  uint64_t inc_ = 0xda3e39cb94b95bdbull;
};

}  // namespace eyetrace
