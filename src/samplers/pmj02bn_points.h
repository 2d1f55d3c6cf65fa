// The point sets pbrt-v4's "pmj02bn" sampler draws from: sets of 65536 points in [0,1)^2 in
// which every prefix of 2^m points is a (0,m,2)-net (each elementary interval of area 2^-m
// holds exactly one point): progressive multi-jittered (0,2) sequences with a best-candidate
// (blue-noise) choice of each point among its valid positions (Christensen, Kensler &
// Kilpatrick 2018, "pmj02bn").
//
// pbrt-v4 ships its sets as precomputed tables; eyetrace makes its own with this generator at
// build time (tools/pmj02bn_tables; samplers/pmj02bn_tables.h reads them). Each doubling of
// the sequence puts every new point in one of the sub-quadrants the paper's construction
// opens (the even step: diagonally opposite a point in its cell; the odd step: the two a
// cell's pair of points left) and there among the fine strata that keep every elementary
// interval of the doubled prefix empty. Within a sub-quadrant those are a product of valid x
// strata and valid y strata (see the .cpp), found by a pruned descent over the free bits.
// The best candidate is the farthest (toroidally) from the points before it, among random
// open sub-quadrants: the nets fix each point of a 2^m prefix to within its 2^-m x 2^-m
// square, so the choice is mostly of order, and it spreads the points (min distance 1.2-1.9
// times plain pmj02's, tests/samplers/pmj02bn_points_test.cpp) without the freedom of an
// unconstrained blue-noise set.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

namespace eyetrace {

inline constexpr int kPmj02bnLevels = 16;
inline constexpr uint32_t kPmj02bnPoints = 1u << kPmj02bnLevels;  // per set, as pbrt-v4's tables
inline constexpr int kPmj02bnSets = 5;                            // as pbrt-v4's
// Candidates per point in the best-candidate choice. 1 gives plain pmj02 (the open
// sub-quadrants filled in a random order).
inline constexpr int kPmj02bnCandidates = 10;
// Set s of the sampler's tables is make_pmj02_points(kPmj02bnPoints, kPmj02bnSeed + s, kPmj02bnCandidates).
inline constexpr uint64_t kPmj02bnSeed = 0x706d6a3032626eull;

using Pmj02Points = std::vector<std::array<uint32_t, 2>>;  // 32-bit fixed-point coordinates

// A progressive multi-jittered (0,2) sequence of n points (a power of 2), chosen by `seed`,
// with `candidates` best-candidate trials per point. About 0.15 s for 65536 points.
Pmj02Points make_pmj02_points(uint32_t n, uint64_t seed, int candidates);

}  // namespace eyetrace
