// pbrt-v4's "projection" light: a point source at the light's origin projecting an RGB image
// like a slide projector, along the light's +z with the image upright (its top row towards +y,
// its left column towards -x). "fov" spans the image's shorter side; towards a direction w
// (light space, w.z > 0) the intensity is the nearest pixel's RGB where the image plane z = 1
// is met at (w.x, w.y) / w.z, zero outside the image and behind the light.
// "power" makes the luminance integrated over the image's solid angle (pbrt-v4's sum over pixels
// of luminance times cos^3 at the pixel centre, times the pixel's area on the plane) equal it;
// "scale" multiplies on top. Placed and turned by the CTM (pbrt-v4 has no "from" or "to" for it).
#pragma once
#include <memory>

#include "core/light.h"
#include "core/transform.h"
#include "lights/rgb_image.h"
#include "scene/registry.h"

namespace eyetrace {

class ProjectionLight : public Light {
 public:
  // `scale` includes the "power" factor.
  ProjectionLight(const Transform& world_from_light, RGBImage image, float fov_deg, float scale);

  std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Vec2 u,
                                         const SampledWavelengths& lambda) const override;
  float pdf_li(const LightSampleContext&, const Vec3&, const SurfaceInteraction*) const override { return 0.f; }
  // Light paths leave uniformly within the cone about the light's +z that holds the image's
  // frustum (its corners on the cone's rim); directions outside the image give no ray. The
  // density is the light frame's: exact when the CTM turns and scales evenly, as the spot light's.
  std::optional<LightLeSample> sample_le(Vec2 u1, Vec2 u2, const SampledWavelengths& lambda, float time) const override;
  void pdf_le(const Vec3& p, const Vec3& n, const Vec3& w, float* pdf_pos, float* pdf_dir) const override;
  bool is_delta() const override { return true; }
  float power() const override;

  // The RGB intensity towards world direction w (any length, pointing away from the light).
  RGB intensity_rgb(const Vec3& w) const;
  const Vec3& position() const { return p_; }
  // pbrt-v4's Phi as RGB: the image integrated over its solid angle, pixel-centre rule.
  RGB power_rgb() const { return power_rgb_; }

  // The image's half extents on the plane z = 1 (tan(fov / 2) on the shorter side).
  static Vec2 half_extent(int width, int height, float fov_deg);
  // Sum over pixels of f(pixel) cos^3(theta at its centre) times the pixel's area on z = 1: the
  // integral of an intensity f over the image's solid angle.
  template <typename F>
  static auto integrate_over_pixels(int width, int height, float fov_deg, F&& f);

 private:
  Transform world_from_light_, light_from_world_;
  Vec3 p_;
  RGBImage image_;
  Vec2 half_;      // half extents on z = 1
  float cos_max_;  // the cone of light paths: cos of the angle from +z to the image's corners
  float scale_;
  RGB power_rgb_;
};

template <typename F>
auto ProjectionLight::integrate_over_pixels(int width, int height, float fov_deg, F&& f) {
  const Vec2 h = half_extent(width, height, fov_deg);
  const double pixel_area = 4.0 * double(h.x) * double(h.y) / (double(width) * double(height));
  decltype(f(0, 0) * 1.f) sum{};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float px = h.x * (2.f * (float(x) + 0.5f) / float(width) - 1.f);
      const float py = h.y * (2.f * (float(y) + 0.5f) / float(height) - 1.f);
      const float cos_theta = 1.f / std::sqrt(1.f + px * px + py * py);
      sum += f(x, y) * (cos_theta * cos_theta * cos_theta);
    }
  return sum * float(pixel_area);
}

const PluginSpec& projection_light_spec();
std::unique_ptr<Light> create_projection_light(const LightContext& ctx);

}  // namespace eyetrace
