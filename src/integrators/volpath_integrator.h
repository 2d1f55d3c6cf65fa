// Volumetric path tracing through homogeneous participating media, as pbrt-v4's "volpath":
// free-flight distances sampled by the hero wavelength's extinction, single-sample spectral
// MIS over the sample's four wavelengths (the ratio spectra r_u and r_l), Henyey-Greenstein
// scattering sampled exactly, next-event estimation from surfaces and from points in media,
// and MIS between light and BSDF/phase sampling. Surfaces without a material ("interface")
// only switch the medium. Shadow rays carry the exact transmittance exp(-sigma_t d) of each
// segment (homogeneous media need no null collisions); the MIS weights follow from that (the
// derivation is at VolPathIntegrator::sample_light in the .cpp).
// Scenes without media are rendered by PathIntegrator instead (create_volpath_integrator).
#pragma once
#include "integrators/light_sampler.h"
#include "render/integrator.h"

namespace eyetrace {

struct SurfaceInteraction;
class BSDF;
class BSSRDF;
class Medium;

class VolPathIntegrator : public Integrator {
 public:
  VolPathIntegrator(const Scene& scene, int max_depth, float rr_threshold);
  SampledSpectrum radiance(const Ray& ray, SampledWavelengths& lambda, Sampler& sampler, ScratchBuffer& arena,
                           RayTally& tally, VisibleSurface* visible = nullptr) const override;
  std::string to_string() const override;

  // Where a path scatters: a surface point with its BSDF, or a point in a medium.
  struct Scatterer {
    Vec3 p{0.f}, p_error{0.f}, n{0.f};  // n zero in a medium
    float time = 0.f;
    const SurfaceInteraction* si = nullptr;  // surfaces
    const BSDF* bsdf = nullptr;
    Vec3 d_in{0.f};  // media: the direction the path arrived in
    float g = 0.f;
    const Medium* medium = nullptr;  // the medium the path is in at p
  };

 private:
  // One light sample, one shadow ray (through interfaces), MIS-weighted; beta and r_p are the
  // path's throughput and ratio spectrum up to the scattering point.
  SampledSpectrum sample_light(const Scatterer& at, const SampledSpectrum& beta, const SampledSpectrum& r_p,
                               const SampledWavelengths& lambda, Sampler& sampler, RayTally& tally) const;
  // Transmittance along a shadow ray through media and interfaces; zero if a surface with a
  // material blocks it.
  SampledSpectrum transmittance(Ray ray, const Medium* medium, const Vec3& p_to, const Vec3& err_to, const Vec3& n_to,
                                const SampledWavelengths& lambda, RayTally& tally) const;
  // After a transmission into a subsurface material at `entry` (its BSSRDF there): moves the path to a sampled
  // exit point (r_u takes every wavelength's density of it), samples light there and Sw for the
  // next ray; `medium` becomes the one the new ray leaves into. False ends the path.
  bool continue_from_subsurface_exit(const SurfaceInteraction& entry, const BSSRDF& bssrdf, SampledWavelengths& lambda,
                                     Sampler& sampler, ScratchBuffer& arena, RayTally& tally, SampledSpectrum& beta,
                                     SampledSpectrum& r_u, SampledSpectrum& r_l, SampledSpectrum& L, Ray& ray,
                                     const Medium*& medium, LightSampleContext& prev_ctx) const;
  int max_depth_;
  float rr_threshold_;
  PowerLightSampler lights_;
};

}  // namespace eyetrace
