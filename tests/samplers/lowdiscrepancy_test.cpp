// The sampler building blocks against outside references: PCG32's published output, pbrt-v4's
// Sobol' matrices, the Pascal matrix, the net properties that define a (0,2)-sequence, radical
// inverses computed by hand, and the structure every scrambling must keep.
#include "samplers/lowdiscrepancy.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "samplers/hash.h"
#include "samplers/rng.h"

namespace {
namespace EYETRACE_UNITY_ID {

using namespace eyetrace;

TEST(Pcg32, MatchesTheReferenceDemoOutput) {
  // pcg32-demo (O'Neill's pcg-c-basic) seeded with pcg32_srandom_r(&rng, 42, 54), round 1.
  Pcg32 rng(54, 42);
  for (uint32_t expected : {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u, 0x83d2f293u, 0xbfa4784bu, 0xcbed606eu})
    EXPECT_EQ(rng.next_u32(), expected);
}

TEST(Pcg32, AdvanceEqualsStepping) {
  for (uint64_t n : {0ull, 1ull, 2ull, 17ull, 1000ull, 65537ull}) {
    Pcg32 a(7, 3), b(7, 3);
    for (uint64_t i = 0; i < n; ++i) a.next_u32();
    b.advance(n);
    EXPECT_TRUE(a == b) << n;
    EXPECT_EQ(a.next_u32(), b.next_u32());
  }
}

TEST(Pcg32, FloatsStayBelowOne) {
  Pcg32 rng(1, 1);
  for (int i = 0; i < 100000; ++i) {
    float u = rng.next_float();
    ASSERT_TRUE(u >= 0.f && u < 1.f);
  }
}

TEST(Hash, MixBitsAvalanches) {
  // Strict avalanche criterion: flipping any input bit flips each output bit with probability
  // 1/2. With 4096 random inputs a cell's frequency has standard deviation 0.0078; 0.05 is 6.4 sd.
  std::mt19937_64 rng(5);
  std::vector<int> flips(64 * 64, 0);
  const int n = 4096;
  for (int k = 0; k < n; ++k) {
    uint64_t x = rng(), h = mix_bits(x);
    for (int i = 0; i < 64; ++i) {
      uint64_t d = h ^ mix_bits(x ^ (1ull << i));
      for (int o = 0; o < 64; ++o) flips[i * 64 + o] += int((d >> o) & 1);
    }
  }
  for (int c = 0; c < 64 * 64; ++c)
    EXPECT_NEAR(flips[c] / double(n), 0.5, 0.05) << "in " << c / 64 << " out " << c % 64;
}

TEST(Hash, HashValuesDependsOnEveryArgument) {
  EXPECT_EQ(hash_values(1, 2, uint64_t(3)), hash_values(1, 2, uint64_t(3)));
  EXPECT_NE(hash_values(1, 2, uint64_t(3)), hash_values(2, 1, uint64_t(3)));
  EXPECT_NE(hash_values(1, 2, uint64_t(3)), hash_values(1, 2, uint64_t(4)));
}

TEST(PermutationElement, IsAPermutation) {
  for (uint32_t n : {1u, 2u, 3u, 7u, 16u, 100u, 1000u, 4097u})
    for (uint32_t seed : {0u, 1u, 0xdeadbeefu, 0x12345678u}) {
      std::vector<bool> seen(n, false);
      for (uint32_t i = 0; i < n; ++i) {
        uint32_t p = permutation_element(i, n, seed);
        ASSERT_LT(p, n);
        ASSERT_FALSE(seen[p]) << "n " << n << " seed " << seed;
        seen[p] = true;
      }
    }
}

TEST(Morton, InterleavesBits) {
  std::mt19937 rng(9);
  for (int k = 0; k < 1000; ++k) {
    uint32_t x = rng(), y = rng();
    uint64_t expected = 0;
    for (int b = 0; b < 32; ++b)
      expected |= (uint64_t((x >> b) & 1) << (2 * b)) | (uint64_t((y >> b) & 1) << (2 * b + 1));
    ASSERT_EQ(encode_morton2(x, y), expected);
  }
  EXPECT_EQ(encode_morton2(1, 0), 1u);
  EXPECT_EQ(encode_morton2(0, 1), 2u);
  EXPECT_EQ(encode_morton2(3, 3), 15u);
}

// --- Sobol' ---

// pbrt-v4's SobolMatrices32 (src/pbrt/util/sobolmatrices.cpp, Grünschloss's table generated
// from the same Joe-Kuo file), all 52 columns of dimensions 2 and 963.
const uint32_t kPbrtDim2[52] = {
    0x80000000, 0xc0000000, 0x60000000, 0x90000000, 0xe8000000, 0x5c000000, 0x8e000000, 0xc5000000, 0x68800000,
    0x9cc00000, 0xee600000, 0x55900000, 0x80680000, 0xc09c0000, 0x60ee0000, 0x90550000, 0xe8808000, 0x5cc0c000,
    0x8e606000, 0xc5909000, 0x6868e800, 0x9c9c5c00, 0xeeee8e00, 0x5555c500, 0x8000e880, 0xc0005cc0, 0x60008e60,
    0x9000c590, 0xe8006868, 0x5c009c9c, 0x8e00eeee, 0xc5005555, 0x68808000, 0x9cc0c000, 0xee606000, 0x55909000,
    0x8068e800, 0xc09c5c00, 0x60ee8e00, 0x9055c500, 0xe880e880, 0x5cc05cc0, 0x8e608e60, 0xc590c590, 0x68686868,
    0x9c9c9c9c, 0xeeeeeeee, 0x55555555, 0x80000000, 0xc0000000, 0x60000000, 0x90000000};
const uint32_t kPbrtDim963[52] = {
    0x80000000, 0xc0000000, 0xa0000000, 0xd0000000, 0x98000000, 0x14000000, 0x02000000, 0x27000000, 0xcc800000,
    0x8c400000, 0x58a00000, 0x33d00000, 0x2a680000, 0x22bc0000, 0x2a520000, 0xc5ab0000, 0x16df8000, 0x0b604000,
    0x39b76000, 0xd25b3000, 0x6b276800, 0x07153c00, 0x8c8fb600, 0x26cd0f00, 0x736ac780, 0x573d6bc0, 0x639771a0,
    0x3ccb64f0, 0x806a3608, 0x39ba4f04, 0x18d0278e, 0x30ed1bf1, 0x2bf8f986, 0x497528fc, 0x2ebd883b, 0xfc554c2e,
    0x40a83e2b, 0x2d5f431e, 0xd3a779ba, 0xf95568c8, 0xbb2ae813, 0x559e7c23, 0xc3475602, 0x08267f28, 0x9192cfb1,
    0x93cf67f7, 0x60edafb4, 0x73f857f5, 0xfd70c78d, 0xfcba6bdc, 0x4352f18c, 0x982c24e7};

TEST(SobolMatrices, MatchPbrtV4Table) {
  const uint32_t* m = sobol_matrices();
  for (int c = 0; c < kSobolMatrixSize; ++c) {
    EXPECT_EQ(m[2 * kSobolMatrixSize + c], kPbrtDim2[c]) << "dim 2 column " << c;
    EXPECT_EQ(m[963 * kSobolMatrixSize + c], kPbrtDim963[c]) << "dim 963 column " << c;
  }
}

TEST(SobolMatrices, FirstDimensionIsVanDerCorput) {
  std::mt19937 rng(2);
  for (int k = 0; k < 10000; ++k) {
    uint32_t i = rng();
    ASSERT_EQ(sobol_bits(i, 0), reverse_bits32(i));
  }
}

TEST(SobolMatrices, ByteTablesEqualTheColumnProduct) {
  // The tabulated dimensions (a byte of the index at a time) against the definition: the XOR
  // of the generator matrix's columns selected by the index's set bits, one bit at a time.
  std::mt19937_64 rng(3);
  for (int d = 0; d < kSobolTableDimensions + 1; ++d) {
    const uint32_t* c = sobol_matrices() + size_t(d) * kSobolMatrixSize;
    for (int k = 0; k < 20000; ++k) {
      uint64_t a = rng() >> (12 + k % 40);  // indices of 12 to 52 bits
      uint32_t expected = 0;
      for (int i = 0; i < kSobolMatrixSize; ++i)
        if ((a >> i) & 1) expected ^= c[i];
      ASSERT_EQ(sobol_bits(a, d), expected) << "dim " << d << " index " << a;
    }
  }
}

TEST(SobolMatrices, SecondDimensionIsThePascalMatrix) {
  // Column c, row r (from the most significant bit) is binomial(c, r) mod 2, which by Lucas's
  // theorem is 1 exactly when the bits of r are a subset of the bits of c.
  const uint32_t* m = sobol_matrices() + kSobolMatrixSize;
  for (uint32_t c = 0; c < 32; ++c)
    for (uint32_t r = 0; r < 32; ++r) EXPECT_EQ((m[c] >> (31 - r)) & 1u, (r & c) == r ? 1u : 0u) << c << " " << r;
}

TEST(SobolMatrices, EveryDimensionIsStratifiedIn1D) {
  // Each generator matrix is nonsingular upper triangular, so the first 2^m points of every
  // dimension fall one per interval of length 2^-m.
  const int m = 10, n = 1 << m;
  for (int d = 0; d < kSobolDimensions; ++d) {
    std::vector<bool> seen(n, false);
    for (int i = 0; i < n; ++i) {
      uint32_t cell = sobol_bits(uint64_t(i), d) >> (32 - m);
      ASSERT_FALSE(seen[cell]) << "dimension " << d;
      seen[cell] = true;
    }
  }
}

TEST(SobolMatrices, FirstTwoDimensionsFormA02Sequence) {
  // Every aligned block of 2^m points has one point in each elementary interval 2^-a x 2^-(m-a).
  for (int m = 0; m <= 12; ++m)
    for (uint64_t block : {0ull, 1ull, 5ull}) {
      uint64_t n = 1ull << m;
      for (int a = 0; a <= m; ++a) {
        std::set<uint64_t> cells;
        for (uint64_t i = block * n; i < (block + 1) * n; ++i) {
          uint64_t x = a == 0 ? 0 : sobol_bits(i, 0) >> (32 - a);
          uint64_t y = a == m ? 0 : sobol_bits(i, 1) >> (32 - (m - a));
          cells.insert((x << 32) | y);
        }
        ASSERT_EQ(cells.size(), n) << "m " << m << " a " << a << " block " << block;
      }
    }
}

// --- Scrambling ---

// A scrambler is a nested permutation when the first k output bits depend only on the first
// k input bits, and it permutes the 2^k prefixes; then it keeps every net a net.
template <typename Scramble>
void expect_nested_permutation(const Scramble& scramble) {
  std::mt19937 rng(4);
  for (int k : {1, 4, 8}) {
    std::set<uint32_t> prefixes;
    for (uint32_t p = 0; p < (1u << k); ++p) {
      uint32_t v = p << (32 - k);
      uint32_t out = scramble(v) >> (32 - k);
      prefixes.insert(out);
      for (int t = 0; t < 8; ++t) {
        uint32_t w = v | (rng() >> k);  // same prefix, other low bits
        ASSERT_EQ(scramble(w) >> (32 - k), out) << "k " << k;
      }
    }
    EXPECT_EQ(prefixes.size(), 1u << k);
  }
}

TEST(Scramblers, AreNestedPermutations) {
  for (uint32_t seed : {0u, 1u, 0x9e3779b9u, 0xffffffffu}) {
    expect_nested_permutation(BinaryPermuteScrambler(seed));
    expect_nested_permutation(FastOwenScrambler(seed));
    expect_nested_permutation(OwenScrambler(seed));
  }
}

TEST(Scramblers, ChangeTheirInput) {
  // A randomisation that left points in place would be no randomisation.
  int changed_fast = 0, changed_owen = 0;
  for (uint32_t v = 0; v < 1000; ++v) {
    changed_fast += FastOwenScrambler(12345u)(v << 20) != (v << 20);
    changed_owen += OwenScrambler(12345u)(v << 20) != (v << 20);
  }
  EXPECT_GT(changed_fast, 900);
  EXPECT_GT(changed_owen, 900);
}

// --- Radical inverse ---

TEST(RadicalInverse, MatchesHandComputedValues) {
  EXPECT_EQ(prime(0), 2);
  EXPECT_EQ(prime(1), 3);
  EXPECT_EQ(prime(2), 5);
  EXPECT_EQ(prime(99), 541);  // the 100th prime
  EXPECT_FLOAT_EQ(radical_inverse(0, 1), 0.5f);
  EXPECT_FLOAT_EQ(radical_inverse(0, 6), 0.375f);  // 110b -> 0.011b
  EXPECT_FLOAT_EQ(radical_inverse(1, 1), 1.f / 3.f);
  EXPECT_FLOAT_EQ(radical_inverse(1, 5), 2.f / 3.f + 1.f / 9.f);   // 12 in base 3 -> 0.21
  EXPECT_FLOAT_EQ(radical_inverse(2, 7), 2.f / 5.f + 1.f / 25.f);  // 12 in base 5 -> 0.21
  EXPECT_EQ(radical_inverse(0, 0), 0.f);
}

TEST(RadicalInverse, InverseRoundTrips) {
  for (int base : {2, 3, 5, 7})
    for (uint64_t i = 0; i < 200 && i < uint64_t(std::pow(base, 6)); ++i) {
      int digits = 6;
      uint64_t reversed = inverse_radical_inverse(i, base, digits);
      EXPECT_EQ(inverse_radical_inverse(reversed, base, digits), i);
    }
}

// The first b^k points of a (randomised) radical inverse in base b hit every b^-k interval once
// (for b^k up to 1024, where float resolution is still far finer than the intervals).
// Unscrambled points sit exactly on interval starts, so for them the nearest start is taken.
template <typename F>
void expect_stratified(int base_index, F value, bool on_interval_starts) {
  int base = prime(base_index);
  for (int n = base; n <= 1024; n *= base) {
    std::vector<bool> seen(size_t(n), false);
    for (int i = 0; i < n; ++i) {
      float u = value(uint64_t(i));
      ASSERT_TRUE(u >= 0.f && u < 1.f);
      double scaled = double(u) * n;
      int cell = on_interval_starts ? int(std::lround(scaled)) : std::min(n - 1, int(scaled));
      ASSERT_FALSE(seen[size_t(cell)]) << "base " << base << " n " << n;
      seen[size_t(cell)] = true;
    }
  }
}

TEST(RadicalInverse, RandomisationsKeepStratification) {
  DigitPermutations perms(77);
  for (int b : {0, 1, 2, 3, 10}) {
    expect_stratified(
        b, [&](uint64_t i) { return radical_inverse(b, i); }, true);
    expect_stratified(
        b, [&](uint64_t i) { return perms.scrambled_radical_inverse(b, i); }, false);
    expect_stratified(
        b, [&](uint64_t i) { return owen_scrambled_radical_inverse(b, i, 0xabcdefu); }, false);
  }
}

// Indices past 2^32 (a 4096x4096 Halton render passes 2^32 at 160 spp) take the 64-bit digit
// loop until they fit in 32 bits, then an exact multiply-shift quotient: both against plain
// long-double arithmetic and 64-bit division written here.
std::vector<uint64_t> indices_across_two_to_the_32() {
  std::vector<uint64_t> a = {0,
                             1,
                             2,
                             12345,
                             0xfffffffeull,
                             0xffffffffull,
                             0x100000000ull,
                             0x100000001ull,
                             0x2540be3ffull,
                             ~uint64_t(0) >> 11,
                             ~uint64_t(0)};
  std::mt19937_64 rng(7);
  for (int i = 0; i < 200; ++i) a.push_back(rng() >> (rng() % 40));
  return a;
}

long double reference_radical_inverse(uint64_t a, uint64_t base) {
  long double u = 0, w = 1.0L / base;
  for (; a != 0; a /= base, w /= base) u += (a % base) * w;
  return u;
}

TEST(RadicalInverse, SixtyFourBitIndicesMatchPlainArithmetic) {
  for (int b : {0, 1, 2, 9, 100, kPrimeTableSize - 1})
    for (uint64_t a : indices_across_two_to_the_32()) {
      const long double expected = reference_radical_inverse(a, uint64_t(prime(b)));
      EXPECT_NEAR(radical_inverse(b, a), double(expected), 1e-7 + 1e-7 * double(expected)) << prime(b) << " " << a;
    }
}

// Owen scrambling's digits from the definition (a permutation per digit, seeded by the digits
// above it), with 64-bit division throughout.
float reference_owen(int b, uint64_t a, uint32_t hash) {
  const uint64_t base = uint64_t(prime(b));
  int n = 0;  // digits until (base - 1) base^-n falls below float's 2^-24
  for (long double w = base - 1.0L; w >= 0x1p-24L; w /= base) ++n;
  uint64_t reversed = 0;
  long double scale = 1;
  for (int i = 0; i < n; ++i, a /= base, scale /= base)
    reversed =
        reversed * base + permutation_element(uint32_t(a % base), uint32_t(base), uint32_t(mix_bits(hash ^ reversed)));
  return float(std::min<long double>(reversed * scale, 0x1.fffffep-1L));
}

TEST(RadicalInverse, OwenScrambledSixtyFourBitIndicesMatchTheDefinition) {
  for (int b : {0, 1, 2, 9, 100, kPrimeTableSize - 1})
    for (uint64_t a : indices_across_two_to_the_32())
      EXPECT_NEAR(owen_scrambled_radical_inverse(b, a, 0x5eedu), reference_owen(b, a, 0x5eedu), 2e-7)
          << prime(b) << " " << a;
}

// Indices that share their k lowest base-b digits share the first k permuted digits of their
// inverses (the same b^-k interval), on either side of 2^32; indices that differ in the lowest
// digit land in different intervals of width 1/b.
TEST(RadicalInverse, DigitPermutationsOfSixtyFourBitIndicesKeepLowDigits) {
  DigitPermutations perms(3);
  for (int b : {0, 1, 2, 9}) {
    const uint64_t base = uint64_t(prime(b)), bk = base * base * base;
    for (uint64_t a : indices_across_two_to_the_32()) {
      const uint64_t low = a % bk, far = low + bk * ((~uint64_t(0) - low) / bk / 3);
      const double u1 = perms.scrambled_radical_inverse(b, low) * double(bk);
      const double u2 = perms.scrambled_radical_inverse(b, far) * double(bk);
      EXPECT_EQ(std::floor(u1), std::floor(u2)) << base << " " << a;
      const uint64_t other = low % base == 0 ? far + 1 : far - 1;
      EXPECT_NE(std::floor(perms.scrambled_radical_inverse(b, other) * double(base)),
                std::floor(u2 / double(base * base)));
    }
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
