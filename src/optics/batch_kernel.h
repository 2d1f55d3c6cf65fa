// The batch trace: a block of kTraceBatchSize rays, in structure-of-arrays form, through a range
// of surfaces, every lane of a surface at once. A rotationally symmetric surface takes the conic
// kernel's step (trace_kernel.h), a placed one (a biconic, a tilted or decentred surface)
// placed_kernel.h's, both for the lane type V; a surface with a phase plate is taken lane by lane
// (V = double). Each lane does the one-ray trace's arithmetic (CompiledSystem::trace_one), so it
// ends with its bits.
//
// Internal to the optics library: included by sequential_trace.cpp (the lane-by-lane helpers),
// trace_kernel_baseline.cpp, trace_kernel_avx2.cpp and trace_kernel_avx512.cpp (the same code
// compiled for the baseline, AVX2 and AVX-512F, chosen at run time).
#pragma once

#include <array>
#include <cstddef>

#include "optics/placed_kernel.h"

namespace eyetrace::optics::kernel {

// kTraceBatchSize rays in structure-of-arrays form: what the batch trace works on.
struct Block {
  static constexpr std::size_t N = kTraceBatchSize;
  alignas(64) double ox[N], oy[N], oz[N];
  alignas(64) double dx[N], dy[N], dz[N];
  alignas(64) double status[N];   // the lane's TraceStatus (Ok = 0 while it travels)
  alignas(64) double surface[N];  // where a lost lane was lost
  alignas(64) double lambda[N];   // per-ray wavelength (nm), already clamped
  alignas(64) double n[N];        // per-ray wavelength: index of the medium the ray is in
  alignas(64) double w[4][N];     // per-ray wavelength: Herzberger weights of lambda
};

struct BlockJob {
  const Interface* interfaces;
  const MediumLaw* laws;
  const trace_detail::PlacedSurface* placed;  // per surface, or null when none is general
  int first, last;
  bool forward;             // towards the image (first <= last) or away from it (first >= last)
  bool per_ray_wavelength;  // Block::lambda is set; else the compiled indices
  bool herzberger;          // some law is Navarro-Herzberger (the weights are needed)
};

// Traces a block through surfaces first..last (lanes not Ok at the start stay as they are).
// The same template (below) compiled for the baseline instruction set (trace_kernel_baseline.cpp)
// and, on x86-64, for AVX2 (trace_kernel_avx2.cpp) and AVX-512F (trace_kernel_avx512.cpp).
void trace_block_baseline(const BlockJob& job, Block& block);
void trace_block_avx2(const BlockJob& job, Block& block);
void trace_block_avx512(const BlockJob& job, Block& block);
bool avx2_compiled();    // trace_block_avx2 exists (x86-64 with a compiler that targets AVX2)
bool avx512_compiled();  // trace_block_avx512 exists (the same for AVX-512F)
// Surface `index`, which has a phase plate, lane by lane (placed_kernel.h steps a plate at
// V = double only); compiled once, in the baseline build (sequential_trace.cpp), so no AVX2
// copy of the plate's inline helpers exists.
void plate_surface_lanes(const BlockJob& job, int index, Block& block);

// Internal linkage, as in trace_kernel.h: no function here may be merged with its AVX2 twin.
namespace {

template <class V>
V load(const double* p) {
  return Lanes<V>::load(p);
}
template <class V>
void store(const V& x, double* p) {
  Lanes<V>::store(x, p);
}

// One surface for every lane: step_lanes(f, o, d, refracts, eta, n_to, alive) is the conic
// kernel's step or a placed surface's.
template <bool Forward, bool PerRayWavelength, class V, class Step>
EYETRACE_KERNEL_INLINE void block_surface(const BlockJob& job, int index, Block& B, const Step& step_lanes) {
  const Interface& f = job.interfaces[index];
  // Only a surface whose far side has a law of its own needs the wavelength and its weights.
  const Interface::Side& from = Forward ? f.before : f.after;
  const Interface::Side& to = Forward ? f.after : f.before;
  const bool evaluates = PerRayWavelength && to.law >= 0 && to.law != from.law;
  for (std::size_t j = 0; j < Block::N; j += Lanes<V>::size) {
    const V ox = load<V>(B.ox + j), oy = load<V>(B.oy + j), oz = load<V>(B.oz + j);
    const V dx = load<V>(B.dx + j), dy = load<V>(B.dy + j), dz = load<V>(B.dz + j);
    V lambda(0.0), n(0.0);
    std::array<V, 4> w{V(0.0), V(0.0), V(0.0), V(0.0)};
    if (evaluates) {
      lambda = load<V>(B.lambda + j);
      if (job.herzberger)
        for (int i = 0; i < 4; ++i) w[i] = load<V>(B.w[i] + j);
    }
    if (PerRayWavelength) n = load<V>(B.n + j);
    Eta<V> eta;
    const bool refracts = refraction_at<Forward, PerRayWavelength>(f, job.laws, lambda, w, n, eta);
    if (PerRayWavelength) store(n, B.n + j);
    // The index of the medium the ray leaves into (a phase plate's rule needs it).
    const V n_to = PerRayWavelength ? n : V(Forward ? f.n_after : f.n_before);

    const V status = load<V>(B.status + j);
    const Mask<V> alive = status == kOk;
    const Moved<V> m = step_lanes(f, ox, oy, oz, dx, dy, dz, refracts, eta, n_to, alive);
    const Mask<V> moves = alive & (m.status == kOk);
    store(select(alive, m.status, status), B.status + j);
    store(select(alive & !moves, V(static_cast<double>(index)), load<V>(B.surface + j)), B.surface + j);
    store(select(moves, m.px, ox), B.ox + j);
    store(select(moves, m.py, oy), B.oy + j);
    store(select(moves, m.pz, oz), B.oz + j);
    store(select(moves, m.dx, dx), B.dx + j);
    store(select(moves, m.dy, dy), B.dy + j);
    store(select(moves, m.dz, dz), B.dz + j);
  }
}

// A placed surface (not one with a phase plate: plate_surface_lanes) for every lane.
template <bool Forward, bool PerRayWavelength, class V>
void placed_surface_lanes(const BlockJob& job, int index, Block& B) {
  const trace_detail::PlacedSurface& s = job.placed[index];
  block_surface<Forward, PerRayWavelength, V>(
      job, index, B,
      [&s](const Interface& f, const auto& ox, const auto& oy, const auto& oz, const auto& dx, const auto& dy,
           const auto& dz, bool refracts, const auto& eta, const auto& n_to, const auto& alive) {
        return placed_step(s, f.sd2, f.role, ox, oy, oz, dx, dy, dz, refracts, eta, n_to, alive);
      });
}

template <bool Forward, bool PerRayWavelength, class V>
void block_step(const BlockJob& job, int index, Block& B) {
  const trace_detail::PlacedSurface* s = job.placed ? job.placed + index : nullptr;
  if (s && s->general) {
    if (s->plate)
      plate_surface_lanes(job, index, B);
    else
      placed_surface_lanes<Forward, PerRayWavelength, V>(job, index, B);
    return;
  }
  block_surface<Forward, PerRayWavelength, V>(
      job, index, B,
      [](const Interface& f, const auto& ox, const auto& oy, const auto& oz, const auto& dx, const auto& dy,
         const auto& dz, bool refracts, const auto& eta, const auto&,
         const auto&) { return step(f, ox, oy, oz, dx, dy, dz, refracts, eta); });
}

// Surface after surface, every lane of the block at once: the surfaces' square roots and
// divisions of Block::N / V::size registers overlap, where one ray would wait for each in turn.
template <class V>
void trace_block(const BlockJob& job, Block& B) {
  static_assert(Block::N % V::size == 0);
  const bool forward = job.forward;  // first == last has either direction
  if (job.per_ray_wavelength) {
    // The weights of each lane's wavelength, and the index of the medium it starts in.
    const Interface& f = job.interfaces[job.first];
    const Interface::Side& start = forward ? f.before : f.after;
    for (std::size_t j = 0; j < Block::N; j += V::size) {
      const V lambda = load<V>(B.lambda + j);
      std::array<V, 4> w{V(0.0), V(0.0), V(0.0), V(0.0)};
      if (job.herzberger) {
        w = dispersion::herzberger_weights(lambda);
        for (int i = 0; i < 4; ++i) store(w[i], B.w[i] + j);
      }
      store(side_index(start, job.laws, lambda, w), B.n + j);
    }
  }
  for (int i = job.first;; i += forward ? 1 : -1) {
    if (job.per_ray_wavelength)
      forward ? block_step<true, true, V>(job, i, B) : block_step<false, true, V>(job, i, B);
    else
      forward ? block_step<true, false, V>(job, i, B) : block_step<false, false, V>(job, i, B);
    if (i == job.last) break;
  }
}

}  // namespace
}  // namespace eyetrace::optics::kernel
