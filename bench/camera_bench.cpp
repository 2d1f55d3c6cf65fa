// Camera ray generation speed (one core): pinhole and thin lens for scale, the schematic-eye
// cameras (target: Navarro >= 5 million rays/s; batched on the start-up instruction set and on
// the baseline), and the eye camera's construction time
// (target < 50 ms). items_per_second = camera samples per second, lost rays included;
// "useful" = fraction of samples that gave a ray.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <random>

#include "cameras/lens_system_camera.h"
#include "cameras/perspective_camera.h"
#include "filters/box_filter.h"
#include "optics/airy_kernel.h"
#include "optics/sequential_trace.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {

const IVec2 kResolution(512, 512);

std::vector<CameraSample> random_samples() {
  std::vector<CameraSample> samples(1 << 16);
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  for (CameraSample& cs : samples) {
    cs.p_film = Vec2(kResolution.x * u(rng), kResolution.y * u(rng));
    cs.p_lens = Vec2(u(rng), u(rng));
  }
  return samples;
}

// The order the integrator asks in: 16x16-pixel tiles, 16 jittered samples per pixel, so
// consecutive samples share a retina position (and its pupil tables) as in a render.
std::vector<CameraSample> tile_ordered_samples() {
  std::vector<CameraSample> samples;
  samples.reserve(1 << 16);
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  for (int tile = 0; samples.size() < (1u << 16); tile += 7) {  // tiles spread over the image
    const int tx = tile % (kResolution.x / 16), ty = (tile / (kResolution.x / 16)) % (kResolution.y / 16);
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x)
        for (int i = 0; i < 16 && samples.size() < (1u << 16); ++i) {
          CameraSample cs;
          cs.p_film = Vec2(float(tx * 16 + x) + u(rng), float(ty * 16 + y) + u(rng));
          cs.p_lens = Vec2(u(rng), u(rng));
          samples.push_back(cs);
        }
  }
  return samples;
}

std::unique_ptr<Camera> eye(const std::string& name, const std::string& params) {
  SceneEntity e = parse_directive_text("Camera \"" + name + "\" " + params, "Camera", "bench");
  CameraContext ctx{e.params, Transform(), kResolution, ""};
  return name == "eye" ? create_eye_camera(ctx) : create_named_eye_camera(name)(ctx);
}

void run(benchmark::State& state, const Camera& cam) {
  const std::vector<CameraSample> samples = random_samples();
  size_t i = 0, rays = 0, n = 0;
  for (auto _ : state) {
    auto r = cam.generate_ray(samples[i]);
    rays += r.has_value();
    benchmark::DoNotOptimize(r);
    i = (i + 1) & (samples.size() - 1);
    ++n;
  }
  state.SetItemsProcessed(static_cast<int64_t>(n));
  state.counters["useful"] = n ? double(rays) / double(n) : 0.0;
}

// The integrator's path: generate_rays over the samples of one pixel at a time (16 here), in
// tile order.
void run_batched(benchmark::State& state, const Camera& cam) {
  const std::vector<CameraSample> samples = tile_ordered_samples();
  constexpr size_t kChunk = 16;
  std::optional<CameraRay> out[kChunk];
  size_t i = 0, rays = 0, n = 0;
  for (auto _ : state) {
    cam.generate_rays(&samples[i], out, kChunk);
    for (const auto& r : out) rays += r.has_value();
    benchmark::DoNotOptimize(out);
    i = (i + kChunk) & (samples.size() - 1);
    n += kChunk;
  }
  state.SetItemsProcessed(static_cast<int64_t>(n));
  state.counters["useful"] = n ? double(rays) / double(n) : 0.0;
}

void BM_Pinhole(benchmark::State& state) {
  PerspectiveCamera::Settings s;
  s.fov_deg = 60.f;
  run(state, PerspectiveCamera(Transform(), kResolution, s));
}
BENCHMARK(BM_Pinhole);

void BM_ThinLens(benchmark::State& state) {
  PerspectiveCamera::Settings s;
  s.fov_deg = 60.f;
  s.lens_radius = 0.0025f;
  s.focal_distance = 2.f;
  run(state, PerspectiveCamera(Transform(), kResolution, s));
}
BENCHMARK(BM_ThinLens);

// The paper's configuration: 5 mm pupil, relaxed eye, 60 degree field.
void BM_Navarro(benchmark::State& state) { run(state, *eye("navarro", "\"float pupildiameter\" 5 \"float fov\" 60")); }
BENCHMARK(BM_Navarro);

void BM_NavarroBatched(benchmark::State& state) {
  run_batched(state, *eye("navarro", "\"float pupildiameter\" 5 \"float fov\" 60"));
}
BENCHMARK(BM_NavarroBatched);

// Not rotationally symmetric (issue 16): cylinder -1.5 D x 90 on the cornea and the iris
// decentred 0.3 mm, traced by the general path; rays drawn in the symmetric envelope's pupil
// regions (symmetric_stand_in.h), so some are rejected: "useful" says how many.
void BM_NavarroAstigmaticBatched(benchmark::State& state) {
  run_batched(state, *eye("navarro",
                          "\"float pupildiameter\" 5 \"float fov\" 60 \"float cylinder\" -1.5 \"float axis\" 90 "
                          "\"float pupildecentration\" [0.3 0]"));
}
BENCHMARK(BM_NavarroAstigmaticBatched);
// The case: an astigmatic eye (-3 D myope, cylinder -1.5 x 90) with the spectacles that
// correct it (two more surfaces, the back one toric: a biconic).
const char* const kAstigmaticSpectacles =
    "\"float pupildiameter\" 5 \"float fov\" 60 \"float refractiveerror\" -3 \"float cylinder\" -1.5 "
    "\"float axis\" 90 \"float spectaclesphere\" -3.112 \"float spectaclecylinder\" -1.5 \"float spectacleaxis\" 90";
void BM_NavarroAstigmaticSpectaclesBatched(benchmark::State& state) {
  run_batched(state, *eye("navarro", kAstigmaticSpectacles));
}
BENCHMARK(BM_NavarroAstigmaticSpectaclesBatched);
// A -3 D myope corrected by a spectacle lens (two more surfaces before the cornea) or by a contact
// lens (one more), against BM_NavarroBatched (issue 16's speed item: at least half its rate).
void BM_NavarroSpectaclesBatched(benchmark::State& state) {
  run_batched(state, *eye("navarro",
                          "\"float pupildiameter\" 5 \"float fov\" 60 \"float refractiveerror\" -3 "
                          "\"float spectaclesphere\" -3.112"));
}
BENCHMARK(BM_NavarroSpectaclesBatched);
void BM_NavarroContactLensBatched(benchmark::State& state) {
  run_batched(state, *eye("navarro",
                          "\"float pupildiameter\" 5 \"float fov\" 60 \"float refractiveerror\" -3 "
                          "\"float contactlens\" -3"));
}
BENCHMARK(BM_NavarroContactLensBatched);

// generate_rays over dispersive-eye samples with their wavelengths (samples.size() a power of
// two), 16 at a time as the integrator asks.
void run_dispersive(benchmark::State& state, const std::vector<CameraSample>& samples,
                    const std::vector<SampledWavelengths>& lambdas) {
  auto cam = eye("navarro", "\"float pupildiameter\" 5 \"float fov\" 60");
  constexpr size_t kChunk = 16;
  std::optional<CameraRay> out[kChunk];
  SampledWavelengths batch[kChunk];
  size_t i = 0, n = 0;
  for (auto _ : state) {
    std::copy_n(&lambdas[i], kChunk, batch);  // the camera may terminate the secondaries
    cam->generate_rays(&samples[i], batch, out, kChunk);
    benchmark::DoNotOptimize(out);
    i = (i + kChunk) & (samples.size() - 1);
    n += kChunk;
  }
  state.SetItemsProcessed(static_cast<int64_t>(n));
}

// The dispersive eye as a render drives it: the samples name their pixel's filter, so every
// ray's three secondary wavelengths are traced back in for spectral MIS (spectral_mis.cpp).
// Its ratio to BM_NavarroBatched is the camera-side cost of MIS.
void BM_NavarroBatchedSpectralMis(benchmark::State& state) {
  const BoxFilter box(Vec2(0.5f));
  std::vector<CameraSample> samples = tile_ordered_samples();
  std::vector<SampledWavelengths> lambdas;
  for (CameraSample& cs : samples) {
    cs.filter = &box;
    cs.filter_offset = cs.p_film - glm::floor(cs.p_film) - Vec2(0.5f);
    lambdas.push_back(SampledWavelengths::sample_visible(float(lambdas.size() % 16) / 16));
  }
  run_dispersive(state, samples, lambdas);
}
BENCHMARK(BM_NavarroBatchedSpectralMis);

// The dispersive eye as a render with wavelengths apart drives it (the default with a box
// filter): each sample's film and pupil point four times in a row, wavelengths rotated so that
// each is the hero once, each ray the hero's alone. items_per_second = camera rays (four a
// sample); its ratio to BM_NavarroBatched is a dispersive ray's cost against a monochromatic one.
void BM_NavarroBatchedWavelengthPaths(benchmark::State& state) {
  const BoxFilter box(Vec2(0.5f));
  const std::vector<CameraSample> drawn = tile_ordered_samples();
  std::vector<CameraSample> samples;
  std::vector<SampledWavelengths> lambdas;
  for (size_t s = 0; s < drawn.size() / kSpectrumSamples; ++s)
    for (int k = 0; k < kSpectrumSamples; ++k) {
      CameraSample cs = drawn[s];
      cs.filter = &box;
      cs.hero_only = true;
      samples.push_back(cs);
      lambdas.push_back(SampledWavelengths::sample_visible(SampledWavelengths::rotated(float(s % 16) / 16, k)));
    }
  run_dispersive(state, samples, lambdas);
}
BENCHMARK(BM_NavarroBatchedWavelengthPaths);

// The same with the batch trace on the baseline instruction set (SSE2) or on AVX2 instead of
// the start-up choice (the widest the CPU has): what a CPU without AVX2, or without AVX-512, gets.
void navarro_batched_on(benchmark::State& state, optics::TraceBatchIsa isa) {
  const optics::TraceBatchIsa start = optics::trace_batch_isa();
  if (!optics::set_trace_batch_isa(isa)) {
    state.SkipWithError("instruction set not available");
    return;
  }
  run_batched(state, *eye("navarro", "\"float pupildiameter\" 5 \"float fov\" 60"));
  optics::set_trace_batch_isa(start);
}
void BM_NavarroBatchedBaseline(benchmark::State& state) { navarro_batched_on(state, optics::TraceBatchIsa::Baseline); }
BENCHMARK(BM_NavarroBatchedBaseline);
void BM_NavarroBatchedAvx2(benchmark::State& state) { navarro_batched_on(state, optics::TraceBatchIsa::Avx2); }
BENCHMARK(BM_NavarroBatchedAvx2);
void BM_NavarroAstigmaticSpectaclesBatchedBaseline(benchmark::State& state) {
  const optics::TraceBatchIsa start = optics::trace_batch_isa();
  optics::set_trace_batch_isa(optics::TraceBatchIsa::Baseline);
  run_batched(state, *eye("navarro", kAstigmaticSpectacles));
  optics::set_trace_batch_isa(start);
}
BENCHMARK(BM_NavarroAstigmaticSpectaclesBatchedBaseline);

void BM_PinholeBatched(benchmark::State& state) {
  PerspectiveCamera::Settings s;
  s.fov_deg = 60.f;
  run_batched(state, PerspectiveCamera(Transform(), kResolution, s));
}
BENCHMARK(BM_PinholeBatched);

void BM_NavarroAccommodated(benchmark::State& state) {
  run(state, *eye("navarro", "\"float pupildiameter\" 5 \"float fov\" 60 \"float accommodation\" 4"));
}
BENCHMARK(BM_NavarroAccommodated);

void BM_Gullstrand(benchmark::State& state) {  // six surfaces
  run(state, *eye("gullstrand", "\"float pupildiameter\" 5 \"float fov\" 60"));
}
BENCHMARK(BM_Gullstrand);

void BM_LeGrand(benchmark::State& state) { run(state, *eye("legrand", "\"float pupildiameter\" 5 \"float fov\" 60")); }
BENCHMARK(BM_LeGrand);

// Diffraction (Camera "bool diffraction", cameras/wave_psf_table.h) at a 2 mm pupil, where it
// matters, against the same eye without it: the ratio is the camera-side cost of drawing each
// ray's direction from the wave PSF. Dispersive (hero wavelength only, as a render with
// diffraction does) and monochromatic at 555 nm.
const char* const k2mm = "\"float pupildiameter\" 2 \"float fov\" 60";
void BM_Navarro2mmBatched(benchmark::State& state) { run_batched(state, *eye("navarro", k2mm)); }
BENCHMARK(BM_Navarro2mmBatched);

void BM_Navarro2mmBatchedDiffraction(benchmark::State& state) {
  run_batched(state, *eye("navarro", std::string(k2mm) + " \"bool diffraction\" true"));
}
BENCHMARK(BM_Navarro2mmBatchedDiffraction);

void BM_Navarro2mm555Batched(benchmark::State& state) {
  run_batched(state, *eye("navarro", std::string(k2mm) + " \"float wavelength\" 555"));
}
BENCHMARK(BM_Navarro2mm555Batched);

void BM_Navarro2mm555BatchedDiffraction(benchmark::State& state) {
  run_batched(state, *eye("navarro", std::string(k2mm) + " \"float wavelength\" 555 \"bool diffraction\" true"));
}
BENCHMARK(BM_Navarro2mm555BatchedDiffraction);

// The per-ray work of the two methods compared in docs/wavefront.md ("Diffraction in
// renders"), alone: (b) a direction from the wave-PSF table (the camera's), (a) an Airy offset
// (optics/airy_kernel.h: inverted radial CDF, a random azimuth) to add to the traced direction.
void BM_DiffractionSampleWavePsf(benchmark::State& state) {
  auto cam = eye("navarro", std::string(k2mm) + " \"bool diffraction\" true");
  const WavePsfTable& table = *dynamic_cast<const LensSystemCamera&>(*cam).psf_table();
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> numbers(1 << 16);
  for (double& x : numbers) x = u(rng);
  size_t i = 0;
  for (auto _ : state) {
    const double* v = &numbers[i];
    benchmark::DoNotOptimize(table.sample(6.0 * v[6], 400.0 + 300.0 * v[7], v));
    i = (i + 8) & ((1 << 16) - 9);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_DiffractionSampleWavePsf);

void BM_DiffractionSampleAiry(benchmark::State& state) {
  const optics::AiryKernel airy;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> numbers(1 << 16);
  for (double& x : numbers) x = u(rng);
  size_t i = 0;
  for (auto _ : state) {
    const double v = airy.sample_radius(numbers[i]) * (400.0 + 300.0 * numbers[i + 2]) * 1e-6 / (3.14159 * 2.27);
    const double phi = 6.283185307 * numbers[i + 1];
    benchmark::DoNotOptimize(glm::dvec2(v * std::cos(phi), v * std::sin(phi)));
    i = (i + 3) & ((1 << 16) - 4);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_DiffractionSampleAiry);

void BM_Navarro2mmDiffractionConstruction(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(eye("navarro", std::string(k2mm) + " \"bool diffraction\" true"));
}
BENCHMARK(BM_Navarro2mmDiffractionConstruction)->Unit(benchmark::kMillisecond);

void BM_Navarro2mm555DiffractionConstruction(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(eye("navarro", std::string(k2mm) + " \"float wavelength\" 555 \"bool diffraction\" true"));
}
BENCHMARK(BM_Navarro2mm555DiffractionConstruction)->Unit(benchmark::kMillisecond);

void BM_NavarroConstruction(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(eye("navarro", "\"float pupildiameter\" 5 \"float fov\" 60"));
}
BENCHMARK(BM_NavarroConstruction)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace eyetrace
