// A camera whose wavelengths of one sample land in different places on the film (a dispersive
// eye) and that can say where, so that the integrator splats each wavelength with the pixel
// filter's weights over the pixels around its landing point (docs/spectral.md, "Splats with a
// smooth filter"). An addition beside core/camera.h that only the integrator's splatting path
// uses: cameras that implement it are found by dynamic_cast.
#pragma once
#include <cmath>
#include <cstddef>
#include <optional>

#include "core/camera.h"
#include "core/wavelength_splat.h"

namespace eyetrace {

struct SampleSplats {
  WavelengthSplat wavelength[kSpectrumSamples];
};

class SplattingCamera {
 public:
  virtual ~SplattingCamera() = default;
  // As Camera::generate_rays. For samples with CameraSample::splat and a filter that is not
  // constant, each wavelength's weight then no longer holds the filter: wavelength k adds
  //   |filter_weight| * weight[k] * L[k] * wx[c] * wy[r]
  // to pixel (first.x + c, first.y + r) of splats[i].wavelength[k] (and nothing to the sample's
  // own pixel beyond its filter weight). Other samples are as generate_rays makes them.
  virtual void generate_rays_splatting(const CameraSample* samples, SampledWavelengths* lambdas,
                                       std::optional<CameraRay>* rays, SampleSplats* splats, size_t count) const = 0;
  // Largest filter radius (pixels, per axis) the splats serve; wider filters keep spectral MIS
  // within the pixel.
  static constexpr float kMaxFilterRadius = 0.5f * (WavelengthSplat::kMaxSpan - 1);
  // How a splatting sample of `pixel` in the tile [lo, hi) draws its film point: uniformly in the
  // pixel's square (filter weight 1) where the pixel's filter stays inside
  // the tile, else through the filter (Filter::sample). Uniform points keep the sampler's
  // stratification across the whole tile; the pixels on its rim draw through the filter so that
  // the tile's samples also reach the points just outside it, which the rim's filters see
  // (docs/spectral.md, "Splats with a smooth filter").
  static bool uniform_in_pixel(IVec2 pixel, IVec2 lo, IVec2 hi, Vec2 radius) {
    const IVec2 m(rim(radius.x), rim(radius.y));
    return pixel.x >= lo.x + m.x && pixel.x < hi.x - m.x && pixel.y >= lo.y + m.y && pixel.y < hi.y - m.y;
  }
  // The uniform draw itself: offset u - 1/2 in the pixel, weight 1 (the filter's sampling weights
  // are f / (pdf integral f), 1 on average).
  static FilterSample uniform_sample(Vec2 u) { return FilterSample{u - Vec2(0.5f), 1.f}; }
  // Along one axis the pixels m = ceil(r - 0.5) from either end of the tile draw through the
  // filter: pixel x's filter (centre x + 0.5, radius r) stays in [lo, hi) when x >= lo + m and
  // x < hi - m.
  static int rim(float r) { return static_cast<int>(std::ceil(double(r) - 0.5)); }
};

}  // namespace eyetrace
