// A participating medium as the volumetric path tracer sees it: absorption and scattering
// coefficients (per unit length) and emitted radiance at the sample's wavelengths, and the
// Henyey-Greenstein asymmetry of its phase function. Only homogeneous media exist today, so
// the properties do not depend on the point; a ray's transmittance over a distance d is
// exactly exp(-sigma_t d) (Beer-Lambert).
#pragma once
#include "core/math.h"
#include "core/sampled_spectrum.h"

namespace eyetrace {

struct MediumProperties {
  SampledSpectrum sigma_a, sigma_s, Le;  // Le: radiance emitted per unit sigma_a
  float g = 0.f;                         // Henyey-Greenstein asymmetry, in (-1, 1)
};

class Medium {
 public:
  virtual ~Medium() = default;
  virtual MediumProperties properties(const SampledWavelengths& lambda) const = 0;
  // Whether Le is zero at every wavelength (the integrator then skips emission).
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
