// pbrt-v4's "homogeneous" medium: the same absorption, scattering and emission everywhere.
// Parameters and defaults as pbrt-v4's HomogeneousMedium::Create: "sigma_a" and "sigma_s"
// (unbounded spectra, default 1 per unit length), both multiplied by "scale"; "g", the
// Henyey-Greenstein asymmetry; "Le" (an illuminant spectrum, default 0: no emission) times
// "Lescale". A "preset" names one of pbrt-v4's measured media (core/measured_media.h) in
// place of "sigma_a" and "sigma_s".
#pragma once
#include <memory>

#include "core/medium.h"
#include "core/spectrum.h"
#include "scene/registry.h"

namespace eyetrace {

class HomogeneousMedium : public Medium {
 public:
  HomogeneousMedium(Spectrum sigma_a, Spectrum sigma_s, Spectrum Le, float g);
  using Medium::properties;
  MediumProperties properties(const Vec3& p, const SampledWavelengths& lambda) const override;
  bool is_homogeneous() const override { return true; }
  // One segment, the extinction itself (used by tests; volpath's exact path needs none).
  MajorantIterator majorants(const Ray& ray, float t_max, const SampledWavelengths& lambda) const override;
  bool emissive() const override { return emissive_; }

 private:
  Spectrum sigma_a_, sigma_s_, Le_;  // scales already applied
  float g_;
  bool emissive_;
};

const PluginSpec& homogeneous_medium_spec();
std::unique_ptr<Medium> create_homogeneous_medium(const MediumContext& ctx);

}  // namespace eyetrace
