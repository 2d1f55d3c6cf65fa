// pbrt-v4's procedural "cloud" medium (its CloudMedium): inside the box [p0, p1] (medium
// space) the density is a sum of five octaves of Perlin noise at `frequency` times the point,
// its lookup point first perturbed by two octaves of the noise's gradient ("wispiness"),
// scaled by `density`, fading with height y and filled in below y = 0.5, clamped to [0, 1]:
//   pp = frequency p;  twice: pp += w DNoise(l pp), w from 0.05 wispiness halving, l from 10 x1.99
//   d = sum_{i<5} 0.5^(i+1) Noise(1.99^i pp)
//   d = clamp(clamp((1 - p.y) 4.5 density d, 0, 1) + 2 max(0, 0.5 - p.y), 0, 1)
// sigma_a and sigma_s are multiplied by d (no "scale", as pbrt-v4). The majorant is
// sigma_a + sigma_s over the whole box (d <= 1): one segment.
#pragma once
#include <memory>

#include "core/medium.h"
#include "core/spectrum.h"
#include "media/medium_box.h"
#include "scene/registry.h"

namespace eyetrace {

class CloudMedium : public Medium {
 public:
  struct Params {
    float density = 1.f, wispiness = 1.f, frequency = 5.f;
  };
  CloudMedium(MediumBox box, Spectrum sigma_a, Spectrum sigma_s, float g, Params shape);
  using Medium::properties;
  MediumProperties properties(const Vec3& p, const SampledWavelengths& lambda) const override;
  MajorantIterator majorants(const Ray& ray, float t_max, const SampledWavelengths& lambda) const override;
  bool emissive() const override { return false; }
  // The density at a point of the medium's own space (pbrt-v4's CloudMedium::Density).
  float density_in_medium_space(const Vec3& p) const;

 private:
  MediumBox box_;
  Spectrum sigma_a_, sigma_s_;
  float g_;
  Params shape_;
};

// pbrt-v4's DNoise: the forward-difference gradient of Perlin noise with step 0.01.
Vec3 perlin_noise_gradient(const Vec3& p);

const PluginSpec& cloud_medium_spec();
std::unique_ptr<Medium> create_cloud_medium(const MediumContext& ctx);

}  // namespace eyetrace
