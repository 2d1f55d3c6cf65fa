// The sRGB transfer curve (IEC 61966-2-1): encoded values of 8-bit images and output, and the
// linear values the renderer works in.
#pragma once
#include <cmath>

namespace eyetrace {

inline float linear_to_srgb(float v) {
  if (!(v > 0.f)) return 0.f;
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.f / 2.4f) - 0.055f;
}

inline float srgb_to_linear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

}  // namespace eyetrace
