// The sequential trace alone (no camera around it), one core: reverse traces through the Navarro
// eye from retina points within 35 deg towards the 4 mm pupil, the rays the eye camera traces.
// items_per_second = traces per second. The batch benchmarks run on each instruction set
// (/0 baseline = SSE2, /1 AVX2 where the CPU has it), at the compiled wavelength and at a
// wavelength of each ray's own (uniform in 360-830 nm). BM_TraceAstigmatic* trace the same rays
// through a non-symmetric eye (its placed surfaces by placed_kernel.h's step, the batch on the
// start-up instruction set): /0 Navarro with a biconic cornea
// of 1.50 D cylinder at axis 90, /1 that eye with the iris decentred 0.3 mm and the lens's
// surfaces decentred 0.1 mm and tilted 1 deg (iris 0.3 mm in front of the lens).
// BM_TraceMeasuredSingle: the plain Navarro eye with a measured wavefront to the 4th order (the
// coefficients of scenes/measured-eye.zer over a 6 mm pupil) as a phase plate on its iris,
// which takes the general path for every surface it has a plate on and the kernel for the rest.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "optics/dispersion_formulas.h"
#include "optics/eye_models.h"
#include "optics/phase_plate.h"
#include "optics/sequential_trace.h"

namespace eyetrace::optics {
namespace {

struct Setup {
  Prescription p;
  CompiledSystem sys;
  std::vector<Ray> rays;
  std::vector<double> lambda;
  explicit Setup(const char* model, int astigmatic = -1)
      : Setup(astigmatic < 0 ? make(model) : make_astigmatic(model, astigmatic)) {}
  explicit Setup(Prescription prescription) : p(std::move(prescription)), sys(p), rays(4096), lambda(rays.size()) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double length = p.axial_length_mm(), z_stop = sys.vertex_z(sys.stop_index());
    for (Ray& r : rays) {
      const double a = 0.6 * u(rng), phi = 2.0 * std::numbers::pi * u(rng);
      const glm::dvec3 at = glm::dvec3(0, 0, length - 12.0) +
                            12.0 * glm::dvec3(std::sin(a) * std::cos(phi), std::sin(a) * std::sin(phi), std::cos(a));
      const double rt = 2.0 * std::sqrt(u(rng)), pt = 2.0 * std::numbers::pi * u(rng);
      r = {at, glm::normalize(glm::dvec3(rt * std::cos(pt), rt * std::sin(pt), z_stop) - at)};
    }
    for (double& l : lambda) l = 360.0 + 470.0 * u(rng);
  }
  static Prescription make(const char* model) {
    EyeOptions o;
    o.model = model;
    return make_eye(o);
  }
  static Prescription make_astigmatic(const char* model, int placed) {
    Prescription p = make(model);
    const SurfaceProfile c = p.surfaces[0].profile;
    const double dn = p.surfaces[0].index_after - 1.0;
    p.surfaces[0].profile = SurfaceProfile::biconic(c.curvature, c.conic, c.curvature + 1.5e-3 / dn, c.conic, 90.0);
    if (placed) {
      const int stop = p.stop_index();
      p.surfaces[stop - 1].thickness_mm -= 0.3;
      p.surfaces[stop].thickness_mm += 0.3;
      p.surfaces[stop].placement.decentre_x_mm = 0.3;
      for (int i = stop + 1; i < p.image_index(); ++i) p.surfaces[i].placement = {0.1, 0.0, 1.0, 0.0};
    }
    return p;
  }
};

const Setup& navarro() {
  static const Setup s("navarro");
  return s;
}

bool use_isa(benchmark::State& state) {
  const auto isa = static_cast<TraceBatchIsa>(state.range(0));
  if (!set_trace_batch_isa(isa)) {
    state.SkipWithError("instruction set not available");
    return false;
  }
  state.SetLabel(to_string(isa));
  return true;
}

void BM_TraceSingle(benchmark::State& state) {
  const Setup& s = navarro();
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(s.sys.trace_reverse(s.rays[i]));
    i = (i + 1) & (s.rays.size() - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TraceSingle);

void BM_TraceSingleWavelength(benchmark::State& state) {
  const Setup& s = navarro();
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(s.sys.trace_range(s.rays[i], s.sys.image_index() - 1, 0, s.lambda[i]));
    i = (i + 1) & (s.rays.size() - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TraceSingleWavelength);

// kTraceBatchSize rays per call, as the camera's generate_rays hands them over.
void batch(benchmark::State& state, bool per_ray_wavelength) {
  if (!use_isa(state)) return;
  const Setup& s = navarro();
  TraceResult results[kTraceBatchSize];
  size_t i = 0;
  for (auto _ : state) {
    s.sys.trace_range_batch(&s.rays[i], per_ray_wavelength ? &s.lambda[i] : nullptr, results, kTraceBatchSize,
                            s.sys.image_index() - 1, 0);
    benchmark::DoNotOptimize(results);
    i = (i + kTraceBatchSize) & (s.rays.size() - 1);
  }
  state.SetItemsProcessed(state.iterations() * kTraceBatchSize);
  set_trace_batch_isa(TraceBatchIsa::Avx512) || set_trace_batch_isa(TraceBatchIsa::Avx2) ||
      set_trace_batch_isa(TraceBatchIsa::Baseline);
}
void BM_TraceBatch(benchmark::State& state) { batch(state, false); }
BENCHMARK(BM_TraceBatch)->Arg(0)->Arg(1)->Arg(2);
void BM_TraceBatchWavelength(benchmark::State& state) { batch(state, true); }
BENCHMARK(BM_TraceBatchWavelength)->Arg(0)->Arg(1)->Arg(2);

const Setup& astigmatic(int placed) {
  static const Setup toric("navarro", 0), toric_placed("navarro", 1);
  return placed ? toric_placed : toric;
}

void BM_TraceAstigmaticSingle(benchmark::State& state) {
  const Setup& s = astigmatic(static_cast<int>(state.range(0)));
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(s.sys.trace_reverse(s.rays[i]));
    i = (i + 1) & (s.rays.size() - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TraceAstigmaticSingle)->Arg(0)->Arg(1);

Prescription measured_navarro() {
  Prescription p = Setup::make("navarro");
  ZernikeFile f;
  f.origin = "measured-eye.zer";
  f.pupil_diameter_mm = 6.0;
  f.max_order = 4;
  f.coefficients_um = {0, 0, 0, -0.08, 0.25, 0.12, 0.03, -0.07, 0.02, -0.04, 0, 0, 0.10, 0, 0};
  add_phase_plate(p, f);
  return p;
}

void BM_TraceMeasuredSingle(benchmark::State& state) {
  static const Setup s(measured_navarro());
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(s.sys.trace_reverse(s.rays[i]));
    i = (i + 1) & (s.rays.size() - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TraceMeasuredSingle);

void BM_TraceAstigmaticBatch(benchmark::State& state) {
  const Setup& s = astigmatic(static_cast<int>(state.range(0)));
  TraceResult results[kTraceBatchSize];
  size_t i = 0;
  for (auto _ : state) {
    s.sys.trace_range_batch(&s.rays[i], nullptr, results, kTraceBatchSize, s.sys.image_index() - 1, 0);
    benchmark::DoNotOptimize(results);
    i = (i + kTraceBatchSize) & (s.rays.size() - 1);
  }
  state.SetItemsProcessed(state.iterations() * kTraceBatchSize);
}
BENCHMARK(BM_TraceAstigmaticBatch)->Arg(0)->Arg(1);

// How the per-ray indices are computed: the Navarro eye's four media at one wavelength each,
// by their law (what the trace does: Herzberger weights once, then four sums) against a table
// per medium at 1 nm steps with cubic (Catmull-Rom) interpolation. "max_error" is the table's
// largest index error over 360-830 nm (sampled every 0.01 nm); the law is exact by definition.
const std::vector<Medium>& navarro_media() { return navarro().p.media; }

void BM_IndicesByLaw(benchmark::State& state) {
  const std::vector<Medium>& media = navarro_media();
  std::array<double, 4> at_reference;
  for (int m = 0; m < 4; ++m) at_reference[m] = media[m].dispersion.evaluate(media[m].reference_wavelength_nm);
  const std::vector<double>& lambda = navarro().lambda;
  size_t i = 0;
  for (auto _ : state) {
    const std::array<double, 4> w = dispersion::herzberger_weights(lambda[i]);
    std::array<double, 4> n;
    for (int m = 0; m < 4; ++m)
      n[m] = media[m].index + dispersion::herzberger_sum(w, media[m].dispersion.herzberger_indices) - at_reference[m];
    benchmark::DoNotOptimize(n);
    i = (i + 1) & (lambda.size() - 1);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["max_error"] = 0.0;  // the law is the definition
}
BENCHMARK(BM_IndicesByLaw);

struct IndexTable {
  static constexpr double kStart = 358.0, kStep = 1.0;  // one node below 360 nm for the cubic
  std::vector<std::array<double, 4>> nodes;             // the four media at each node
  IndexTable() {
    for (double l = kStart; l <= 833.0; l += kStep) {
      std::array<double, 4> n;
      for (int m = 0; m < 4; ++m) n[m] = navarro_media()[m].index_at(std::fmax(l, kMinWavelength_nm));
      nodes.push_back(n);
    }
    // The law itself below 360 nm (index_at clamps nothing; at_wavelength refuses it).
    for (int m = 0; m < 4; ++m) {
      const Medium& me = navarro_media()[m];
      for (int k = 0; k < 2; ++k)
        nodes[k][m] =
            me.index + me.dispersion.evaluate(kStart + k * kStep) - me.dispersion.evaluate(me.reference_wavelength_nm);
    }
  }
  std::array<double, 4> at(double lambda) const {
    const double x = (lambda - kStart) / kStep;
    const int k = static_cast<int>(x);
    const double t = x - k;
    std::array<double, 4> n;
    for (int m = 0; m < 4; ++m) {
      const double p0 = nodes[k - 1][m], p1 = nodes[k][m], p2 = nodes[k + 1][m], p3 = nodes[k + 2][m];
      n[m] = p1 + 0.5 * t * (p2 - p0 + t * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3 + t * (3.0 * (p1 - p2) + p3 - p0)));
    }
    return n;
  }
};

void BM_IndicesByTable(benchmark::State& state) {
  static const IndexTable table;
  const std::vector<double>& lambda = navarro().lambda;
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(table.at(lambda[i]));
    i = (i + 1) & (lambda.size() - 1);
  }
  state.SetItemsProcessed(state.iterations());
  double max_error = 0.0;
  for (double l = 360.0; l <= 830.0; l += 0.01) {
    const std::array<double, 4> n = table.at(l);
    for (int m = 0; m < 4; ++m) max_error = std::fmax(max_error, std::abs(n[m] - navarro_media()[m].index_at(l)));
  }
  state.counters["max_error"] = max_error;
}
BENCHMARK(BM_IndicesByTable);

}  // namespace
}  // namespace eyetrace::optics
