// pbrt-v4's orthographic camera: parallel rays along the camera's +z, each leaving from its
// point of the screen window on the plane z = 0 (one scene unit of the window is one unit of the
// scene). With "lensradius" > 0 it is pbrt-v4's thin lens: a ray leaves from a point of the
// lens disc (radius lensradius, centred on the camera's origin) towards the point
// (screen x, screen y, focaldistance), where the parallel ray would reach the plane of focus.
#pragma once
#include <memory>

#include "cameras/screen_window.h"
#include "cameras/shutter.h"
#include "core/animated_transform.h"
#include "core/camera.h"
#include "scene/registry.h"

namespace eyetrace {

class OrthographicCamera : public Camera {
 public:
  struct Settings {
    Vec4 screen_window{0.f};      // x0 x1 y0 y1; zero means "from the aspect ratio"
    float lens_radius = 0.f;      // scene units
    float focal_distance = 1e6f;  // scene units, along the camera's z axis
    Shutter shutter;
  };
  // `motion`: the camera's movement over the TransformTimes; when it is not animated every ray
  // leaves from world_from_camera.
  OrthographicCamera(const Transform& world_from_camera, IVec2 resolution, const Settings& s,
                     const AnimatedTransform& motion = {});
  std::optional<CameraRay> generate_ray(const CameraSample& sample, SampledWavelengths& lambda) const override;
  using Camera::generate_ray;
  std::string to_string() const override;

 private:
  Transform world_from_camera_;
  AnimatedTransform motion_;
  IVec2 resolution_;
  Settings s_;
};

const PluginSpec& orthographic_camera_spec();
std::unique_ptr<Camera> create_orthographic_camera(const CameraContext& ctx);

}  // namespace eyetrace
