#include "samplers/lowdiscrepancy.h"

#include <algorithm>
#include <stdexcept>

#include "samplers/sobol_direction_numbers.h"

namespace eyetrace {

const char* randomization_name(Randomization r) {
  switch (r) {
    case Randomization::None: return "none";
    case Randomization::PermuteDigits: return "permutedigits";
    case Randomization::FastOwen: return "fastowen";
    case Randomization::Owen: return "owen";
  }
  return "?";
}

// Dimension 0 is the van der Corput sequence (identity matrix). Every other dimension follows
// Bratley & Fox's recurrence on the direction numbers v_j = m_j / 2^j, carried as 64-bit
// fractions so that columns past 32 keep their leading bits exactly before truncation.
static std::vector<uint32_t> build_sobol_matrices() {
  std::vector<uint32_t> m(size_t(kSobolDimensions) * kSobolMatrixSize, 0u);
  for (int c = 0; c < 32; ++c) m[c] = 1u << (31 - c);
  size_t pos = 0;
  for (int d = 1; d < kSobolDimensions; ++d) {
    int s = kJoeKuoDirectionNumbers[pos++];
    uint32_t a = kJoeKuoDirectionNumbers[pos++];
    uint64_t v[kSobolMatrixSize];
    for (int j = 0; j < s; ++j) v[j] = uint64_t(kJoeKuoDirectionNumbers[pos++]) << (63 - j);
    for (int j = s; j < kSobolMatrixSize; ++j) {
      v[j] = v[j - s] ^ (v[j - s] >> s);
      for (int k = 1; k < s; ++k)
        if ((a >> (s - 1 - k)) & 1u) v[j] ^= v[j - k];
    }
    for (int j = 0; j < kSobolMatrixSize; ++j) m[size_t(d) * kSobolMatrixSize + j] = uint32_t(v[j] >> 32);
  }
  if (pos != kJoeKuoDirectionNumbersSize) throw std::logic_error("Sobol' direction number table is inconsistent");
  return m;
}

const uint32_t* sobol_matrices() {
  static const std::vector<uint32_t> matrices = build_sobol_matrices();
  return matrices.data();
}

const uint32_t* sobol_byte_tables() {
  static const std::vector<uint32_t> tables = [] {
    // 7 bytes cover the 52 matrix columns; column 52+ would be zero anyway.
    std::vector<uint32_t> t(size_t(kSobolTableDimensions) * 7 * 256, 0u);
    const uint32_t* m = sobol_matrices();
    for (int dim = 0; dim < kSobolTableDimensions; ++dim)
      for (int byte = 0; byte < 7; ++byte)
        for (int value = 0; value < 256; ++value) {
          uint32_t v = 0;
          for (int bit = 0; bit < 8; ++bit) {
            int col = byte * 8 + bit;
            if ((value >> bit & 1) && col < kSobolMatrixSize) v ^= m[size_t(dim) * kSobolMatrixSize + col];
          }
          t[(size_t(dim) * 7 + byte) * 256 + value] = v;
        }
    return t;
  }();
  return tables.data();
}

float randomized_sobol_sample(uint64_t a, int dim, Randomization r, uint32_t seed) {
  switch (r) {
    case Randomization::None: return sobol_sample(a, dim, NoRandomizer());
    case Randomization::PermuteDigits: return sobol_sample(a, dim, BinaryPermuteScrambler(seed));
    case Randomization::FastOwen: return sobol_sample(a, dim, FastOwenScrambler(seed));
    case Randomization::Owen: return sobol_sample(a, dim, OwenScrambler(seed));
  }
  return 0.f;
}

static std::vector<int> first_primes(int n) {
  std::vector<int> primes;
  for (int c = 2; int(primes.size()) < n; ++c) {
    bool is_prime = true;
    for (int p : primes) {
      if (p * p > c) break;
      if (c % p == 0) {
        is_prime = false;
        break;
      }
    }
    if (is_prime) primes.push_back(c);
  }
  return primes;
}

int prime(int index) {
  static const std::vector<int> primes = first_primes(kPrimeTableSize);
  return primes[size_t(index)];
}

int radical_inverse_digits(int base) {
  int n = 0;
  for (double weight = base - 1.0; weight >= 0x1p-24; weight /= base) ++n;
  return n;
}

// Digits reversed into an integer are scaled once at the end: exact up to 2^53, unlike a
// running sum of digit/base^k terms.
static float scale_reversed(uint64_t reversed, int base, int n_digits) {
  double inv = 1.0;
  for (int i = 0; i < n_digits; ++i) inv /= base;
  float u = float(double(reversed) * inv);
  return std::min(u, kOneMinusEpsilon);
}

float radical_inverse(int base_index, uint64_t a) {
  int base = prime(base_index);
  uint64_t reversed = 0;
  int n = 0;
  for (; a != 0; ++n) {
    uint64_t next = a / base;
    reversed = reversed * base + (a - next * base);
    a = next;
  }
  return scale_reversed(reversed, base, n);
}

uint64_t inverse_radical_inverse(uint64_t inverse, int base, int n_digits) {
  uint64_t index = 0;
  for (int i = 0; i < n_digits; ++i) {
    uint64_t digit = inverse % base;
    inverse /= base;
    index = index * base + digit;
  }
  return index;
}

float owen_scrambled_radical_inverse(int base_index, uint64_t a, uint32_t hash) {
  int base = prime(base_index);
  int n = radical_inverse_digits(base);
  uint64_t reversed = 0;
  for (int i = 0; i < n; ++i) {
    uint64_t next = a / base;
    uint32_t digit = uint32_t(a - next * base);
    // The permutation of this digit depends on every (scrambled) digit above it.
    uint32_t digit_hash = uint32_t(mix_bits(hash ^ reversed));
    reversed = reversed * base + permutation_element(digit, uint32_t(base), digit_hash);
    a = next;
  }
  return scale_reversed(reversed, base, n);
}

DigitPermutations::DigitPermutations(uint64_t seed) {
  offset_.resize(kPrimeTableSize + 1);
  size_t total = 0;
  for (int i = 0; i < kPrimeTableSize; ++i) {
    offset_[i] = total;
    total += size_t(prime(i)) * radical_inverse_digits(prime(i));
  }
  offset_[kPrimeTableSize] = total;
  table_.resize(total);
  for (int i = 0; i < kPrimeTableSize; ++i) {
    int base = prime(i), n = radical_inverse_digits(base);
    for (int digit_index = 0; digit_index < n; ++digit_index) {
      uint32_t dseed = uint32_t(hash_values(base, digit_index, seed));
      uint16_t* perm = &table_[offset_[i] + size_t(digit_index) * base];
      for (int v = 0; v < base; ++v) perm[v] = uint16_t(permutation_element(uint32_t(v), uint32_t(base), dseed));
    }
  }
}

float DigitPermutations::scrambled_radical_inverse(int base_index, uint64_t a) const {
  int base = prime(base_index);
  int n = radical_inverse_digits(base);
  const uint16_t* perm = &table_[offset_[base_index]];
  uint64_t reversed = 0;
  // All n digits are permuted, leading zeros included, so the point set is shifted as a whole.
  for (int i = 0; i < n; ++i, perm += base) {
    uint64_t next = a / base;
    reversed = reversed * base + perm[a - next * base];
    a = next;
  }
  return scale_reversed(reversed, base, n);
}

}  // namespace eyetrace
