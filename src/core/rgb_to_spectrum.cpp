// The RGB -> spectrum lookup; see core/rgb_to_spectrum.h. The table is generated at build time
// by tools/rgb2spec_opt and embedded (assembler .incbin) by the generated rgb2spec_srgb.cpp,
// which defines the three symbols below; the layout is described in that tool.
#include "core/rgb_to_spectrum.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>

extern "C" {
extern const uint32_t eyetrace_rgb2spec_srgb_header[4];  // magic "R2S1", resolution, 0, 0
extern const float eyetrace_rgb2spec_srgb_z[];
extern const float eyetrace_rgb2spec_srgb_coefficients[];
}

namespace eyetrace {

namespace {

constexpr uint32_t kRgbToSpectrumMagic = 0x31533252u;  // "R2S1"

// [0, 1], NaN to 0.
float clamp01(float v) { return v > 0.f ? (v < 1.f ? v : 1.f) : 0.f; }

}  // namespace

const RGBToSpectrumTable& RGBToSpectrumTable::srgb() {
  static const RGBToSpectrumTable table = [] {
    const uint32_t* h = eyetrace_rgb2spec_srgb_header;
    if (h[0] != kRgbToSpectrumMagic || h[1] < 2 || h[1] > 256 || h[2] != 0 || h[3] != 0) {
      std::fprintf(stderr, "eyetrace: the embedded RGB -> spectrum table is damaged (rebuild)\n");
      std::abort();
    }
    return RGBToSpectrumTable(int(h[1]), eyetrace_rgb2spec_srgb_z, eyetrace_rgb2spec_srgb_coefficients);
  }();
  return table;
}

SigmoidPolynomial RGBToSpectrumTable::operator()(const glm::vec3& in) const {
  const float rgb[3] = {clamp01(in.x), clamp01(in.y), clamp01(in.z)};
  // Greys: the constant spectrum, S(c2) = g for c2 = (g - 1/2) / sqrt(g (1 - g)).
  if (rgb[0] == rgb[1] && rgb[1] == rgb[2]) {
    const float g = rgb[0], inf = std::numeric_limits<float>::infinity();
    if (g == 0.f) return {0.f, 0.f, -inf};
    if (g == 1.f) return {0.f, 0.f, inf};
    return {0.f, 0.f, (g - 0.5f) / std::sqrt(g * (1.f - g))};
  }
  // The case: which component is largest (ties go to the later one; either is correct).
  const int m = rgb[0] > rgb[1] ? (rgb[0] > rgb[2] ? 0 : 2) : (rgb[1] > rgb[2] ? 1 : 2);
  const float z = rgb[m];  // > 0: not all components are equal
  const float x = rgb[(m + 1) % 3] / z, y = rgb[(m + 2) % 3] / z;

  // Cell and weights: x and y uniform, z by binary search (the largest k <= res - 2 with
  // z_[k] <= z; z_[0] = 0).
  const int last = res_ - 2;
  const float xf = x * float(res_ - 1), yf = y * float(res_ - 1);
  const int xi = std::min(int(xf), last), yi = std::min(int(yf), last);
  int zi = 0;
  for (int len = res_ - 1; len > 1;) {
    const int half = len / 2;
    if (z_[zi + half] <= z) zi += half;
    len -= half;
  }
  const float dx = xf - float(xi), dy = yf - float(yi), dz = (z - z_[zi]) / (z_[zi + 1] - z_[zi]);

  const size_t res = size_t(res_);
  const float* c = coefficients_ + (((size_t(m) * res + size_t(zi)) * res + size_t(yi)) * res + size_t(xi)) * 3;
  const size_t sx = 3, sy = 3 * res, sz = 3 * res * res;
  float out[3];
  for (int n = 0; n < 3; ++n) {
    auto lerp = [](float t, float a, float b) { return a + t * (b - a); };
    const float* p = c + n;
    float y0 = lerp(dy, lerp(dx, p[0], p[sx]), lerp(dx, p[sy], p[sy + sx]));
    float y1 = lerp(dy, lerp(dx, p[sz], p[sz + sx]), lerp(dx, p[sz + sy], p[sz + sy + sx]));
    out[n] = lerp(dz, y0, y1);
  }
  return {out[0], out[1], out[2]};
}

}  // namespace eyetrace
