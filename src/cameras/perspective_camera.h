// pbrt-v4's perspective camera: a pinhole, or a thin lens when lensradius > 0.
// Registered as "perspective", "pinhole" (lens radius must be 0) and "thinlens". It defines
// importance (pbrt-v4's PerspectiveCamera::We, PDF_We, SampleWi), so bdpt connects light paths
// to it (t = 1).
#pragma once
#include <memory>

#include "cameras/screen_window.h"
#include "cameras/shutter.h"
#include "core/animated_transform.h"
#include "core/camera.h"
#include "scene/registry.h"

namespace eyetrace {

class PerspectiveCamera : public Camera {
 public:
  struct Settings {
    float fov_deg = 90.f;         // of the shorter image axis, as pbrt
    Vec4 screen_window{0.f};      // x0 x1 y0 y1; zero means "from the aspect ratio"
    float lens_radius = 0.f;      // scene units
    float focal_distance = 1e6f;  // scene units, along the camera's z axis
    Shutter shutter;              // each ray's time is drawn in between
  };
  // `motion`: the camera's movement over the TransformTimes; when it is not animated every ray
  // leaves from world_from_camera.
  PerspectiveCamera(const Transform& world_from_camera, IVec2 resolution, const Settings& s,
                    const AnimatedTransform& motion = {});
  std::optional<CameraRay> generate_ray(const CameraSample& sample, SampledWavelengths& lambda) const override;
  using Camera::generate_ray;
  std::string to_string() const override;
  bool has_importance() const override { return true; }
  float we(const Ray& ray, Vec2* p_raster = nullptr) const override;
  void pdf_we(const Ray& ray, float* pdf_pos, float* pdf_dir) const override;
  std::optional<CameraWiSample> sample_wi(const Vec3& p_ref, float time, Vec2 u) const override;
  // Camera-space direction (not normalised, z = 1) through a raster position.
  Vec3 camera_direction(Vec2 p_raster) const;

 private:
  Transform world_from_camera_;
  AnimatedTransform motion_;
  IVec2 resolution_;
  Settings s_;
  float tan_half_fov_;
  float film_area_;  // of the full film on the camera-space plane z = 1 (pbrt-v4's A)
  float lens_area_;  // pi r^2; 1 for a pinhole (pbrt-v4)

  // cos theta of a world-space ray against the viewing axis, and where it lands on the film;
  // false when it points away from the film or lands off it.
  bool on_film(const Ray& ray, float* cos_theta, Vec2* p_raster) const;
};

const PluginSpec& perspective_camera_spec();  // perspective, thinlens, pinhole
std::unique_ptr<Camera> create_perspective_camera(const CameraContext& ctx);
std::unique_ptr<Camera> create_pinhole_camera(const CameraContext& ctx);
std::unique_ptr<Camera> create_thinlens_camera(const CameraContext& ctx);

}  // namespace eyetrace
