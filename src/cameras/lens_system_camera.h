// The lens-system camera: rays leave a point of the retina (or film), pass the crystalline lens,
// iris and cornea of a schematic eye (or the elements of a pbrt lens file) by an exact
// double-precision sequential trace, and enter the scene. Every eye model (Camera "eye" "string
// model" M, or Camera M for each model name) and pbrt-v4's "realistic" are this one class with
// different prescriptions; docs/eye-camera.md describes every parameter.
//
// Frames: the system frame of the optics library (mm, z = 0 at the corneal vertex, +z towards
// the retina) and pbrt camera space (+x right, +y up, +z forward, scene units). The eye looks
// along camera +z with its corneal vertex at the camera origin: camera = (-x, y, -z) * scale,
// a rotation about y, so nothing is mirrored. The eye's image is inverted; pixel (sx, sy) of the
// screen maps to the retina point in direction (sx, -sy), which rotates it back upright.
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "cameras/pupil_sampler.h"
#include "cameras/retina_mapping.h"
#include "cameras/retina_surface.h"
#include "cameras/shutter.h"
#include "cameras/wave_psf_table.h"
#include "core/animated_transform.h"
#include "core/camera.h"
#include "core/splatting_camera.h"
#include "optics/prescription.h"
#include "optics/sequential_trace.h"
#include "scene/registry.h"

namespace eyetrace {

class LensSystemCamera : public Camera, public SplattingCamera {
 public:
  struct Settings {
    FieldMapping mapping = FieldMapping::Angle;
    double fov_deg = 60.0;      // full field across the shorter image axis
    double film_half_mm = 0.0;  // > 0: a physical flat film whose shorter half-axis is this
    double scene_units_per_mm = 1e-3;
    std::string name = "eye";  // for to_string()
    // Trace each sample's hero wavelength through the media's dispersion laws (the others
    // are terminated: each wavelength leaves the eye its own way). Off, or for a system
    // without dispersion, every ray is traced at the prescription's wavelength.
    bool dispersive = false;
    // Draw each ray's outgoing direction from the eye's wave PSF (wave_psf_table.h) instead of
    // keeping the traced one. A dispersive eye then keeps each sample's hero wavelength only
    // (no spectral MIS, no splats): see generate_ray.
    bool diffraction = false;
    // How a dispersive eye's wavelengths share work: one path by spectral MIS (Shared), a camera
    // ray and path each (Apart), or by the pixel filter (Auto). The eye's `dispersionsampling`.
    enum class WavelengthPaths { Auto, Shared, Apart } wavelength_paths = WavelengthPaths::Auto;
    PupilSampler::Options pupil;
    Shutter shutter;  // the realistic camera's; an eye's stays pbrt-v4's default, open from 0 to 1
  };
  // Throws optics::OpticsError when the system cannot be used (invalid, or no ray passes at the
  // image centre) and FieldError (below) when the field of view cannot be mapped.
  LensSystemCamera(const optics::Prescription& prescription, const Transform& world_from_camera, IVec2 resolution,
                   const Settings& settings);
  // Motion blur: the eye moves over the TransformTimes, each ray leaving it placed at the
  // ray's time (the sample's time spread over Settings::shutter). The optics do not change
  // with the motion.
  void set_motion(const AnimatedTransform& world_from_camera) { motion_ = world_from_camera; }

  std::optional<CameraRay> generate_ray(const CameraSample& sample, SampledWavelengths& lambda) const override;
  void generate_rays(const CameraSample* samples, SampledWavelengths* lambdas, std::optional<CameraRay>* rays,
                     size_t count) const override;
  // With a smooth pixel filter, the dispersive eye's wavelengths splat with the filter's weights
  // around where they land (spectral_mis.cpp).
  void generate_rays_splatting(const CameraSample* samples, SampledWavelengths* lambdas, std::optional<CameraRay>* rays,
                               SampleSplats* splats, size_t count) const override;
  using Camera::generate_ray;
  using Camera::generate_rays;
  // Spectral MIS needs each wavelength's density of the ray, which diffraction makes a
  // convolution over the pixels (see generate_ray): the diffracting eye does not splat.
  bool splats() const override { return dispersive_ && !diffraction(); }
  // Settings::wavelength_paths, "auto": spectral MIS, except with a box (constant) filter in a
  // render that cannot splat (adaptive sampling), where MIS would keep each wavelength in the
  // sample's pixel and cost more at equal error than paths (docs/spectral.md).
  bool traces_wavelengths_apart(const Filter& filter, bool splats_allowed) const override {
    if (!splats()) return false;
    using Paths = Settings::WavelengthPaths;
    return settings_.wavelength_paths == Paths::Apart ||
           (settings_.wavelength_paths == Paths::Auto && filter.constant() && !splats_allowed);
  }
  std::string to_string() const override;

  // --- For tests and tools ---------------------------------------------------------------
  struct RetinaPoint {
    glm::dvec3 position;  // system frame, mm
    glm::dvec3 normal;    // unit, towards the lens
    double arc_mm = 0.0;  // arc length from the retina vertex
    glm::dvec2 meridian;  // unit lateral direction of the point in the system frame
  };
  // Where a raster position lands on the retina; nullopt outside the traced field.
  std::optional<RetinaPoint> retina_point(Vec2 p_film) const;
  const optics::Prescription& prescription() const { return prescription_; }
  const optics::CompiledSystem& system() const { return system_; }
  const RetinaSurface& retina() const { return retina_; }
  const PupilSampler& pupil() const { return pupil_; }
  const FieldAngleTable& field_angles() const { return angles_; }
  const Settings& settings() const { return settings_; }
  bool dispersive() const { return dispersive_; }
  bool diffraction() const { return psf_table_ != nullptr; }
  const WavePsfTable* psf_table() const { return psf_table_.get(); }
  // Upper bound of every weight generate_ray returns, and the constant that makes the mean
  // weight at the image centre 1 (1 / integral of cos dw over the passing directions there).
  double max_weight() const { return max_weight_; }
  double weight_normalisation() const { return normalisation_; }

 private:
  // The sample's hero wavelength goes alone (CameraSample::filter, hero_only; generate_ray).
  bool hero_alone(const CameraSample& cs) const { return dispersive_ && (!cs.filter || cs.hero_only || psf_table_); }
  struct PendingRay {
    optics::Ray ray;     // from the retina towards the sampled plane point (system frame)
    glm::dvec3 d_local;  // the same direction in the meridian frame, unnormalised
    glm::dvec2 normal;   // retina normal in the meridian frame
    double area = 0.0;   // sampled area of the plane (1 / density)
    double arc = 0.0;    // retina arc of the point
    double screen_radius = 0.0;
    glm::dvec2 meridian{1.0, 0.0};  // unit lateral direction of the retina point (system frame)
  };
  // One wavelength's share of a ray under spectral MIS (spectral_mis.cpp).
  struct WavelengthTerms {
    double filter = 0.0;         // the pixel filter at the wavelength's retina point (signed)
    double u = 0.0;              // its sampling density, up to a common factor; 0: cannot sample the ray
    double inv_n2_jacobian = 0;  // 1 / (n_vitreous^2 * (retina area per raster area)) there
    IVec2 offset{0};             // the pixel it counts in, from the sample's (splats)
  };
  bool start_ray(const CameraSample& cs, PendingRay* pending) const;
  // Whether start_ray gives b what it gave a (the same film and pupil point).
  static bool same_start(const CameraSample& a, const CameraSample& b) {
    return a.p_film == b.p_film && a.p_lens == b.p_lens;
  }
  static optics::Ray back_in(const optics::TraceResult& left);
  std::optional<CameraRay> finish_ray(const CameraSample& cs, const PendingRay& pending, const optics::TraceResult& r,
                                      double lambda_nm) const;
  // The direction a diffracting eye gives the ray that left the eye as r (system frame).
  glm::dvec3 diffracted_direction(const CameraSample& cs, const PendingRay& pending, const optics::TraceResult& r,
                                  double lambda_nm) const;
  void build_psf_table(double corner_arc);
  // Spectral MIS: the ray that left the eye at the hero wavelength, traced back in at each
  // secondary wavelength (forward[k - 1] for wavelength k), weighs every wavelength.
  // splats: null, or (smooth filter) where each wavelength splats.
  void weigh_wavelengths(const CameraSample& cs, SampledWavelengths& lambda, const PendingRay& hero,
                         const optics::TraceResult* forward, CameraRay* out, SampleSplats* splats) const;
  WavelengthTerms hero_terms(const CameraSample& cs, const PendingRay& hero, double lambda_nm,
                             WavelengthSplat* spread) const;
  WavelengthTerms secondary_terms(const CameraSample& cs, glm::dvec2 pixel_centre, const optics::TraceResult& forward,
                                  double lambda_nm, WavelengthSplat* spread) const;
  double filter_at(const CameraSample& cs, glm::dvec2 pixel_centre, double screen_radius, glm::dvec2 meridian,
                   IVec2* offset, WavelengthSplat* spread) const;
  static double spread_at(const CameraSample& cs, glm::dvec2 raster, WavelengthSplat* spread);
  void trace_rays(const CameraSample* samples, SampledWavelengths* lambdas, std::optional<CameraRay>* rays,
                  SampleSplats* splats, size_t count) const;
  static double inverse_n2_jacobian(double n, double screen_radius, double height, double slope);
  glm::dvec2 screen(Vec2 p_film) const;
  void compute_normalisation(const optics::CompiledSystem& system);

  optics::Prescription prescription_;
  optics::CompiledSystem system_;
  optics::CompiledSystem aiming_system_;  // apertures opened for chief-ray aiming (chief_ray.h)
  Transform world_from_camera_;
  AnimatedTransform motion_;  // not animated unless set_motion was given a moving one
  IVec2 resolution_;
  Settings settings_;
  glm::dvec4 screen_window_;  // pbrt's: x0 x1 y0 y1, shorter axis [-1, 1]
  glm::dvec2 screen_scale_;   // screen units per raster pixel
  glm::dvec2 inv_screen_scale_;
  RetinaSurface retina_;
  RetinaPointTable retina_points_;
  double z_plane_ = 0.0;
  FieldAngleTable angles_;
  RetinaMapping mapping_;
  PupilSampler pupil_;
  double normalisation_ = 1.0;
  double max_weight_ = 0.0;
  bool dispersive_ = false;
  std::shared_ptr<const WavePsfTable> psf_table_;  // diffraction on
};

// A field-of-view/mapping combination the system cannot serve (message names why).
class FieldError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

std::unique_ptr<Camera> create_eye_camera(const CameraContext& ctx);        // Camera "eye" "string model" ...
CameraFactory create_named_eye_camera(std::string model);                   // Camera "navarro" ...
std::unique_ptr<Camera> create_realistic_camera(const CameraContext& ctx);  // pbrt-v4 Camera "realistic"
// For `eyetrace optics` and tests: the prescription a Camera directive describes (eye cameras
// and "realistic"; lens files relative to search_dir). Errors are SceneErrors naming the
// parameter.
optics::Prescription prescription_from_camera_params(const std::string& camera_name, const ParameterList& params,
                                                     const std::string& search_dir);

}  // namespace eyetrace
