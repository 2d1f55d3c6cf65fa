// BSSRDF interface: subsurface transport from where a path entered a translucent object to
// where it leaves, S(po, wo, pi, wi) = (1 - Fr) Sp(po, pi) Sw(wi) in pbrt-v4's separable
// form. The entry's refraction is the material's BSDF; the integrator then samples a probe
// segment (sample_sp), finds the surface points on it that belong to the same material, picks
// one and turns it into the exit: Sp with its density over the surface (per wavelength, for
// spectral MIS) and the Sw BSDF there.
#pragma once
#include <optional>

#include "core/arena.h"
#include "core/bsdf.h"
#include "core/interaction.h"
#include "core/sampled_spectrum.h"

namespace eyetrace {

struct BSSRDFProbeSegment {
  Vec3 p0{0.f}, p1{0.f};
};

struct BSSRDFSample {
  SampledSpectrum sp{0.f};   // spatial profile Sp(po, pi)
  SampledSpectrum pdf{0.f};  // density of pi per unit area, per wavelength (before the choice among hits)
  const BSDF* sw = nullptr;  // directional term at pi, with pi's shading normal as wo
};

class BSSRDF {
 public:
  virtual ~BSSRDF() = default;
  // u1 chooses the probe axis; u2 the radius and angle. Empty when the radius falls beyond the
  // profile's support.
  virtual std::optional<BSSRDFProbeSegment> sample_sp(float u1, Vec2 u2) const = 0;
  // `exit`: a hit on the probe segment with the entry's material.
  virtual BSSRDFSample probe_intersection_to_sample(const SurfaceInteraction& exit, ScratchBuffer& arena) const = 0;
};

}  // namespace eyetrace
