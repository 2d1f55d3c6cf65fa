// Low-discrepancy building blocks shared by the samplers: Sobol' generator matrices, radical
// inverses (Halton), their randomisations (digit permutation, Owen scrambling) and the Morton
// (Z-order) code. Everything here is a pure function of its arguments.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"
#include "samplers/hash.h"

namespace eyetrace {

// How a low-discrepancy point set is randomised (pbrt-v4's "randomization" parameter).
enum class Randomization { None, PermuteDigits, FastOwen, Owen };
const char* randomization_name(Randomization r);

inline uint32_t reverse_bits32(uint32_t n) {
  n = (n << 16) | (n >> 16);
  n = ((n & 0x00ff00ffu) << 8) | ((n & 0xff00ff00u) >> 8);
  n = ((n & 0x0f0f0f0fu) << 4) | ((n & 0xf0f0f0f0u) >> 4);
  n = ((n & 0x33333333u) << 2) | ((n & 0xccccccccu) >> 2);
  n = ((n & 0x55555555u) << 1) | ((n & 0xaaaaaaaau) >> 1);
  return n;
}

// Spreads the 32 bits of x over the even bit positions of the result.
inline uint64_t spread_bits2(uint32_t v) {
  uint64_t x = v;
  x = (x ^ (x << 16)) & 0x0000ffff0000ffffull;
  x = (x ^ (x << 8)) & 0x00ff00ff00ff00ffull;
  x = (x ^ (x << 4)) & 0x0f0f0f0f0f0f0f0full;
  x = (x ^ (x << 2)) & 0x3333333333333333ull;
  x = (x ^ (x << 1)) & 0x5555555555555555ull;
  return x;
}

// Morton (Z-order) code: x in the even bits, y in the odd bits.
inline uint64_t encode_morton2(uint32_t x, uint32_t y) { return (spread_bits2(y) << 1) | spread_bits2(x); }

// A 32-bit fixed-point fraction to a float in [0, 1).
inline float bits_to_unit_float(uint32_t v) {
  float u = float(v) * 0x1p-32f;
  return u < kOneMinusEpsilon ? u : kOneMinusEpsilon;
}

// ---- Randomisations of base-2 digits. Each maps a 32-bit fraction to another bijectively. ----

struct NoRandomizer {
  uint32_t operator()(uint32_t v) const { return v; }
};

// Random digit flips (Kollig & Keller 2002): an XOR with one random word per dimension.
struct BinaryPermuteScrambler {
  explicit BinaryPermuteScrambler(uint32_t perm) : permutation(perm) {}
  uint32_t operator()(uint32_t v) const { return permutation ^ v; }
  uint32_t permutation;
};

// Nested uniform scrambling by a hash on reversed bits (Laine & Karras 2011, with Burley's
// 2020 constants, as pbrt-v4): in the reversed word each operation only lets a bit change the
// bits above it, so each output digit depends on the digits before it, as Owen's scrambling.
struct FastOwenScrambler {
  explicit FastOwenScrambler(uint32_t s) : seed(s) {}
  uint32_t operator()(uint32_t v) const {
    v = reverse_bits32(v);
    v ^= v * 0x3d20adeau;
    v += seed;
    v *= (seed >> 16) | 1u;
    v ^= v * 0x05526c56u;
    v ^= v * 0x53a22864u;
    return reverse_bits32(v);
  }
  uint32_t seed;
};

// Owen scrambling done digit by digit: digit b flips when a hash of the digits above it says so.
struct OwenScrambler {
  explicit OwenScrambler(uint32_t s) : seed(s) {}
  uint32_t operator()(uint32_t v) const {
    if (seed & 1) v ^= 1u << 31;
    for (int b = 1; b < 32; ++b) {
      uint32_t mask = (~0u) << (32 - b);
      if (uint32_t(mix_bits((v & mask) ^ seed)) & (1u << b)) v ^= 1u << (31 - b);
    }
    return v;
  }
  uint32_t seed;
};

// ---- Sobol' ----

inline constexpr int kSobolDimensions = 1024;  // dimension 0 (van der Corput) + Joe-Kuo 2..1024
inline constexpr int kSobolMatrixSize = 52;    // columns: indices below 2^52

// Generator matrices, built once from the direction numbers: column c of dimension d is
// entry d * kSobolMatrixSize + c (a 32-bit fraction, most significant bit first).
const uint32_t* sobol_matrices();

// The unrandomised Sobol' point a in dimension `dim` as a 32-bit fraction.
// The first four dimensions (all that ZSobol uses: 0-1 for every sample, 2-3 for its joint lens
// sample; the film and lens position of every sampler) are multiplied a byte of the index at a
// time through precomputed tables: the matrix product is linear over GF(2), so the columns of
// each byte combine independently. Same bits as the column loop, in 7 lookups instead of one
// branch per index bit (the loop was 17% of a Navarro render's time, docs/performance.md).
inline constexpr int kSobolTableDimensions = 4;
const uint32_t* sobol_byte_tables();  // [dim 0..3][byte 0..6][256]

inline uint32_t sobol_bits(uint64_t a, int dim) {
  if (dim < kSobolTableDimensions) {
    const uint32_t* t = sobol_byte_tables() + size_t(dim) * 7 * 256;
    uint32_t v = 0;
    for (int byte = 0; a != 0 && byte < 7; a >>= 8, ++byte) v ^= t[byte * 256 + (a & 0xff)];
    return v;
  }
  const uint32_t* c = sobol_matrices() + size_t(dim) * kSobolMatrixSize;
  uint32_t v = 0;
  for (int i = 0; a != 0 && i < kSobolMatrixSize; a >>= 1, ++i)
    if (a & 1) v ^= c[i];
  return v;
}

template <typename R>
float sobol_sample(uint64_t a, int dim, R randomizer) {
  return bits_to_unit_float(randomizer(sobol_bits(a, dim)));
}

// Samples dimension `dim` of the Sobol' point a with the given randomisation and 32-bit seed.
float randomized_sobol_sample(uint64_t a, int dim, Randomization r, uint32_t seed);

// ---- Radical inverse (Halton) ----

inline constexpr int kPrimeTableSize = 256;  // Halton dimensions available before wrapping
int prime(int index);                        // index in [0, kPrimeTableSize)

// Digits of base b that still change a float in [0, 1): b^-n (b-1) must reach below 2^-24.
int radical_inverse_digits(int base);

float radical_inverse(int base_index, uint64_t a);
// The index whose first n_digits base-b digits, reversed, are `inverse`.
uint64_t inverse_radical_inverse(uint64_t inverse, int base, int n_digits);
// Owen scrambling in base b: each digit is permuted by a hash of the digits above it.
float owen_scrambled_radical_inverse(int base_index, uint64_t a, uint32_t hash);

// One random permutation of the digits per (prime base, digit position), drawn from a seed
// (Faure & Tezuka's random digit permutations, as pbrt-v4's DigitPermutation).
class DigitPermutations {
 public:
  explicit DigitPermutations(uint64_t seed);
  float scrambled_radical_inverse(int base_index, uint64_t a) const;

 private:
  std::vector<uint16_t> table_;  // per base: digits x base entries
  std::vector<size_t> offset_;   // start of each base's block in table_
};

}  // namespace eyetrace
