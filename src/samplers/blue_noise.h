// Blue-noise textures for the "pmj02bn" sampler's per-pixel decorrelation, as pbrt-v4 takes
// its Cranley-Patterson rotations and 1-D offsets from 48 precomputed 128 x 128 textures
// (pbrt-v4 util/bluenoise.h): neighbouring pixels get values far apart, so the error a
// rotation leaves in a pixel is anticorrelated with its neighbours' (high-frequency, less
// visible, and averaged away by the filter) instead of white.
//
// eyetrace makes its own by Ulichney's void-and-cluster method (1993, "The void-and-cluster
// method for dither array generation"): a Gaussian energy (sigma 1.5 pixels) on the torus, an
// initial pattern relaxed by moving its tightest cluster to its largest void, then ranks
// given by removing tightest clusters and filling largest voids. The sampler's textures are
// made at build time (tools/pmj02bn_tables; samplers/pmj02bn_tables.h reads them).
#pragma once
#include <cstdint>
#include <vector>

namespace eyetrace {

inline constexpr int kBlueNoiseSize = 128;     // as pbrt-v4's BlueNoiseResolution
inline constexpr int kBlueNoiseTextures = 48;  // as pbrt-v4's NumBlueNoiseTextures
// Texture t of the sampler's tables is make_void_and_cluster(kBlueNoiseSize, kBlueNoiseSeed + t).
inline constexpr uint64_t kBlueNoiseSeed = 0x626c75656e6f6973ull;

// The void-and-cluster ranks of a size x size toroidal texture (row-major, each rank in
// [0, size^2) once), chosen by `seed`. About 60 ms for 128 x 128.
std::vector<uint16_t> make_void_and_cluster(int size, uint64_t seed);

}  // namespace eyetrace
