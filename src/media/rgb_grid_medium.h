// pbrt-v4's "rgbgrid" medium (its RGBGridMedium): sigma_a and sigma_s given per grid sample as
// RGB colours (RGBUnboundedSpectrum: the sigmoid spectrum of rgb / 2m times 2m, m the largest
// component), absent ones 1 everywhere, both times "scale"; emission "Le" per sample as an RGB
// illuminant (the sigmoid spectrum times the colour space's D65) times "Lescale", not
// normalised to luminance (as pbrt-v4: see emission in the .cpp). Each corner's spectrum is
// evaluated at the path's wavelengths and the results are interpolated trilinearly over the box
// [p0, p1]. Majorants: per voxel of a 16^3 grid, scale times the largest sigma_a spectrum value
// plus the largest sigma_s one among the samples reaching it, walked by 3-D DDA.
#pragma once
#include <memory>
#include <optional>

#include "core/medium.h"
#include "core/rgb_to_spectrum.h"
#include "media/medium_box.h"
#include "media/sampled_grid.h"
#include "scene/registry.h"

namespace eyetrace {

// An RGB colour as a spectrum: scale times a sigmoid; zero by default (outside a grid).
struct RgbSpectrumSample {
  SigmoidPolynomial poly;
  float scale = 0.f;
  bool times_white = false;  // an illuminant: times the colour space's D65 (luminance 1)
  static RgbSpectrumSample from_rgb(const RGB& rgb, bool illuminant);
  SampledSpectrum sample(const SampledWavelengths& lambda) const;
  float max_value() const { return scale * poly.max_value(); }  // unbounded ones
};

class RGBGridMedium : public Medium {
 public:
  using Grid = SampledGrid<RgbSpectrumSample>;
  RGBGridMedium(MediumBox box, float g, std::optional<Grid> sigma_a, std::optional<Grid> sigma_s, float sigma_scale,
                std::optional<Grid> Le, float Le_scale);
  using Medium::properties;
  MediumProperties properties(const Vec3& p, const SampledWavelengths& lambda) const override;
  MajorantIterator majorants(const Ray& ray, float t_max, const SampledWavelengths& lambda) const override;
  bool emissive() const override { return Le_ && Le_scale_ > 0.f; }

 private:
  MediumBox box_;
  float g_;
  std::optional<Grid> sigma_a_, sigma_s_, Le_;
  float sigma_scale_, Le_scale_;
  MajorantGrid majorant_grid_;
};

const PluginSpec& rgb_grid_medium_spec();
std::unique_ptr<Medium> create_rgb_grid_medium(const MediumContext& ctx);

}  // namespace eyetrace
