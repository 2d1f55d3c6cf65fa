// Camera interface: a camera turns a CameraSample into an optional world-space ray and a
// weight. An empty optional is a ray the camera lost (vignetted, stopped by the iris, totally
// reflected inside a lens): the film counts it, it is not a magic zero radiance.
#pragma once
#include <cstddef>
#include <optional>
#include <string>

#include "core/math.h"
#include "core/ray.h"

namespace eyetrace {

struct CameraSample {
  Vec2 p_film{0.f};           // continuous raster position on the full film, in pixels
  Vec2 p_lens{0.5f};          // [0,1)^2 sample of the lens / pupil
  float wavelength_u = 0.5f;  // [0,1) sample for spectral cameras (unused by RGB cameras)
  float time = 0.f;
  float filter_weight = 1.f;
};

struct CameraRay {
  Ray ray;
  // Multiplies the radiance along the ray. Lens cameras put relative illumination here, so
  // the image of a uniform scene shows the real fall-off; normalised to 1 at the image centre.
  float weight = 1.f;
};

class Camera {
 public:
  virtual ~Camera() = default;
  virtual std::optional<CameraRay> generate_ray(const CameraSample& sample) const = 0;
  // The same for `count` samples: rays[i] equals generate_ray(samples[i]) bit for bit. Lens
  // cameras override it to trace several rays at once (their trace is latency-bound).
  virtual void generate_rays(const CameraSample* samples, std::optional<CameraRay>* rays, size_t count) const {
    for (size_t i = 0; i < count; ++i) rays[i] = generate_ray(samples[i]);
  }
  virtual std::string to_string() const = 0;
};

}  // namespace eyetrace
