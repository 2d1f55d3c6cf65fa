// Exact real-ray trace through a sequential system, forward (object -> image) and in reverse
// (image -> object, as the renderer's eye camera traces from a retina point out into the world).
// A Prescription is compiled once into a flat array of interfaces; tracing then allocates
// nothing, throws nothing and reports every lost ray by kind instead of producing NaN.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "optics/prescription.h"

namespace eyetrace::optics {

enum class TraceStatus : std::uint8_t {
  Ok,
  Missed,                   // the ray does not meet the surface (or only behind itself)
  Vignetted,                // meets it outside the semi-diameter
  StopBlocked,              // meets the aperture stop outside its opening
  TotalInternalReflection,  // cannot refract into the next medium
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

class CompiledSystem {
 public:
  // Validates the prescription (throws OpticsError) and flattens it.
  explicit CompiledSystem(const Prescription& prescription);

  int surface_count() const { return static_cast<int>(interfaces_.size()); }
  int stop_index() const { return stop_index_; }
  int image_index() const { return surface_count() - 1; }
  double vertex_z(int surface) const { return interfaces_[surface].z; }
  double index_before(int surface) const { return interfaces_[surface].n_before; }
  double index_after(int surface) const { return interfaces_[surface].n_after; }

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

  // The same for many rays at once (results[j] as trace_range(rays[j], first, last) would
  // give, bit for bit). Faster per ray: see sequential_trace.cpp. No allocation.
  void trace_range_batch(const Ray* rays, TraceResult* results, std::size_t count, int first, int last) const;
  void trace_reverse_batch(const Ray* rays, TraceResult* results, std::size_t count) const {
    trace_range_batch(rays, results, count, image_index() - 1, 0);
  }

 private:
  struct Interface {
    double z;            // vertex position
    double c;            // curvature
    double k;            // 1 + conic
    double sd2;          // semi-diameter squared, +inf when unlimited
    double n_before;     // index before (object side)
    double n_after;      // index after (image side)
    double eta_forward;  // n_before / n_after, 1 when the surface does not refract
    double eta_reverse;  // n_after / n_before, likewise
    SurfaceRole role;
  };
  struct Lanes;  // rays of a batch in structure-of-arrays form (sequential_trace.cpp)
  template <bool Forward>
  static TraceStatus step(const Interface& f, glm::dvec3& o, glm::dvec3& d);
  template <bool Forward>
  static void batch_step(const Interface& f, int index, Lanes& lanes, std::size_t n);
  void trace_lanes(const Ray* rays, TraceResult* results, std::size_t n, int first, int last) const;
  template <bool Forward>
  TraceResult trace_impl(const Ray& ray, int first, int last, glm::dvec3* points) const;

  std::vector<Interface> interfaces_;
  int stop_index_ = -1;
};

}  // namespace eyetrace::optics
