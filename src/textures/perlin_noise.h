// Perlin's gradient noise and its sums, as pbrt-v4 defines them (pbrt-v4's util/noise.h):
// Ken Perlin's lattice ("Improving Noise", SIGGRAPH 2002: his published permutation of 0..255
// and the quintic fade 6t^5 - 15t^4 + 10t^3) with pbrt's choice of the 12 + 4 gradient
// directions; zero at every lattice point, values in about [-1, 1].
//
// fbm and turbulence sum `octaves` copies at frequencies 1.99^i with weights omega^i. pbrt-v4
// drops the octaves finer than a pixel's footprint (from ray differentials) and replaces
// turbulence's dropped ones by their mean 0.2; eyetrace's hits carry no ray differentials, so
// every octave is summed and the pixel's samples average the fine ones (pbrt-v4's own result
// when the footprint is small).
#pragma once
#include "core/math.h"

namespace eyetrace {

float perlin_noise(float x, float y = 0.5f, float z = 0.5f);
inline float perlin_noise(const Vec3& p) { return perlin_noise(p.x, p.y, p.z); }
// sum over i < octaves of omega^i noise(1.99^i p).
float fbm(const Vec3& p, float omega, int octaves);
// sum over i < octaves of omega^i |noise(1.99^i p)|, plus omega^octaves 0.2 (pbrt-v4's term for
// the octave it would blend in).
float turbulence(const Vec3& p, float omega, int octaves);

}  // namespace eyetrace
