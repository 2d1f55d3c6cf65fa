// Light interface. All lights can be sampled from a shading point (next-event estimation);
// area and infinite lights also answer what radiance a ray that hits/escapes carries and the
// solid-angle density with which sample_li would have chosen that direction (for MIS).
#pragma once
#include <optional>

#include "core/interaction.h"
#include "core/ray.h"
#include "core/spectrum.h"

namespace eyetrace {

struct LightSampleContext {
  Vec3 p{0.f};
  Vec3 n{0.f};  // geometric normal at p, or zero for points in free space
};

struct LightLiSample {
  SampledSpectrum L{0.f};  // incident radiance arriving at ctx.p from the light
  Vec3 wi{0.f};            // unit direction from ctx.p towards the light
  float pdf = 0.f;         // solid-angle density (1 for delta lights: a discrete choice)
  Vec3 p_light{0.f};       // point on the light, for the shadow ray (far away for distant/infinite)
  Vec3 n_light{0.f};
  Vec3 p_light_error{0.f};  // rounding-error bound of p_light (area lights; zero for the others)
};

// A ray leaving a light (photon emission, pbrt-v4's LightLeSample): the radiance it carries,
// the density of its origin (area measure; 1 for a point, 1 / (pi r^2) on the disc a distant
// or infinite light shoots through) and of its direction (solid angle; 1 for a distant light's
// single direction). n is the emitting surface's normal, zero where there is no surface.
struct LightLeSample {
  SampledSpectrum L{0.f};
  Ray ray;
  Vec3 n{0.f};
  float pdf_pos = 0.f;
  float pdf_dir = 0.f;
  // The cosine that turns radiance into flux through the surface: 1 without a surface.
  float abs_cos_theta(const Vec3& w) const { return n == Vec3(0.f) ? 1.f : std::abs(glm::dot(n, w)); }
};

class Light {
 public:
  virtual ~Light() = default;
  virtual std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Vec2 u,
                                                 const SampledWavelengths& lambda) const = 0;
  // Density of sample_li choosing direction wi; `hit` is the point where the ray along wi
  // met this (area) light, null for infinite lights. Zero for delta lights.
  virtual float pdf_li(const LightSampleContext& ctx, const Vec3& wi, const SurfaceInteraction* hit) const = 0;
  // Area lights: radiance leaving surface point `hit` in direction w.
  virtual SampledSpectrum L(const SurfaceInteraction& hit, const Vec3& w, const SampledWavelengths& lambda) const {
    return SampledSpectrum(0.f);
  }
  // Infinite lights: radiance carried by a ray that leaves the scene.
  virtual SampledSpectrum Le(const Ray& ray, const SampledWavelengths& lambda) const { return SampledSpectrum(0.f); }
  // Samples a ray leaving the light (photons): u1 and u2 pick its origin and direction.
  // Empty when the sample carries nothing. Lights that cannot emit photons say so with
  // emits_photons() and return nothing.
  virtual std::optional<LightLeSample> sample_le(Vec2 u1, Vec2 u2, const SampledWavelengths& lambda, float time) const {
    return std::nullopt;
  }
  virtual bool emits_photons() const { return false; }
  virtual bool is_delta() const = 0;
  virtual bool is_infinite() const { return false; }
  // Total emitted power (or a proportional estimate), for choosing lights proportionally.
  virtual float power() const = 0;
  // Called once the scene's extent is known (distant and infinite lights need its radius).
  virtual void preprocess(const Bounds3& scene_bounds) {}
};

}  // namespace eyetrace
