// Camera interface: a camera turns a CameraSample and the sample's wavelengths into an
// optional world-space ray and a weight per wavelength. A camera whose optics disperse traces
// the hero wavelength; when the sample names its pixel's filter it weights the other
// wavelengths by spectral MIS (docs/spectral.md), else it terminates them
// (SampledWavelengths::terminate_secondary). An empty optional is a ray the camera lost
// (vignetted, stopped by the iris, totally reflected inside a lens): the film counts it, it is
// not a magic zero radiance.
#pragma once
#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>

#include "core/filter.h"
#include "core/math.h"
#include "core/ray.h"
#include "core/sampled_spectrum.h"

namespace eyetrace {

struct CameraSample {
  Vec2 p_film{0.f};           // continuous raster position on the full film, in pixels
  Vec2 p_lens{0.5f};          // [0,1)^2 sample of the lens / pupil
  float wavelength_u = 0.5f;  // [0,1) sample that picked the wavelengths
  float time = 0.f;
  float filter_weight = 1.f;
  // The pixel's reconstruction filter and this sample's offset from the pixel centre: with
  // them a dispersive camera can tell how much each wavelength's ray belongs to the pixel.
  // Null (tools, tests): the camera keeps the hero wavelength only.
  const Filter* filter = nullptr;
  Vec2 filter_offset{0.f};
  // The pixels (absolute raster bounds [lo, hi), the sample's tile) into which the camera may
  // send a wavelength that landed in another pixel (CameraRay::pixel_offset), with a constant
  // filter only. Without: each wavelength counts in the sample's own pixel or not at all.
  bool splat = false;
  IVec2 splat_lo{0}, splat_hi{0};
};

struct CameraRay {
  Ray ray;
  // Multiplies the radiance along the ray, per wavelength. Lens cameras put relative
  // illumination here, so the image of a uniform scene shows the real fall-off; normalised to
  // 1 at the image centre. A dispersive camera's spectral MIS weights differ per wavelength.
  SampledSpectrum weight{1.f};
  // The hero wavelength's weight when the path keeps only the hero (a dispersive dielectric
  // in the scene terminated the others): the plain, non-MIS weight, since the other
  // wavelengths can no longer share the path.
  float hero_weight = 1.f;
  // Where each wavelength's weighted radiance belongs, from the sample's pixel (a dispersive
  // camera splatting by wavelength); (0, 0) is the sample's own pixel.
  IVec2 pixel_offset[kSpectrumSamples] = {};
};

class Camera {
 public:
  virtual ~Camera() = default;
  virtual std::optional<CameraRay> generate_ray(const CameraSample& sample, SampledWavelengths& lambda) const = 0;
  // The same for `count` samples: rays[i] equals generate_ray(samples[i], lambdas[i]) bit for
  // bit. Lens cameras override it to trace several rays at once (their trace is latency-bound).
  virtual void generate_rays(const CameraSample* samples, SampledWavelengths* lambdas, std::optional<CameraRay>* rays,
                             size_t count) const {
    for (size_t i = 0; i < count; ++i) rays[i] = generate_ray(samples[i], lambdas[i]);
  }
  // At the wavelengths the sample's own wavelength_u picks (tools, tests and benchmarks).
  std::optional<CameraRay> generate_ray(const CameraSample& sample) const {
    SampledWavelengths lambda = SampledWavelengths::sample_visible(sample.wavelength_u);
    return generate_ray(sample, lambda);
  }
  void generate_rays(const CameraSample* samples, std::optional<CameraRay>* rays, size_t count) const {
    for (size_t i = 0; i < count; i += kBatch) {
      const size_t n = std::min(kBatch, count - i);
      SampledWavelengths lambdas[kBatch];
      for (size_t j = 0; j < n; ++j) lambdas[j] = SampledWavelengths::sample_visible(samples[i + j].wavelength_u);
      generate_rays(samples + i, lambdas, rays + i, n);
    }
  }
  // True when the camera may send a wavelength to another pixel (CameraRay::pixel_offset) for
  // samples that allow it (CameraSample::splat).
  virtual bool splats() const { return false; }
  virtual std::string to_string() const = 0;

 private:
  static constexpr size_t kBatch = 64;
};

}  // namespace eyetrace
