// The hot path of the eye camera: one loop over a flat interface array around the kernels of
// trace_kernel.h (a rotationally symmetric surface) and placed_kernel.h (a placed one), for one
// ray (V = double) or a block of rays (V = a SIMD batch, batch_kernel.h). No allocation, no
// exceptions, no virtual calls per ray.
#include "optics/sequential_trace.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "optics/batch_kernel.h"

namespace eyetrace::optics {

const char* to_string(TraceStatus status) {
  switch (status) {
    case TraceStatus::Ok: return "ok";
    case TraceStatus::Missed: return "missed";
    case TraceStatus::Vignetted: return "vignetted";
    case TraceStatus::StopBlocked: return "stop blocked";
    case TraceStatus::TotalInternalReflection: return "total internal reflection";
    case TraceStatus::NoConvergence: return "no convergence";
  }
  return "?";
}

namespace {

using trace_detail::Interface;
using trace_detail::MediumLaw;

// A surface side's index at any wavelength: a law of `laws` (added once per medium name), or a
// constant. Mirrors at_wavelength(): the medium from the table, Medium::index_at.
Interface::Side side_of(const Medium* m, double fallback_index, std::vector<std::string>& law_names,
                        std::vector<MediumLaw>& laws) {
  if (!m) return {-1, fallback_index};  // not in the table (at_wavelength would throw)
  if (m->dispersion.law == DispersionLaw::None) return {-1, m->index};
  for (std::size_t i = 0; i < law_names.size(); ++i)
    if (law_names[i] == m->name) return {static_cast<int>(i), 0.0};
  law_names.push_back(m->name);
  laws.push_back(
      {m->dispersion, m->index, m->reference_wavelength_nm, m->dispersion.evaluate(m->reference_wavelength_nm)});
  return {static_cast<int>(laws.size()) - 1, 0.0};
}

}  // namespace

CompiledSystem::CompiledSystem(const Prescription& p) {
  validate(p);
  const std::vector<double> z = p.vertex_z_mm();
  std::vector<std::string> law_names;
  interfaces_.reserve(p.surfaces.size());
  Interface::Side before{-1, p.object_index};  // object space: the same index at every wavelength
  for (size_t i = 0; i < p.surfaces.size(); ++i) {
    const Surface& s = p.surfaces[i];
    Interface f;
    f.z = z[i];
    f.c = s.profile.is_flat() ? 0.0 : s.profile.curvature;
    f.k = 1.0 + s.profile.conic;
    f.kc = f.k * f.c;
    f.sd2 = s.limited() ? s.semi_diameter_mm * s.semi_diameter_mm : std::numeric_limits<double>::infinity();
    f.n_before = p.index_before(static_cast<int>(i));
    f.n_after = s.index_after;
    // Stops and the image do not refract; eta == 1 also skips equal-index interfaces.
    const bool refracts = s.role == SurfaceRole::Refract;
    f.eta_forward = refracts ? f.n_before / f.n_after : 1.0;
    f.eta_reverse = refracts ? f.n_after / f.n_before : 1.0;
    f.role = s.role;
    f.plane = f.c == 0.0;
    f.before = before;
    f.after = side_of(p.find_medium(s.medium), s.index_after, law_names, laws_);
    if (f.before.law < 0 && f.after.law < 0) {
      f.eta_forward_any = refracts ? f.before.index / f.after.index : 1.0;
      f.eta_reverse_any = refracts ? f.after.index / f.before.index : 1.0;
    }
    before = f.after;
    interfaces_.push_back(f);
    placed_.emplace_back(s, z[i]);
    general_ = general_ || placed_.back().general;
  }
  stop_index_ = p.stop_index();
  wavelength_nm_ = p.wavelength_nm;
  herzberger_ = std::any_of(laws_.begin(), laws_.end(),
                            [](const MediumLaw& m) { return m.dispersion.law == DispersionLaw::NavarroHerzberger; });
}

double CompiledSystem::plate_path_mm(int surface, const glm::dvec3& point) const {
  return trace_detail::plate_path_mm(placed_[surface], point);
}

double CompiledSystem::index_before(int surface, double lambda_nm) const {
  const double lambda = kernel::clamp_wavelength(lambda_nm, wavelength_nm_);
  return kernel::side_index(interfaces_[surface].before, laws_.data(), lambda, dispersion::herzberger_weights(lambda));
}

double CompiledSystem::index_after(int surface, double lambda_nm) const {
  const double lambda = kernel::clamp_wavelength(lambda_nm, wavelength_nm_);
  return kernel::side_index(interfaces_[surface].after, laws_.data(), lambda, dispersion::herzberger_weights(lambda));
}

// ---- One ray ---------------------------------------------------------------------------------

TraceResult CompiledSystem::trace_range(const Ray& ray, int first, int last, glm::dvec3* points) const {
  if (general_)
    return first <= last ? trace_one<true, false, true>(ray, first, last, 0.0, points)
                         : trace_one<false, false, true>(ray, first, last, 0.0, points);
  return first <= last ? trace_one<true, false>(ray, first, last, 0.0, points)
                       : trace_one<false, false>(ray, first, last, 0.0, points);
}

TraceResult CompiledSystem::trace_range(const Ray& ray, int first, int last, double lambda_nm,
                                        glm::dvec3* points) const {
  if (general_)
    return first <= last ? trace_one<true, true, true>(ray, first, last, lambda_nm, points)
                         : trace_one<false, true, true>(ray, first, last, lambda_nm, points);
  return first <= last ? trace_one<true, true>(ray, first, last, lambda_nm, points)
                       : trace_one<false, true>(ray, first, last, lambda_nm, points);
}

// General: the surfaces with placed_[i].general take placed_kernel.h's step; the others the
// conic kernel's, as in a symmetric system.
template <bool Forward, bool PerRayWavelength, bool General>
TraceResult CompiledSystem::trace_one(const Ray& ray, int first, int last, double lambda_nm, glm::dvec3* points) const {
  constexpr int step_dir = Forward ? 1 : -1;
  glm::dvec3 o = ray.origin;
  // Normalised once on entry so Snell's law can assume |d| = 1.
  glm::dvec3 d = ray.direction * (1.0 / std::sqrt(glm::dot(ray.direction, ray.direction)));
  double lambda = 0.0, n = 0.0;  // per-ray wavelength: the index of the medium the ray is in
  std::array<double, 4> w{};
  if constexpr (PerRayWavelength) {
    lambda = kernel::clamp_wavelength(lambda_nm, wavelength_nm_);
    w = dispersion::herzberger_weights(lambda);
    const Interface& f = interfaces_[first];
    n = kernel::side_index(Forward ? f.before : f.after, laws_.data(), lambda, w);
  }
  for (int i = first;; i += step_dir) {
    const Interface& f = interfaces_[i];
    kernel::Eta<double> eta;
    const bool refracts = kernel::refraction_at<Forward, PerRayWavelength>(f, laws_.data(), lambda, w, n, eta);
    // The index of the medium the ray leaves into (a phase plate's rule needs it).
    const double n_to = PerRayWavelength ? n : (Forward ? f.n_after : f.n_before);
    const kernel::Moved<double> m =
        General && placed_[i].general
            ? kernel::placed_step(placed_[i], f.sd2, f.role, o.x, o.y, o.z, d.x, d.y, d.z, refracts, eta, n_to, true)
            : kernel::step(f, o.x, o.y, o.z, d.x, d.y, d.z, refracts, eta);
    if (m.status != kernel::kOk) return {static_cast<TraceStatus>(static_cast<int>(m.status)), i, {o, d}};
    o = {m.px, m.py, m.pz};
    d = {m.dx, m.dy, m.dz};
    if (points) points[Forward ? i - first : first - i] = o;
    if (i == last) break;
  }
  // Snell's law keeps |d| = 1 up to rounding; renormalise once so callers can rely on it.
  d *= 1.0 / std::sqrt(glm::dot(d, d));
  return {TraceStatus::Ok, last, {o, d}};
}

// ---- Many rays -------------------------------------------------------------------------------

namespace kernel {

void plate_surface_lanes(const BlockJob& job, int index, Block& block) {
  if (job.per_ray_wavelength)
    job.forward ? placed_surface_lanes<true, true, double>(job, index, block)
                : placed_surface_lanes<false, true, double>(job, index, block);
  else
    job.forward ? placed_surface_lanes<true, false, double>(job, index, block)
                : placed_surface_lanes<false, false, double>(job, index, block);
}

}  // namespace kernel

namespace {

// The batch tracer of each instruction set, where the CPU has it and the library was built
// with it. docs/performance.md has the measurements behind the start-up choice.
using BlockTracer = void (*)(const kernel::BlockJob&, kernel::Block&);
bool isa_available(TraceBatchIsa isa) {
  if (isa == TraceBatchIsa::Baseline) return true;
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  __builtin_cpu_init();  // may run before libgcc's own initialisation (a static initialiser)
  if (isa == TraceBatchIsa::Avx2) return kernel::avx2_compiled() && __builtin_cpu_supports("avx2");
  return kernel::avx512_compiled() && __builtin_cpu_supports("avx512f");
#else
  return false;
#endif
}
BlockTracer tracer_of(TraceBatchIsa isa) {
  switch (isa) {
    case TraceBatchIsa::Avx2: return kernel::trace_block_avx2;
    case TraceBatchIsa::Avx512: return kernel::trace_block_avx512;
    case TraceBatchIsa::Baseline: break;
  }
  return kernel::trace_block_baseline;
}
// The widest the CPU has: each is faster than the one before on this machine (AMD EPYC, Zen 4).
TraceBatchIsa startup_isa() {
  for (TraceBatchIsa isa : {TraceBatchIsa::Avx512, TraceBatchIsa::Avx2})
    if (isa_available(isa)) return isa;
  return TraceBatchIsa::Baseline;
}
// Initialised on first use (a static initialiser elsewhere may trace before this file's run).
std::atomic<BlockTracer>& block_tracer() {
  static std::atomic<BlockTracer> tracer{tracer_of(startup_isa())};
  return tracer;
}

}  // namespace

TraceBatchIsa trace_batch_isa() {
  const BlockTracer t = block_tracer().load(std::memory_order_relaxed);
  for (TraceBatchIsa isa : {TraceBatchIsa::Avx512, TraceBatchIsa::Avx2})
    if (t == tracer_of(isa)) return isa;
  return TraceBatchIsa::Baseline;
}

bool set_trace_batch_isa(TraceBatchIsa isa) {
  if (!isa_available(isa)) return false;
  block_tracer().store(tracer_of(isa), std::memory_order_relaxed);
  return true;
}

const char* to_string(TraceBatchIsa isa) {
  switch (isa) {
    case TraceBatchIsa::Avx2: return "avx2";
    case TraceBatchIsa::Avx512: return "avx512";
    case TraceBatchIsa::Baseline: break;
  }
  return "baseline";
}

void CompiledSystem::trace_range_batch(const Ray* rays, const double* lambda_nm, TraceResult* results,
                                       std::size_t count, int first, int last) const {
  for (std::size_t base = 0; base < count; base += kTraceBatchSize)
    trace_block(rays + base, lambda_nm ? lambda_nm + base : nullptr, results + base,
                std::min(kTraceBatchSize, count - base), first, last);
}

// A block of rays through surfaces first..last, every surface for all lanes at once (a placed
// one by placed_kernel.h's step, a symmetric one by the conic kernel's), so every lane ends with
// the bits of trace_range.
void CompiledSystem::trace_block(const Ray* rays, const double* lambda_nm, TraceResult* results, std::size_t n,
                                 int first, int last) const {
  kernel::Block B;
  for (std::size_t j = 0; j < n; ++j) {
    const glm::dvec3 d = rays[j].direction * (1.0 / std::sqrt(glm::dot(rays[j].direction, rays[j].direction)));
    B.ox[j] = rays[j].origin.x, B.oy[j] = rays[j].origin.y, B.oz[j] = rays[j].origin.z;
    B.dx[j] = d.x, B.dy[j] = d.y, B.dz[j] = d.z;
    B.status[j] = kernel::kOk, B.surface[j] = -1.0;
    B.lambda[j] = lambda_nm ? kernel::clamp_wavelength(lambda_nm[j], wavelength_nm_) : wavelength_nm_;
  }
  // A padding lane starts lost, so nothing it computes is used.
  for (std::size_t j = n; j < kernel::Block::N; ++j) {
    B.ox[j] = B.oy[j] = B.oz[j] = B.dx[j] = B.dy[j] = 0.0, B.dz[j] = 1.0;
    B.status[j] = kernel::code(TraceStatus::Missed), B.surface[j] = -1.0;
    B.lambda[j] = wavelength_nm_;
  }
  block_tracer().load(std::memory_order_relaxed)({interfaces_.data(), laws_.data(), general_ ? placed_.data() : nullptr,
                                                  first, last, first <= last, lambda_nm != nullptr, herzberger_},
                                                 B);
  for (std::size_t j = 0; j < n; ++j) {
    const glm::dvec3 o(B.ox[j], B.oy[j], B.oz[j]);
    glm::dvec3 d(B.dx[j], B.dy[j], B.dz[j]);
    if (B.status[j] == kernel::kOk) {
      d *= 1.0 / std::sqrt(glm::dot(d, d));
      results[j] = {TraceStatus::Ok, last, {o, d}};
    } else {
      results[j] = {static_cast<TraceStatus>(static_cast<int>(B.status[j])), static_cast<int>(B.surface[j]), {o, d}};
    }
  }
}

}  // namespace eyetrace::optics
