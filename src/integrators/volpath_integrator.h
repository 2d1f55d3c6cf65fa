// Volumetric path tracing through homogeneous participating media, as pbrt-v4's "volpath":
// free-flight distances sampled by the hero wavelength's extinction, single-sample spectral
// MIS over the sample's four wavelengths (the ratio spectra r_u and r_l), Henyey-Greenstein
// scattering sampled exactly, next-event estimation from surfaces and from points in media,
// and MIS between light and BSDF/phase sampling. Surfaces without a material ("interface")
// only switch the medium. In homogeneous media, shadow rays carry the exact transmittance
// exp(-sigma_t d) of each segment (no null collisions needed); heterogeneous media (grids,
// clouds) are crossed by delta tracking against their majorants and shadow rays through them
// by ratio tracking, with pbrt-v4's spectral MIS updates at null collisions. The MIS weights
// of both, and how they combine on one shadow ray, are derived at
// VolPathIntegrator::sample_light in the .cpp.
// Scenes without media are rendered by PathIntegrator instead (create_volpath_integrator).
#pragma once
#include "integrators/light_sampler.h"
#include "integrators/russian_roulette.h"
#include "render/integrator.h"

namespace eyetrace {

struct SurfaceInteraction;
class BSDF;
class BSSRDF;
class Medium;

class VolPathIntegrator : public Integrator {
 public:
  VolPathIntegrator(const Scene& scene, int max_depth, RussianRoulette roulette = {});
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

  // What a path carries from vertex to vertex.
  struct PathState {
    SampledSpectrum L{0.f}, beta{1.f}, r_u{1.f}, r_l{1.f};
    int depth = 0;
    bool specular_bounce = false;
    LightSampleContext prev_ctx;
  };
  // A shadow ray's transmittance estimate and the factors its segments put into the light
  // (r_l) and scatter (r_u) strategies' ratio spectra.
  struct ShadowTransmittance {
    SampledSpectrum T{1.f}, r_l{1.f}, r_u{1.f};
  };

 private:
  // One light sample, one shadow ray (through interfaces), MIS-weighted; beta and r_p are the
  // path's throughput and ratio spectrum up to the scattering point.
  SampledSpectrum sample_light(const Scatterer& at, const SampledSpectrum& beta, const SampledSpectrum& r_p,
                               const SampledWavelengths& lambda, Sampler& sampler, RayTally& tally) const;
  // Transmittance along a shadow ray through media and interfaces; zero if a surface with a
  // material blocks it.
  ShadowTransmittance transmittance(Ray ray, const Medium* medium, const Vec3& p_to, const Vec3& err_to,
                                    const Vec3& n_to, const SampledWavelengths& lambda, RayTally& tally) const;
  enum class MediumEvent { Passed, Scattered, Terminated };
  // Delta tracking of `ray` (unit direction) through a heterogeneous medium up to t_end:
  // absorption, emission, real scattering (with next-event estimation; `ray` then leaves the
  // scattering point) or passing the segment, with the throughput and ratios updated.
  MediumEvent delta_track(const Medium& medium, Ray& ray, float t_end, PathState& s, const SampledWavelengths& lambda,
                          Sampler& sampler, RayTally& tally) const;
  // After a transmission into a subsurface material at `entry` (its BSSRDF there): moves the path to a sampled
  // exit point (r_u takes every wavelength's density of it), samples light there and Sw for the
  // next ray; `medium` becomes the one the new ray leaves into. False ends the path.
  bool continue_from_subsurface_exit(const SurfaceInteraction& entry, const BSSRDF& bssrdf, SampledWavelengths& lambda,
                                     Sampler& sampler, ScratchBuffer& arena, RayTally& tally, SampledSpectrum& beta,
                                     SampledSpectrum& r_u, SampledSpectrum& r_l, SampledSpectrum& L, Ray& ray,
                                     const Medium*& medium, LightSampleContext& prev_ctx) const;
  int max_depth_;
  RussianRoulette roulette_;
  PowerLightSampler lights_;
};

}  // namespace eyetrace
