// Diffraction in the lens-system camera: each ray's outgoing direction drawn from the eye's wave
// PSF at its retina point and wavelength (wave_psf_table.h says why and what it approximates).
//
// Random numbers: the renderer gives a camera sample six dimensions (pixel 2, lens 2, time,
// wavelength) and restarts the path's stream after them, so the PSF's six numbers are hashed
// from those six values. They are then a deterministic function of the sampler's dimensions
// (same seed, same image at any thread count), independent of the pupil point in practice,
// though not stratified.
#include <bit>
#include <cmath>
#include <cstdint>

#include "cameras/chief_ray.h"
#include "cameras/lens_system_camera.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"

namespace eyetrace {

namespace {

// SplitMix64's finaliser (Steele, Lea & Flood 2014): a bijective 64-bit mix.
uint64_t mix64(uint64_t x) {
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

uint64_t pack(float a, float b) {
  return uint64_t(std::bit_cast<uint32_t>(a)) | uint64_t(std::bit_cast<uint32_t>(b)) << 32;
}

void diffraction_uniforms(const CameraSample& cs, double u[WavePsfTable::kUniforms]) {
  uint64_t h = mix64(pack(cs.p_film.x, cs.p_film.y) + 0x9e3779b97f4a7c15ull);
  h = mix64(h ^ pack(cs.p_lens.x, cs.p_lens.y));
  h = mix64(h ^ pack(cs.wavelength_u, cs.time));
  for (int i = 0; i < WavePsfTable::kUniforms; ++i)
    u[i] = double(mix64(h + uint64_t(i + 1) * 0x9e3779b97f4a7c15ull) >> 11) * 0x1p-53;
}

// Refractions beyond this (D, myopic) focus the eye at a finite distance.
constexpr double kEmmetropic_D = 0.005;

}  // namespace

void LensSystemCamera::build_psf_table(double corner_arc) {
  if (settings_.film_half_mm > 0.0 || angles_.empty())
    throw optics::OpticsError("diffraction", "needs an eye camera's field mapping (not a flat film)");
  double slope = 0.0;
  const double corner_field = angles_.angle_for_arc(corner_arc, &slope);
  WavePsfTable::Options o;
  o.max_field_deg = corner_field >= 0.0 ? corner_field : angles_.max_angle_deg();
  o.dispersive = dispersive_;
  // The PSF is computed where the eye is focused: its far point at the model's reference
  // wavelength (for a monochromatic eye too: a Navarro eye at 450 nm is focused where the
  // model's eye is, and sees that distance with its chromatic defocus) when that is real, else
  // at infinity. Object distances are from the entrance pupil.
  const optics::ParaxialData pd =
      optics::paraxial_analysis(optics::at_wavelength(prescription_, prescription_.reference_wavelength_nm));
  if (pd.refraction_D < -kEmmetropic_D)
    o.focus_distance_m = -1.0 / pd.refraction_D - 1e-3 * pd.entrance_pupil.position_mm;
  try {
    psf_table_ = std::make_shared<const WavePsfTable>(prescription_, aiming_prescription(prescription_), retina_,
                                                      z_plane_, pupil_.max_arc_mm(), o);
  } catch (const optics::OpticsError& e) {
    throw optics::OpticsError("diffraction", e.message());
  }
}

// The chief ray of field theta leaves the eye towards -z with its lateral part along -m (the
// retina point is on the meridian m; the image is inverted). A PSF offset (a_s, a_t) with a_t > 0
// moving the image outwards means the light at this point comes from theta - a_t; the sagittal
// offset turns the direction across the meridian (the PSF is symmetric about the meridian, so
// its sign does not matter). Then, for a finite focus distance F, the ray is aimed from its own
// pupil point at the point F along that direction from the entrance-pupil centre.
glm::dvec3 LensSystemCamera::diffracted_direction(const CameraSample& cs, const PendingRay& pending,
                                                  const optics::TraceResult& r, double lambda_nm) const {
  double u[WavePsfTable::kUniforms];
  diffraction_uniforms(cs, u);
  const WavePsfTable::Sample s = psf_table_->sample(pending.arc, lambda_nm, u);
  if (!s.ok) return r.ray.direction;  // beyond the table: the geometric ray
  const double theta = s.field_deg * (kPiDouble / 180.0) - s.angle_rad.y;
  const glm::dvec2 m = pending.meridian;
  const double st = std::sin(theta), ct = std::cos(theta);
  glm::dvec3 d(-m.x * st - m.y * s.angle_rad.x, -m.y * st + m.x * s.angle_rad.x, -ct);
  d = glm::normalize(d);
  const double focus = psf_table_->focus_distance_mm();
  if (focus > 0.0) {
    const glm::dvec3 aim = glm::dvec3(0.0, 0.0, psf_table_->entrance_pupil_z_mm()) + focus * d;
    d = glm::normalize(aim - r.ray.origin);
  }
  return d;
}

}  // namespace eyetrace
