// A participating medium as the volumetric path tracer sees it: absorption and scattering
// coefficients (per unit length) and emitted radiance at the sample's wavelengths, and the
// Henyey-Greenstein asymmetry of its phase function, at a point (render space), and majorants
// along a ray (core/majorant.h) for delta and ratio tracking. A homogeneous medium says so
// (is_homogeneous): its properties do not depend on the point, and the integrator then uses
// the exact transmittance exp(-sigma_t d) (Beer-Lambert) instead of tracking.
#pragma once
#include "core/majorant.h"
#include "core/math.h"
#include "core/ray.h"
#include "core/sampled_spectrum.h"

namespace eyetrace {

struct MediumProperties {
  SampledSpectrum sigma_a, sigma_s, Le;  // Le: radiance emitted per unit sigma_a
  float g = 0.f;                         // Henyey-Greenstein asymmetry, in (-1, 1)
};

class Medium {
 public:
  virtual ~Medium() = default;
  // Properties at render-space point p.
  virtual MediumProperties properties(const Vec3& p, const SampledWavelengths& lambda) const = 0;
  // Properties of a homogeneous medium (anywhere).
  MediumProperties properties(const SampledWavelengths& lambda) const { return properties(Vec3(0.f), lambda); }
  // True when the properties are the same everywhere (volpath's exact path).
  virtual bool is_homogeneous() const { return false; }
  // The majorant segments of `ray` (render space, unit direction) over [0, t_max]; every
  // point's sigma_a + sigma_s is at most its segment's sigma_maj at every wavelength, and
  // points outside every segment have none.
  virtual MajorantIterator majorants(const Ray& ray, float t_max, const SampledWavelengths& lambda) const = 0;
  // Whether Le is zero at every wavelength and point (the integrator then skips emission).
  virtual bool emissive() const = 0;
};

// The media on the two sides of a surface: `inside` opposite the geometric normal, `outside`
// where it points (pbrt-v4's MediumInterface). Null is vacuum.
struct MediumInterface {
  const Medium* inside = nullptr;
  const Medium* outside = nullptr;
  // A surface with the same medium on both sides bounds nothing: rays keep their medium.
  bool is_transition() const { return inside != outside; }
  // The medium a ray leaving the surface in direction w travels through.
  const Medium* towards(const Vec3& w, const Vec3& n) const { return glm::dot(w, n) > 0.f ? outside : inside; }
};

}  // namespace eyetrace
