// pbrt-v4's "uniformgrid" medium (its GridMedium): sigma_a and sigma_s spectra (times "scale")
// multiplied by a density given on an nx x ny x nz grid over the box [p0, p1] and looked up
// trilinearly (media/sampled_grid.h). Emission is either the spectrum "Le" times a grid of
// "Lescale" values, or, with a "temperature" grid, a blackbody at
// (temperature - temperatureoffset) * temperaturescale kelvin (normalised to peak 1, as
// pbrt-v4's BlackbodySpectrum; no emission at or below 100 K) times the "Lescale" grid, in
// pbrt-v4's film units (see emission() in the .cpp).
// Majorants: the density's maxima over a 16^3 grid, walked by 3-D DDA.
#pragma once
#include <memory>
#include <optional>

#include "core/medium.h"
#include "core/spectrum.h"
#include "media/medium_box.h"
#include "media/sampled_grid.h"
#include "scene/registry.h"

namespace eyetrace {

class GridMedium : public Medium {
 public:
  struct Emission {
    Spectrum Le;                  // without a temperature grid
    SampledGrid<float> Le_scale;  // luminance normalisation of Le already applied
    std::optional<SampledGrid<float>> temperature;
    float temperature_offset = 0.f, temperature_scale = 1.f;
  };
  GridMedium(MediumBox box, Spectrum sigma_a, Spectrum sigma_s, float g, SampledGrid<float> density, Emission emission);
  using Medium::properties;
  MediumProperties properties(const Vec3& p, const SampledWavelengths& lambda) const override;
  MajorantIterator majorants(const Ray& ray, float t_max, const SampledWavelengths& lambda) const override;
  bool emissive() const override { return emissive_; }
  // The density at render-space p (tests: the majorant grid must bound it).
  float density(const Vec3& p) const { return density_.lookup(box_.to_unit(box_.to_medium(p))); }
  const MajorantGrid& majorant_grid() const { return majorant_grid_; }

 private:
  SampledSpectrum emission(const Vec3& unit, const SampledWavelengths& lambda) const;
  MediumBox box_;
  Spectrum sigma_a_, sigma_s_;  // "scale" applied
  float g_;
  SampledGrid<float> density_;
  Emission emission_;
  bool emissive_;
  MajorantGrid majorant_grid_;
};

// pbrt-v4's BlackbodySpectrum: Planck's law at T kelvin divided by its value at the peak
// wavelength (Wien: 2.8977721e-3 m K / T), so the peak is 1.
float normalized_blackbody(float lambda_nm, float kelvin);

const PluginSpec& grid_medium_spec();
std::unique_ptr<Medium> create_grid_medium(const MediumContext& ctx);

}  // namespace eyetrace
