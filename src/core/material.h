// Material interface: builds the BSDF at a hit for the sample's wavelengths, in per-sample
// scratch memory. A material whose BSDF would send each wavelength its own way (a dispersive
// dielectric) keeps only the hero wavelength (SampledWavelengths::terminate_secondary).
#pragma once
#include "core/arena.h"
#include "core/bsdf.h"
#include "core/interaction.h"
#include "core/sampled_spectrum.h"

namespace eyetrace {

class Material {
 public:
  virtual ~Material() = default;
  virtual const BSDF* bsdf(const SurfaceInteraction& si, SampledWavelengths& lambda, ScratchBuffer& arena) const = 0;
};

}  // namespace eyetrace
