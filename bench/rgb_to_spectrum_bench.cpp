// The cost of the RGB -> spectrum conversion (core/rgb_to_spectrum.h) in the render loop: one
// table lookup per texture evaluation, then the spectrum at a few wavelengths.
//   build/bench/rgb_to_spectrum_bench
// BM_Lookup cycles through 4096 random colours, so most lookups miss the caches (the table is
// 9.4 MB); BM_LookupCoherent looks up neighbouring colours. docs/spectral.md quotes the numbers.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "core/rgb_to_spectrum.h"

namespace eyetrace {
namespace {

std::vector<glm::vec3> random_colours() {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  std::vector<glm::vec3> colours(4096);
  for (glm::vec3& c : colours) c = glm::vec3(u(rng), u(rng), u(rng));
  return colours;
}

void BM_Lookup(benchmark::State& state) {
  const RGBToSpectrumTable& table = RGBToSpectrumTable::srgb();
  const std::vector<glm::vec3> colours = random_colours();
  size_t i = 0;
  for (auto _ : state) {
    SigmoidPolynomial s = table(colours[i++ & 4095]);
    benchmark::DoNotOptimize(s);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Lookup);

// Neighbouring lookups, as along a smooth gradient of a texture: the table's cache lines are
// warm, so this is the arithmetic alone.
void BM_LookupCoherent(benchmark::State& state) {
  const RGBToSpectrumTable& table = RGBToSpectrumTable::srgb();
  std::vector<glm::vec3> colours(4096);
  for (size_t i = 0; i < colours.size(); ++i) {
    float t = float(i) / float(colours.size());
    colours[i] = glm::vec3(0.6f + 0.01f * t, 0.3f + 0.02f * t, 0.2f - 0.01f * t);
  }
  size_t i = 0;
  for (auto _ : state) {
    SigmoidPolynomial s = table(colours[i++ & 4095]);
    benchmark::DoNotOptimize(s);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LookupCoherent);

// A lookup and the spectrum at four wavelengths (a hero-wavelength sample).
void BM_LookupAndEvaluate4(benchmark::State& state) {
  const RGBToSpectrumTable& table = RGBToSpectrumTable::srgb();
  const std::vector<glm::vec3> colours = random_colours();
  size_t i = 0;
  float lambda = 400.f;
  for (auto _ : state) {
    SigmoidPolynomial s = table(colours[i++ & 4095]);
    float sum = s(lambda) + s(lambda + 100.f) + s(lambda + 200.f) + s(lambda + 300.f);
    benchmark::DoNotOptimize(sum);
    lambda = lambda < 480.f ? lambda + 1.f : 400.f;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LookupAndEvaluate4);

void BM_MaxValue(benchmark::State& state) {
  const RGBToSpectrumTable& table = RGBToSpectrumTable::srgb();
  const std::vector<glm::vec3> colours = random_colours();
  std::vector<SigmoidPolynomial> spectra;
  for (const glm::vec3& c : colours) spectra.push_back(table(c));
  size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(spectra[i++ & 4095].max_value());
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_MaxValue);

}  // namespace
}  // namespace eyetrace
