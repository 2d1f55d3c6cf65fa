// Camera interface: a camera turns a CameraSample and the sample's wavelengths into an
// optional world-space ray and a weight per wavelength. A camera whose optics disperse traces
// the hero wavelength; when the sample names its pixel's filter it weights the other
// wavelengths by spectral MIS (docs/spectral.md), else (or when the sample asks for the hero
// alone) it terminates them (SampledWavelengths::terminate_secondary). An empty optional is a
// ray the camera lost (vignetted, stopped by the iris, totally reflected inside a lens): the
// film counts it, it is not a magic zero radiance.
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
  // send a wavelength that landed in another pixel: with a constant filter by
  // CameraRay::pixel_offset, with a smooth one by the filter's weights around the landing point
  // (core/splatting_camera.h). Without: each wavelength counts in the sample's own pixel or not
  // at all.
  bool splat = false;
  IVec2 splat_lo{0}, splat_hi{0};
  // The hero wavelength alone, whatever the filter: a renderer that traces each wavelength's
  // own camera ray and path (Camera::traces_wavelengths_apart) asks for it.
  bool hero_only = false;
};

struct CameraRay {
  Ray ray;
  // Multiplies the radiance along the ray, per wavelength. Lens cameras put relative
  // illumination here, so the image of a uniform scene shows the real fall-off; normalised to
  // 1 at the image centre. A dispersive camera's spectral MIS weights differ per wavelength.
  SampledSpectrum weight{1.f};
  // The hero wavelength's weight when the path keeps only the hero (a dispersive dielectric
  // in the scene terminated the others): the plain, non-MIS weight, since the other
  // wavelengths can no longer share the path. With smooth splats (SplattingCamera) the hero is
  // splatted around where it landed like every wavelength, and this is its weight as the one
  // technique, per unit of the tile's sampling density there (cameras/spectral_mis.cpp).
  float hero_weight = 1.f;
  // Where each wavelength's weighted radiance belongs, from the sample's pixel (a dispersive
  // camera splatting by wavelength); (0, 0) is the sample's own pixel.
  IVec2 pixel_offset[kSpectrumSamples] = {};
  // With those splats (box filter), each wavelength's share of the sample: the number of
  // wavelengths times its balance-heuristic weight, 4 u_k / sum u (cameras/spectral_mis.cpp).
  // Summed over the samples that put wavelength k into a pixel, its expectation is the pixel's
  // sample count, by which the film divides (Film::add_share).
  SampledSpectrum share{1.f};
};

// Light arriving at a point from the camera's lens (Camera::sample_wi, pbrt-v4's CameraWiSample).
struct CameraWiSample {
  float Wi = 0.f;      // importance the lens point sends towards the reference point
  Vec3 wi{0.f};        // unit direction from the reference point to the lens point
  float pdf = 0.f;     // density of the lens point, per unit solid angle at the reference point
  Vec2 p_raster{0.f};  // where that ray lands on the full film, in pixels
  Vec3 p_lens{0.f};    // the lens point (world)
  Vec3 n_lens{0.f};    // the lens's normal (world): the camera's viewing axis
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
  // True when, with this pixel filter, the camera's wavelengths are best estimated each by a
  // camera ray and scene path of its own (the sample's four rotations of its wavelengths, each
  // hero alone: CameraSample::hero_only) rather than by one path shared by spectral MIS.
  // splats_allowed: whether the render lets wavelengths count in other pixels (CameraSample::
  // splat; not with adaptive sampling).
  virtual bool traces_wavelengths_apart(const Filter& /*filter*/, bool /*splats_allowed*/) const { return false; }

  // Importance (pbrt-v4's We, PDF_We, SampleWi): an optional capability, which light tracing
  // (bdpt's t = 1 strategies) needs. A camera without it (the default) is reached only
  // through its own rays. Importance is normalised over the full film, whose raster is
  // [0, resolution]: a ray that lands outside has none. Not spectral: one value for every
  // wavelength.
  virtual bool has_importance() const { return false; }
  // The importance a ray leaving the lens carries (zero off the film); *p_raster, when given,
  // receives where it lands.
  virtual float we(const Ray& /*ray*/, Vec2* /*p_raster*/ = nullptr) const { return 0.f; }
  // The densities with which generate_ray's rays would make `ray`: of its origin per unit lens
  // area, of its direction per unit solid angle (as pbrt-v4, uniform over the film's area on the
  // plane at distance 1). Zero off the film.
  virtual void pdf_we(const Ray& /*ray*/, float* pdf_pos, float* pdf_dir) const { *pdf_pos = *pdf_dir = 0.f; }
  // A lens point seen from `p_ref` at `time`, from a [0,1)^2 sample; empty when it has no
  // importance there (behind the camera, off the film).
  virtual std::optional<CameraWiSample> sample_wi(const Vec3& /*p_ref*/, float /*time*/, Vec2 /*u*/) const {
    return std::nullopt;
  }
  virtual std::string to_string() const = 0;

 private:
  static constexpr size_t kBatch = 64;
};

}  // namespace eyetrace
