// Exact real-ray trace through a sequential system, forward (object -> image) and in reverse
// (image -> object, as the renderer's eye camera traces from a retina point out into the world).
// A Prescription is compiled once into a flat array of interfaces; tracing then allocates
// nothing, throws nothing and reports every lost ray by kind instead of producing NaN. Each ray
// can be traced at its own wavelength: the indices then come from the media's dispersion laws.
// One kernel (trace_kernel.h) intersects and refracts for the single-ray and the batched trace.
// In a system that is not rotationally symmetric the placed surfaces (a biconic surface, a
// decentred or tilted surface or iris, a phase plate) take the general step instead, each
// surface in its own frame (placed_surface.h, placed_kernel.h; the same code for one ray and for
// a batch's lanes, a phase plate's surface lane by lane); its symmetric, unplaced surfaces still
// go through the kernel. A symmetric system never enters that step, so its results are those of
// the kernel, bit for bit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "optics/placed_surface.h"
#include "optics/prescription.h"

namespace eyetrace::optics {

enum class TraceStatus : std::uint8_t {
  Ok,
  Missed,                   // the ray does not meet the surface (or only behind itself)
  Vignetted,                // meets it outside the semi-diameter
  StopBlocked,              // meets the aperture stop outside its opening
  TotalInternalReflection,  // cannot refract into the next medium
  NoConvergence,            // the iterative intersection of a biconic gave up (biconic_surface.h)
};

const char* to_string(TraceStatus status);

// Position in mm in the system frame (z = 0 at the first vertex); direction of unit length.
struct Ray {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, 1.0};
};

struct TraceResult {
  TraceStatus status = TraceStatus::Ok;
  // Ok: the last surface visited. Otherwise: the surface at which the ray was lost.
  int surface = -1;
  // Ok: origin on the last surface visited, direction after it (unit length; at the image
  // surface the direction of arrival). Lost: the ray as it was just before the failing
  // surface, so it is always finite for a finite input.
  Ray ray;

  bool ok() const { return status == TraceStatus::Ok; }
};

// Rays the batch trace works on at once, in structure-of-arrays form (trace_kernel.h): callers
// that gather rays for trace_range_batch gather this many (any count is accepted).
inline constexpr std::size_t kTraceBatchSize = 16;

// The instruction set the batch trace runs on: AVX-512F (8 rays a register) or AVX2 (4) where
// the CPU has it and the build targets it, else the baseline (SSE2 on x86-64, 2 rays a
// register); the widest is chosen at start-up. The results are the same bits on each. Tests
// and benchmarks may switch; set_trace_batch_isa returns false (and changes nothing) when the
// CPU or build lacks the set.
enum class TraceBatchIsa { Baseline, Avx2, Avx512 };
TraceBatchIsa trace_batch_isa();
bool set_trace_batch_isa(TraceBatchIsa isa);
const char* to_string(TraceBatchIsa isa);

namespace trace_detail {

// The compiled form of one surface, as the kernel (trace_kernel.h) reads it.
struct Interface {
  double z;            // vertex position
  double c;            // curvature
  double k;            // 1 + conic
  double kc;           // k c
  double sd2;          // semi-diameter squared, +inf when unlimited
  double n_before;     // index before (object side) at the compiled wavelength
  double n_after;      // index after (image side) at the compiled wavelength
  double eta_forward;  // n_before / n_after, 1 when the surface does not refract
  double eta_reverse;  // n_after / n_before, likewise
  SurfaceRole role;
  bool plane;  // c == 0: every ray meets it in one point or not at all
  // At any other wavelength: each side's medium is either one of CompiledSystem's dispersion
  // laws (law >= 0) or has the same index at every wavelength (law < 0: that index).
  struct Side {
    int law = -1;
    double index = 1.0;
  };
  Side before, after;
  // Both sides constant: n_before / n_after and its inverse from the media table (1 when the
  // surface does not refract), the same at every wavelength.
  double eta_forward_any = 1.0, eta_reverse_any = 1.0;
};

// A medium's index at any wavelength, Medium::index_at: index + law(lambda) - law(reference).
struct MediumLaw {
  Dispersion dispersion;
  double index;
  double reference_nm;
  double at_reference;  // dispersion.evaluate(reference_nm)
};

}  // namespace trace_detail

class CompiledSystem {
 public:
  // Validates the prescription (throws OpticsError) and flattens it. The indices at the
  // prescription's wavelength are the surfaces' index_after; at any other wavelength they are
  // those at_wavelength(prescription, lambda) gives: each surface's medium from the media
  // table, re-evaluated by its dispersion law (a medium the table lacks keeps the surface's
  // index at every wavelength, where at_wavelength would throw).
  explicit CompiledSystem(const Prescription& prescription);

  int surface_count() const { return static_cast<int>(interfaces_.size()); }
  int stop_index() const { return stop_index_; }
  int image_index() const { return surface_count() - 1; }
  double vertex_z(int surface) const { return interfaces_[surface].z; }
  double index_before(int surface) const { return interfaces_[surface].n_before; }
  double index_after(int surface) const { return interfaces_[surface].n_after; }
  // The wavelength the system was compiled at (the prescription's wavelength_nm).
  double wavelength_nm() const { return wavelength_nm_; }
  // True when some medium has a dispersion law: then the trace depends on the wavelength.
  bool dispersive() const { return !laws_.empty(); }
  // Indices at lambda_nm as the per-wavelength trace uses them (the kernel's own evaluation).
  double index_before(int surface, double lambda_nm) const;
  double index_after(int surface, double lambda_nm) const;

  // Object space -> image surface: the ray starts in object space (index object_index) in
  // front of surface 0 and ends on the image surface.
  TraceResult trace_forward(const Ray& ray) const { return trace_range(ray, 0, image_index()); }
  // Image space -> object space: the ray starts on (or in front of) the image surface in the
  // last medium, travels towards -z through surfaces image-1 ... 0 and leaves into object
  // space; the result's origin is on surface 0.
  TraceResult trace_reverse(const Ray& ray) const { return trace_range(ray, image_index() - 1, 0); }
  // Visits surfaces first, first +- 1, ..., last (inclusive). first <= last traces forward
  // with the ray in the medium before `first`; first > last traces in reverse with the ray in
  // the medium after `first`. E.g. trace_range(r, image_index() - 1, stop_index()) brings a
  // retina ray to the stop plane (ray aiming). If points is not null it receives the hit
  // point of every surface reached, |last - first| + 1 entries at most.
  TraceResult trace_range(const Ray& ray, int first, int last, glm::dvec3* points = nullptr) const;
  // The same at wavelength lambda_nm: equal, bit for bit, to the trace through
  // CompiledSystem(at_wavelength(prescription, lambda_nm)). A wavelength outside
  // [kMinWavelength_nm, kMaxWavelength_nm] is clamped into it and NaN means the compiled
  // wavelength, so the trace still never throws.
  TraceResult trace_range(const Ray& ray, int first, int last, double lambda_nm, glm::dvec3* points = nullptr) const;

  // The same for many rays at once: results[j] is what trace_range(rays[j], first, last,
  // lambda_nm[j]) gives, bit for bit; lambda_nm == nullptr traces every ray at the compiled
  // wavelength, as trace_range(rays[j], first, last). Faster per ray: rays go in batches of
  // kTraceBatchSize, several per SIMD register, through every surface (a surface with a phase
  // plate takes them one at a time; a biconic's rare rays that its Newton iteration does not
  // settle are searched one at a time, biconic_kernel.h). No allocation.
  void trace_range_batch(const Ray* rays, const double* lambda_nm, TraceResult* results, std::size_t count, int first,
                         int last) const;
  void trace_range_batch(const Ray* rays, TraceResult* results, std::size_t count, int first, int last) const {
    trace_range_batch(rays, nullptr, results, count, first, last);
  }
  void trace_reverse_batch(const Ray* rays, TraceResult* results, std::size_t count) const {
    trace_range_batch(rays, nullptr, results, count, image_index() - 1, 0);
  }

  // The optical path (mm) a phase plate on `surface` adds to a ray that crosses it at `point`
  // (system frame): -W there (phase_plate.h); 0 for a surface without one. The trace bends rays
  // by the plates but sums no path; the wavefront (wavefront.h) adds this to its own sum.
  double plate_path_mm(int surface, const glm::dvec3& point) const;

  // False when some surface is biconic, placed or carries a phase plate: then every trace takes
  // the general step on those surfaces.
  bool rotationally_symmetric() const { return !general_; }

  // The compiled data as the kernel reads it (trace_kernel.h).
  const std::vector<trace_detail::Interface>& interfaces() const { return interfaces_; }
  const std::vector<trace_detail::MediumLaw>& laws() const { return laws_; }

 private:
  template <bool Forward, bool PerRayWavelength, bool General = false>
  TraceResult trace_one(const Ray& ray, int first, int last, double lambda_nm, glm::dvec3* points) const;
  void trace_block(const Ray* rays, const double* lambda_nm, TraceResult* results, std::size_t n, int first,
                   int last) const;

  std::vector<trace_detail::Interface> interfaces_;
  std::vector<trace_detail::MediumLaw> laws_;        // the distinct media with a dispersion law
  std::vector<trace_detail::PlacedSurface> placed_;  // per surface; used by the general path only
  bool general_ = false;                             // some surface is biconic, placed or has a plate
  int stop_index_ = -1;
  double wavelength_nm_ = 0.0;
  bool herzberger_ = false;  // some law needs the Herzberger weights of the wavelength
};

}  // namespace eyetrace::optics
