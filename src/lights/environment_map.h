// An environment image over the sphere of directions (in the light's frame) and the
// piecewise-constant distribution that picks directions in proportion to its luminance.
// Radiance is looked up at the nearest pixel (as pbrt-v4's ImageInfiniteLight does), so the
// sampling density is proportional to what is returned, pixel by pixel.
#pragma once
#include <optional>

#include "core/distribution.h"
#include "lights/rgb_image.h"
#include "lights/sphere_mapping.h"

namespace eyetrace {

enum class SphereMapping { EqualArea, LatLong };

class EnvironmentMap {
 public:
  EnvironmentMap(RGBImage image, SphereMapping mapping);

  // Radiance arriving from direction w (unit, light space).
  RGB radiance(const Vec3& w) const;
  // A direction with its density per unit solid angle; nullopt when the map is black there.
  std::optional<Vec3> sample(Vec2 u, float* pdf) const;
  float pdf(const Vec3& w) const;

  // Radiance averaged over the sphere (by solid angle).
  RGB mean_radiance() const;
  // Luminous irradiance on a patch facing +z: integral of luminance(L) cos(theta) over z > 0.
  float up_illuminance() const;
  SphereMapping mapping() const { return mapping_; }
  const RGBImage& image() const { return image_; }

 private:
  Vec2 to_square(const Vec3& w) const;
  Vec3 to_sphere(Vec2 uv) const;
  // Solid angle per unit area of the square at direction w: 4 pi, or 2 pi^2 sin(theta).
  float sphere_per_square(const Vec3& w) const;
  // Solid angle of pixel row y (every pixel of the row covers the same).
  float pixel_solid_angle(int y) const;
  float equal_area_pixel_cosine(int x, int y) const;

  RGBImage image_;
  SphereMapping mapping_;
  PiecewiseConstant2D distribution_;
};

}  // namespace eyetrace
