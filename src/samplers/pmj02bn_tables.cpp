#include "samplers/pmj02bn_tables.h"

// Defined by the assembler file tools/pmj02bn_tables writes (build/generated/pmj02bn_tables.cpp).
extern "C" {
extern const uint32_t eyetrace_pmj02bn_points[];       // [set][index][x, y]
extern const uint16_t eyetrace_blue_noise_textures[];  // [texture][y][x]
}

namespace eyetrace {

std::array<uint32_t, 2> pmj02bn_point(int set, uint32_t index) {
  const size_t i = (size_t(set % kPmj02bnSets) * kPmj02bnPoints + index) * 2;
  return {eyetrace_pmj02bn_points[i], eyetrace_pmj02bn_points[i + 1]};
}

uint16_t blue_noise_rank(int texture, int x, int y) {
  const size_t t = size_t(((texture % kBlueNoiseTextures) + kBlueNoiseTextures) % kBlueNoiseTextures);
  return eyetrace_blue_noise_textures[(t * kBlueNoiseSize + size_t(y)) * kBlueNoiseSize + size_t(x)];
}

float blue_noise(int texture, IVec2 pixel) {
  const int x = ((pixel.x % kBlueNoiseSize) + kBlueNoiseSize) % kBlueNoiseSize;
  const int y = ((pixel.y % kBlueNoiseSize) + kBlueNoiseSize) % kBlueNoiseSize;
  return (float(blue_noise_rank(texture, x, y)) + 0.5f) * (1.f / (kBlueNoiseSize * kBlueNoiseSize));
}

}  // namespace eyetrace
