// The pmj02bn sampler's tables, made at build time by tools/pmj02bn_tables from the
// generators in samplers/pmj02bn_points.h and samplers/blue_noise.h and embedded in the
// library (5 x 65536 points of 8 bytes and 48 textures of 128 x 128 ranks of 2 bytes:
// 4 MiB of read-only data, nothing to compute at run time).
#pragma once
#include <array>
#include <cstdint>

#include "core/math.h"
#include "samplers/blue_noise.h"
#include "samplers/pmj02bn_points.h"

namespace eyetrace {

// Point `index` (< kPmj02bnPoints) of set `set` (modulo kPmj02bnSets), fixed point.
std::array<uint32_t, 2> pmj02bn_point(int set, uint32_t index);

// Texture `texture` (modulo kBlueNoiseTextures) at `pixel` (wrapped toroidally, also for
// negative coordinates): (rank + 1/2) / 128^2, in (0, 1).
float blue_noise(int texture, IVec2 pixel);

// The rank behind blue_noise() (row-major, y * size + x), for the tests.
uint16_t blue_noise_rank(int texture, int x, int y);

}  // namespace eyetrace
