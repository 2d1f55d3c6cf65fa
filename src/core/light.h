// Light interface. All lights can be sampled from a shading point (next-event estimation);
// area and infinite lights also answer what radiance a ray that hits/escapes carries and the
// solid-angle density with which sample_li would have chosen that direction (for MIS).
// Lights that can start a light path (bidirectional path tracing) sample a ray leaving them
// (sample_le) and give the densities of that choice (pdf_le), as pbrt-v4's SampleLe/PDF_Le.
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

// A ray leaving a light, for light paths. Densities as pbrt-v4: pdf_pos per unit area of the
// emitter (1 for a point; per unit area of the scene's bounding disc for distant and infinite
// lights) and pdf_dir per unit solid angle (1 for a distant light's single direction).
struct LightLeSample {
  SampledSpectrum L{0.f};  // radiance (area, distant, infinite lights) or intensity (point, spot) along ray.d
  Ray ray;                 // leaves the emitter; ray.d unit
  Vec3 n{0.f};             // the emitting surface's normal (area lights), zero for the others
  Vec3 p_error{0.f};       // rounding-error bound of the surface point (area lights)
  Vec2 uv{0.f};
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
  // A ray leaving the light, or nullopt (no emission there, or the light cannot start light
  // paths: emits_rays() false).
  virtual std::optional<LightLeSample> sample_le(Vec2 u1, Vec2 u2, const SampledWavelengths& lambda, float time) const {
    return std::nullopt;
  }
  // The densities sample_le has for a ray leaving the light at p (n: its surface normal there,
  // zero off surfaces) in unit direction w. Infinite and distant lights ignore p and n.
  virtual void pdf_le(const Vec3& p, const Vec3& n, const Vec3& w, float* pdf_pos, float* pdf_dir) const {
    *pdf_pos = *pdf_dir = 0.f;
  }
  // Whether sample_le and pdf_le are implemented (every light but one seen through a portal).
  virtual bool emits_rays() const { return true; }
  virtual bool is_delta() const = 0;
  // A delta distribution of directions (a distant light): no point can be connected to it.
  virtual bool is_delta_direction() const { return false; }
  virtual bool is_infinite() const { return false; }
  // Total emitted power (or a proportional estimate), for choosing lights proportionally.
  virtual float power() const = 0;
  // Called once the scene's extent is known (distant and infinite lights need its radius).
  virtual void preprocess(const Bounds3& scene_bounds) {}
};

}  // namespace eyetrace
