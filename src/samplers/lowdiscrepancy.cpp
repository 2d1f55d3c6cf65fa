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

namespace {

// What every radical inverse in one prime base needs, computed once: the digit loops below run
// per sample dimension, and recomputing the digit count, b^-n and a 64-bit division per digit
// was a quarter of a Halton render (2026-11-27 profile of scenes/peer.pbrt).
struct RadicalInverseBase {
  uint32_t base = 0;
  int n_digits = 0;             // radical_inverse_digits(base)
  uint64_t div_constant = 0;    // ceil(2^64 / base), for exact_quotient
  std::vector<double> inv_pow;  // base^-k for k = 0 .. digits of 2^64 - 1, each by k divisions
};

std::vector<RadicalInverseBase> make_radical_inverse_bases() {
  std::vector<RadicalInverseBase> bases(kPrimeTableSize);
  for (int i = 0; i < kPrimeTableSize; ++i) {
    RadicalInverseBase& b = bases[size_t(i)];
    b.base = uint32_t(prime(i));
    b.n_digits = radical_inverse_digits(int(b.base));
    b.div_constant = ~uint64_t(0) / b.base + 1;
    // The same repeated divisions scale_reversed did, so the scaled values are bit-identical.
    double inv = 1.0;
    b.inv_pow.push_back(inv);
    for (uint64_t rest = ~uint64_t(0); rest != 0; rest /= b.base) b.inv_pow.push_back(inv /= b.base);
  }
  return bases;
}

const RadicalInverseBase& radical_inverse_base(int base_index) {
  static const std::vector<RadicalInverseBase> bases = make_radical_inverse_bases();
  return bases[size_t(base_index)];
}

inline uint64_t reversed_bits64(uint64_t a) {
  return (uint64_t(reverse_bits32(uint32_t(a))) << 32) | reverse_bits32(uint32_t(a >> 32));
}

// floor(a / base) for a < 2^32, exactly, by one multiplication (Lemire, Kaser & Kurz, "Faster
// remainder by direct computation", 2019: c = ceil(2^64 / d) is exact for every 32-bit a).
inline uint32_t exact_quotient(uint32_t a, uint64_t c) { return uint32_t((unsigned __int128)c * a >> 64); }

// Digits reversed into an integer are scaled once at the end: exact up to 2^53, unlike a
// running sum of digit/base^k terms.
inline float scale_reversed(uint64_t reversed, const RadicalInverseBase& b, int n_digits) {
  float u = float(double(reversed) * b.inv_pow[size_t(n_digits)]);
  return std::min(u, kOneMinusEpsilon);
}

// Calls digit(i, d) for the first n base-b digits d of a, least significant first (zeros once a
// is exhausted), dividing in 64 bits only while a needs them.
template <typename DigitFn>
inline void for_each_digit(uint64_t a, const RadicalInverseBase& b, int n, DigitFn&& digit) {
  int i = 0;
  for (; i < n && (a >> 32) != 0; ++i) {
    const uint64_t next = a / b.base;
    digit(i, uint32_t(a - next * b.base));
    a = next;
  }
  for (uint32_t a32 = uint32_t(a); i < n; ++i) {
    const uint32_t next = exact_quotient(a32, b.div_constant);
    digit(i, a32 - next * b.base);
    a32 = next;
  }
}

}  // namespace

float radical_inverse(int base_index, uint64_t a) {
  const RadicalInverseBase& b = radical_inverse_base(base_index);
  // Base 2 (every film sample's x) reverses bits; below 2^62 the digit loop would not stop early.
  if (b.base == 2 && (a >> 62) == 0) {
    const int n = a == 0 ? 0 : 64 - __builtin_clzll(a);
    return n == 0 ? 0.f : scale_reversed(reversed_bits64(a) >> (64 - n), b, n);
  }
  uint64_t reversed = 0;
  int n = 0;
  // Digits past 64 bits of `reversed` lie below 2^-64 of the result: stop before they overflow
  // it (a beyond about 2^42 in the largest bases, as pbrt-v4's RadicalInverse does).
  const uint64_t limit = ~uint64_t(0) / b.base - b.base;
  for (; (a >> 32) != 0 && reversed < limit; ++n) {
    const uint64_t next = a / b.base;
    reversed = reversed * b.base + (a - next * b.base);
    a = next;
  }
  for (uint32_t a32 = uint32_t(a); a32 != 0 && reversed < limit; ++n) {
    const uint32_t next = exact_quotient(a32, b.div_constant);
    reversed = reversed * b.base + (a32 - next * b.base);
    a32 = next;
  }
  return scale_reversed(reversed, b, n);
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
  const RadicalInverseBase& b = radical_inverse_base(base_index);
  uint64_t reversed = 0;
  for_each_digit(a, b, b.n_digits, [&](int, uint32_t digit) {
    // The permutation of this digit depends on every (scrambled) digit above it.
    const uint32_t digit_hash = uint32_t(mix_bits(hash ^ reversed));
    reversed = reversed * b.base + permutation_element(digit, b.base, digit_hash);
  });
  return scale_reversed(reversed, b, b.n_digits);
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
  const RadicalInverseBase& b = radical_inverse_base(base_index);
  const uint16_t* perm = &table_[offset_[base_index]];
  uint64_t reversed = 0;
  // All n digits are permuted, leading zeros included, so the point set is shifted as a whole.
  for_each_digit(a, b, b.n_digits,
                 [&](int i, uint32_t digit) { reversed = reversed * b.base + perm[size_t(i) * b.base + digit]; });
  return scale_reversed(reversed, b, b.n_digits);
}

}  // namespace eyetrace
