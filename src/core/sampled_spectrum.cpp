// The tabulated visible-wavelength sampler (core/sampled_spectrum.h).
#include "core/sampled_spectrum.h"

#include <algorithm>
#include <array>

namespace eyetrace {

namespace {

constexpr int kTableCells = 4096;

// lambda at u = k / kTableCells from the analytic inverse CDF (the ends are exactly 360, 830).
const std::array<float, kTableCells + 1> kLambdaAtU = [] {
  std::array<float, kTableCells + 1> t{};
  for (int k = 0; k <= kTableCells; ++k)
    t[k] = std::clamp(sample_visible_wavelength(float(k) / kTableCells), kLambdaMin, kLambdaMax);
  t[0] = kLambdaMin;
  t[kTableCells] = kLambdaMax;
  return t;
}();

}  // namespace

void visible_wavelength_from_table(float u, float* lambda, float* pdf) {
  const float x = std::clamp(u, 0.f, 1.f) * kTableCells;
  const int k = std::min(int(x), kTableCells - 1);
  const float a = kLambdaAtU[k], b = kLambdaAtU[k + 1];
  *lambda = a + (x - float(k)) * (b - a);
  // Uniform u in the cell maps linearly onto [a, b]: density (1 / cells) / (b - a).
  *pdf = 1.f / (float(kTableCells) * (b - a));
}

}  // namespace eyetrace
