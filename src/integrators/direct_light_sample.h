// Next-event estimation at a surface point, shared by the path and SPPM integrators: one light
// chosen by power, one point on it, one shadow ray, weighted against BSDF sampling by the power
// heuristic (delta lights, which BSDF sampling cannot hit, take the whole estimate).
#pragma once
#include "core/sampled_spectrum.h"
#include "core/sampler.h"
#include "integrators/light_sampler.h"
#include "render/integrator.h"

namespace eyetrace {

class Scene;
struct SurfaceInteraction;
class BSDF;

// Draws a 1-D sample (the light) and a 2-D sample (the point on it) from `sampler`, in that order.
// A sample that cannot contribute (no light, zero radiance or density, f cos = 0) traces no shadow
// ray and counts in tally.shadow_rays_skipped.
SampledSpectrum sample_one_light(const Scene& scene, const PowerLightSampler& lights, const SurfaceInteraction& si,
                                 const BSDF& bsdf, const SampledWavelengths& lambda, Sampler& sampler, RayTally& tally);

}  // namespace eyetrace
