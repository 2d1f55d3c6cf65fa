// Optics report of a prescription: paraxial constants, real-ray spot sizes and chromatic
// aberration as JSON, the same as readable text, and its figures (spot diagram, chromatic
// refraction curve) rasterised into RGB buffers (the caller writes the image files: the optics
// library does no image I/O).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "optics/chromatic.h"
#include "optics/polychromatic_psf.h"
#include "optics/prescription.h"
#include "optics/raster.h"
#include "optics/spot.h"
#include "optics/wavefront.h"

namespace eyetrace::optics {

struct ReportOptions {
  std::vector<double> fields_deg{0.0, 10.0, 20.0, 30.0, 40.0};
  double object_distance_m = std::numeric_limits<double>::infinity();  // spot source distance
  int spot_grid = 64;
  ChromaticOptions chromatic;  // wavelengths of the chromatic section (TCA at fields_deg, object_distance_m)
  // The wavefront section (wavefront.h) when set: one analysis per field of fields_deg, at
  // object_distance_m; wave.field_deg and wave.object_distance_m are ignored.
  bool wave = false;
  WavefrontOptions wave_options;
  // The wave section's polychromatic object per field when set (polychromatic_psf.h).
  bool polychromatic = false;
  PolychromaticOptions polychromatic_options;
  // MTF frequencies of the wave section (cycles per degree), each within the diffraction cut-off.
  std::vector<double> mtf_freqs_cpd{5.0, 10.0, 20.0, 30.0, 40.0, 60.0};
};

// Refractions smaller than this (D) are reported as emmetropic (far point at infinity).
inline constexpr double kEmmetropia_D = 0.005;

// Keys: model, variant, source, wavelength_nm, notes, power_diopters, refraction_diopters (for a
// system with biconic surfaces: that of their spherical equivalents, paraxial.h), the refraction
// per meridian at the first vertex (sphero_cylinder.h): sphere_diopters, cylinder_diopters
// (minus cylinder, <= 0), axis_deg ([0, 180), TABO notation, i.e. the ANSI Z80.28 frame of the
// wave section; 0 without cylinder) and the power vector M, J0, J45 (D, same frame),
// far_point_m (null when emmetropic: |refraction| < kEmmetropia_D), axial_length_mm, retina_radius_mm (null for flat),
// retina_conic, focal_points_mm [F, F'], principal_points_mm [H, H'], nodal_points_mm [N, N'],
// focal_lengths_mm [front, back], back_focal_distance_mm, stop_diameter_mm,
// entrance_pupil / exit_pupil {position_mm, diameter_mm, magnification, and centre_mm [x, y]
// when the stop is decentred},
// spot: [{field_deg, rms_radius_um (null when no ray passes), rays, rays_launched}],
// spot_object_distance_m (null = infinity), surfaces (the prescription as a table);
// chromatic aberration (chromatic.h):
//   dispersion {source, assumed, media: [{medium, law, index_reference, index_at_range_ends}]},
//   chromatic_refraction: [{wavelength_nm, refraction_diopters}] from min to max every step,
//   chromatic {min_wavelength_nm, max_wavelength_nm, step_nm, lca_diopters (= refraction at
//   max - at min)},
//   tca {short_wavelength_nm, long_wavelength_nm, mapping_wavelength_nm, object_distance_m,
//   fields: [{field_deg, tca_arcmin, retina_um (both null when a chief ray is lost, with `lost`
//   saying why), short_angle_deg, long_angle_deg, centroid_tca_arcmin, centroid_retina_um (the
//   spots' centroids instead of the chief rays, the pupil filled with a spot_grid grid)}]}.
// wavefront (options.wave; wavefront.h), one entry per field:
//   wave: [{field_deg, wavelength_nm, pupil_radius_mm (entrance pupil), object_distance_m,
//   rms_wavefront_waves (from the coefficients), rms_sampled_waves, pv_wavefront_waves,
//   zernike_order, zernike_osa_um (c_j, j = 0, 1, ...), refraction {least_squares, paraxial}:
//   {M_diopters, J0_diopters, J45_diopters}, rays, rays_lost, warning (when rays were lost)}];
//   a field whose analysis fails (chief ray lost, too few rays) has its numbers null and `error`;
//   with options.polychromatic, `polychromatic` (wave_optics_report.h), or {error} when it fails.
// Throws OpticsError for invalid chromatic or wavefront options (naming them), and for an MTF
// frequency beyond the diffraction cut-off.
nlohmann::json optics_report(const Prescription& prescription, const ReportOptions& options = {});

// Human-readable text of an optics_report() result.
std::string format_report(const nlohmann::json& report);

// One panel per spot, left to right in the order given, on a common scale: light axes through
// each centroid, the points, and a black scale bar (length scale_bar_um) along each panel's
// bottom edge. width/height in pixels (each >= 16).
RgbImage spot_diagram(const std::vector<SpotResult>& spots, int width, int height);

// The chromatic difference of refraction of an optics_report() result as a curve: refraction (D)
// against wavelength (nm) with axes, ticks, labels, a dashed line at the prescription's
// wavelength and the LCA in the title. width >= 240, height >= 160 pixels.
RgbImage chromatic_plot(const nlohmann::json& report, int width, int height);

}  // namespace eyetrace::optics
