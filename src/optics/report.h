// Optics report of a prescription: paraxial constants and real-ray spot sizes as JSON, the same
// as readable text, and a spot diagram rasterised into an RGB buffer (the caller writes the
// image file: the optics library does no image I/O).
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "optics/prescription.h"
#include "optics/spot.h"

namespace eyetrace::optics {

struct ReportOptions {
  std::vector<double> fields_deg{0.0, 10.0, 20.0, 30.0, 40.0};
  double object_distance_m = std::numeric_limits<double>::infinity();  // spot source distance
  int spot_grid = 64;
};

// Refractions smaller than this (D) are reported as emmetropic (far point at infinity).
inline constexpr double kEmmetropia_D = 0.005;

// Keys: model, variant, source, wavelength_nm, notes, power_diopters, refraction_diopters,
// far_point_m (null when emmetropic: |refraction| < kEmmetropia_D), axial_length_mm, retina_radius_mm (null for flat),
// retina_conic, focal_points_mm [F, F'], principal_points_mm [H, H'], nodal_points_mm [N, N'],
// focal_lengths_mm [front, back], back_focal_distance_mm, stop_diameter_mm,
// entrance_pupil / exit_pupil {position_mm, diameter_mm, magnification},
// spot: [{field_deg, rms_radius_um (null when no ray passes), rays, rays_launched}],
// spot_object_distance_m (null = infinity), surfaces (the prescription as a table).
nlohmann::json optics_report(const Prescription& prescription, const ReportOptions& options = {});

// Human-readable text of an optics_report() result.
std::string format_report(const nlohmann::json& report);

struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // row-major, top row first, 3 bytes per pixel
  double um_per_pixel = 0.0;      // common scale of every panel
  double scale_bar_um = 0.0;      // length of the black bar drawn in each panel
};

// One panel per spot, left to right in the order given, on a common scale: light axes through
// each centroid, the points, and a black scale bar (length scale_bar_um) along each panel's
// bottom edge. width/height in pixels (each >= 16).
RgbImage spot_diagram(const std::vector<SpotResult>& spots, int width, int height);

}  // namespace eyetrace::optics
