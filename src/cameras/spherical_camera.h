// pbrt-v4's spherical camera: every pixel a direction of the whole sphere around the camera's
// origin. Raster position p on a film of resolution (W, H) is (u, v) = (p.x / W, p.y / H):
// - "equalarea" (the default): pbrt-v4's equal-area octahedral square (lights/sphere_mapping.h;
//   (u, v) outside [0, 1]^2, which a wide pixel filter reaches, is folded back across the edge as
//   pbrt-v4's WrapEqualAreaSquare does);
// - "equirectangular": theta = pi v, phi = 2 pi u, (sin theta cos phi, sin theta sin phi, cos theta);
// and then, as pbrt-v4, the y and z components are exchanged. So the camera's +y (up) is the
// equal-area image's centre and the equirectangular image's top row; its +z (forward) is the
// middle of the equal-area image's bottom edge and the equirectangular column u = 1/4 on the
// middle row; its +x the middle of the equal-area image's right edge and the equirectangular
// column u = 0; its -y (down) the equal-area image's corners and the equirectangular bottom row.
// "lensradius", "focaldistance", "screenwindow" and "frameaspectratio" are read and ignored, as
// pbrt-v4 ignores them (with a warning here).
#pragma once
#include <memory>

#include "cameras/shutter.h"
#include "core/animated_transform.h"
#include "core/camera.h"
#include "scene/registry.h"

namespace eyetrace {

enum class SphericalMapping { EqualArea, Equirectangular };

// The camera-space direction (unit) of a point (u, v) of the image square.
Vec3 spherical_direction(SphericalMapping mapping, Vec2 uv);
// pbrt-v4's WrapEqualAreaSquare: a point up to one square outside [0, 1]^2 mirrored back in, so
// that the equal-area map continues across its edges.
Vec2 wrap_equal_area_square(Vec2 uv);

class SphericalCamera : public Camera {
 public:
  SphericalCamera(const Transform& world_from_camera, IVec2 resolution, SphericalMapping mapping,
                  const Shutter& shutter = {}, const AnimatedTransform& motion = {});
  std::optional<CameraRay> generate_ray(const CameraSample& sample, SampledWavelengths& lambda) const override;
  using Camera::generate_ray;
  std::string to_string() const override;

 private:
  Transform world_from_camera_;
  AnimatedTransform motion_;
  IVec2 resolution_;
  SphericalMapping mapping_;
  Shutter shutter_;
};

const PluginSpec& spherical_camera_spec();
std::unique_ptr<Camera> create_spherical_camera(const CameraContext& ctx);

}  // namespace eyetrace
