// Material interface: builds the BSDF at a hit for the sample's wavelengths, in per-sample
// scratch memory. A material whose BSDF would send each wavelength its own way (a dispersive
// dielectric) keeps only the hero wavelength (SampledWavelengths::terminate_secondary).
#pragma once
#include "core/arena.h"
#include "core/bsdf.h"
#include "core/bssrdf.h"
#include "core/interaction.h"
#include "core/sampled_spectrum.h"

namespace eyetrace {

class Material {
 public:
  virtual ~Material() = default;
  virtual const BSDF* bsdf(const SurfaceInteraction& si, SampledWavelengths& lambda, ScratchBuffer& arena) const = 0;
  // Whether light refracted into the surface scatters below it and leaves elsewhere (the
  // "subsurface" material); the integrator then asks bssrdf() at each transmission.
  virtual bool has_subsurface() const { return false; }
  // The BSSRDF at the entry point `si` (as given to bsdf()); null without subsurface scattering.
  virtual const BSSRDF* bssrdf(const SurfaceInteraction& /*si*/, const SampledWavelengths& /*lambda*/,
                               ScratchBuffer& /*arena*/) const {
    return nullptr;
  }
};

}  // namespace eyetrace
