// The full wave report of one field and wavelength (issue 15's speed target: < 50 ms on one core
// at the default sampling): the wavefront traced with the real stop (64 x 64 pupil grid), its
// 15 Zernike terms (order 4), the retinal scale, the PSF by FFT (256 x 256), its Strehl ratio
// and encircled energy, and the MTF at the six default frequencies. Navarro's eye, 555 nm.
#include <benchmark/benchmark.h>

#include "optics/eye_models.h"
#include "optics/mtf.h"
#include "optics/psf.h"
#include "optics/wave_optics_report.h"
#include "optics/wavefront.h"

namespace {

using namespace eyetrace::optics;

Prescription navarro() {
  EyeOptions o;
  o.model = "navarro";
  return make_eye(o);
}

void wave_report(benchmark::State& state, double field_deg) {
  const Prescription p = navarro();
  WavefrontOptions o;
  o.field_deg = field_deg;
  o.wavelength_nm = 555.0;
  o.zernike_order = 4;  // 15 terms
  o.clip_at_stop = true;
  for (auto _ : state) {
    const WavefrontResult w = trace_wavefront(p, o);
    const Psf psf = compute_psf(w, retinal_scale(p, field_deg, o.object_distance_m, 555.0));
    benchmark::DoNotOptimize(compute_mtf(psf, {5.0, 10.0, 20.0, 30.0, 40.0, 60.0}));
  }
}

// What `eyetrace optics --wave` does per field beyond the Zernike fit: the same, with the pupil
// grid refined until the phase is sampled (224 across at 20 degrees, a 1024 x 1024 FFT).
void report_entry(benchmark::State& state, double field_deg) {
  const Prescription p = navarro();
  WavefrontOptions o;
  o.field_deg = field_deg;
  o.wavelength_nm = 555.0;
  o.zernike_order = 4;
  for (auto _ : state) benchmark::DoNotOptimize(wave_optics_json(p, o, {5.0, 10.0, 20.0, 30.0, 40.0, 60.0}));
}

}  // namespace

BENCHMARK_CAPTURE(wave_report, on_axis, 0.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(wave_report, field_20deg, 20.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(report_entry, on_axis, 0.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(report_entry, field_20deg, 20.0)->Unit(benchmark::kMillisecond);
