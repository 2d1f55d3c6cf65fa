// The subsurface step of a path (pbrt-v4's VolPathIntegrator, "attenuated subsurface
// scattering"): after the path refracts into a material with a BSSRDF at `entry`, sample a
// probe segment, collect the probe's hits on that same material, choose one uniformly
// (reservoir sampling) and return it as the exit point with its Sw BSDF, Sp and the density of
// having found it, P(choice) pdf, per wavelength: the radius was sampled at the hero
// wavelength's coefficients, so each wavelength's density is that of its own strategy (spectral
// MIS, pbrt-v4's r_u).
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
  SampledSpectrum sp{0.f};
  SampledSpectrum pdf{0.f};  // P(choice) x density per unit area; pdf[0] > 0
  // The throughput factor for an integrator without spectral MIS bookkeeping: Sp over the
  // density averaged over the carried wavelengths (one-sample MIS, balance heuristic), or the
  // hero's alone once the others are terminated.
  SampledSpectrum weight(const SampledWavelengths& lambda) const {
    return sp / (lambda.secondary_terminated() ? pdf[0] : pdf.average());
  }
};

// Consumes four sampler dimensions (1D axis, 2D radius and angle, 1D choice) whatever happens.
std::optional<SubsurfaceExit> sample_subsurface_exit(const Scene& scene, const BSSRDF& bssrdf,
                                                     const SurfaceInteraction& entry, const SampledWavelengths& lambda,
                                                     Sampler& sampler, ScratchBuffer& arena, RayTally& tally);

}  // namespace eyetrace
