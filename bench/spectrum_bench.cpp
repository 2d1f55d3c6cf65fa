// The per-wavelength cost of tabulated spectra and of the lights' RGB emission (core/spectrum.h),
// both read at the four wavelengths of every sample that meets them.
//   build/bench/spectrum_bench
// BM_InterpolateTable: a tabulated spectrum of N points (the named metals and glasses have 20-36,
// measured tables up to hundreds) at wavelengths spread over its range. BM_WhiteIlluminant: the colour
// space's white (D65 of luminance 1) at 4 wavelengths, which every RGB emission multiplies by.
// docs/spectral.md quotes the numbers.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "core/sampled_spectrum.h"
#include "core/spectrum.h"

namespace eyetrace {
namespace {

std::vector<float> random_wavelengths(float lo, float hi) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(lo, hi);
  std::vector<float> l(4096);
  for (float& x : l) x = u(rng);
  return l;
}

void BM_InterpolateTable(benchmark::State& state) {
  const int n = int(state.range(0));
  std::vector<float> lambda(n), value(n);
  for (int i = 0; i < n; ++i) {
    lambda[i] = 360.f + 470.f * float(i) / float(n - 1);
    value[i] = 0.5f + 0.4f * float(i % 7) / 7.f;
  }
  const std::vector<float> l = random_wavelengths(360.f, 830.f);
  size_t i = 0;
  for (auto _ : state) {
    float v = interpolate_spectrum(lambda, value, l[i++ & 4095]);
    benchmark::DoNotOptimize(v);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_InterpolateTable)->Arg(8)->Arg(32)->Arg(471);

void BM_WhiteIlluminant4(benchmark::State& state) {
  const std::vector<float> l = random_wavelengths(360.f, 830.f);
  size_t i = 0;
  for (auto _ : state) {
    const float* x = &l[i & 4092];
    i += 4;
    float v = white_illuminant(x[0]) + white_illuminant(x[1]) + white_illuminant(x[2]) + white_illuminant(x[3]);
    benchmark::DoNotOptimize(v);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_WhiteIlluminant4);

// An RGB light's emission at a sample's 4 wavelengths: the sigmoid times the white.
void BM_RgbEmission4(benchmark::State& state) {
  const Spectrum s = Spectrum::from_rgb(RGB(0.9f, 0.6f, 0.3f), SpectrumType::Illuminant);
  std::vector<SampledWavelengths> lambda;
  for (float u : random_wavelengths(0.f, 1.f)) lambda.push_back(SampledWavelengths::sample_visible(u));
  size_t i = 0;
  for (auto _ : state) {
    SampledSpectrum v = s.sample(lambda[i++ & 4095]);
    benchmark::DoNotOptimize(v);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_RgbEmission4);

}  // namespace
}  // namespace eyetrace
