// The subsurface step of a path (pbrt-v4's VolPathIntegrator, "attenuated subsurface
// scattering"): after the path refracts into a material with a BSSRDF at `entry`, sample a
// probe segment, collect the probe's hits on that same material, choose one uniformly
// (reservoir sampling) and return it as the exit point with its Sw BSDF and the path weight
// Sp / (P(choice) pdf). The weight divides by the pdf averaged over the carried wavelengths
// (one-sample spectral MIS: the radius was sampled at the hero wavelength's coefficients),
// which is pbrt-v4's r_u bookkeeping folded into the throughput.
#pragma once
#include <optional>

#include "core/bssrdf.h"
#include "core/sampler.h"
#include "render/integrator.h"
#include "render/scene.h"

namespace eyetrace {

struct SubsurfaceExit {
  SurfaceInteraction si;  // wo is the exit's shading normal (pbrt-v4's Sw convention)
  const BSDF* sw = nullptr;
  SampledSpectrum weight{0.f};
};

// Consumes four sampler dimensions (1D axis, 2D radius and angle, 1D choice) whatever happens.
std::optional<SubsurfaceExit> sample_subsurface_exit(const Scene& scene, const BSSRDF& bssrdf,
                                                     const SurfaceInteraction& entry, const SampledWavelengths& lambda,
                                                     Sampler& sampler, ScratchBuffer& arena, RayTally& tally);

}  // namespace eyetrace
