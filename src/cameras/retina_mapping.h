// Pixel -> retina: where on the retina (arc length along the meridian) a pixel's screen radius
// lands, for the three mappings of the eye cameras and the physical film of "realistic":
//   angle   pixels linear in the visual field angle of the chief ray (the angle at which the ray
//           through the stop centre leaves the eye), so images of different eyes line up pixel
//           for pixel: an equidistant projection of the visual field;
//   flat    pixels linear in lateral retina height (a flat film seen along the axis);
//   retina  pixels linear in arc length on the (curved) retina.
// The screen is pbrt's: the shorter image axis spans [-1, 1]; "screen radius" is the distance
// from the image centre in those units.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cameras/retina_surface.h"
#include "optics/sequential_trace.h"

namespace eyetrace {

enum class FieldMapping { Angle, Flat, Retina };

// Closest a retina point may come to the sampling plane: nearer, the directions to it degenerate
// (are ill-conditioned). The field-angle table and the eye camera's retina limit both stop there.
inline constexpr double kMinPlaneGap_mm = 0.5;

// "angle", "flat", "retina"; parse returns false for anything else.
const char* to_string(FieldMapping m);
bool parse_field_mapping(const std::string& text, FieldMapping* out);

// Chief-ray field angle as a function of retina arc length, traced once: (arc, angle) nodes with
// the angle strictly increasing, and the inverse resampled on a uniform angle grid.
class FieldAngleTable {
 public:
  FieldAngleTable() = default;
  // Traces chief rays outwards from the retina centre until the field angle reaches
  // max_angle_deg, the chief ray is lost, the angle stops growing or the retina point comes
  // within reach of the sampling plane.
  FieldAngleTable(const optics::CompiledSystem& system, const RetinaSurface& retina, double z_plane,
                  double max_angle_deg, double max_arc_mm);

  bool empty() const { return arcs_.size() < 2; }
  double max_angle_deg() const { return angles_.empty() ? 0.0 : angles_.back(); }
  double max_arc_mm() const { return arcs_.empty() ? 0.0 : arcs_.back(); }
  // Retina arc whose chief ray leaves at angle_deg; negative beyond max_angle_deg().
  double arc_for_angle(double angle_deg) const {
    if (!(angle_deg <= max_angle_deg()) || empty()) return -1.0;
    const double x = angle_deg * inverse_scale_;
    const size_t i = std::min(static_cast<size_t>(x), inverse_.size() - 2);
    const double t = x - static_cast<double>(i);
    return inverse_[i] + t * (inverse_[i + 1] - inverse_[i]);
  }
  // d arc / d angle (mm per degree) of arc_for_angle's piecewise-linear form at angle_deg
  // (within the table).
  double arc_slope_for_angle(double angle_deg) const {
    if (empty()) return 0.0;
    const size_t i = std::min(static_cast<size_t>(std::fmax(angle_deg * inverse_scale_, 0.0)), inverse_.size() - 2);
    return (inverse_[i + 1] - inverse_[i]) * inverse_scale_;
  }
  // The inverse of arc_for_angle, exact for its piecewise-linear form, and that form's slope
  // d arc / d angle (mm per degree) there; negative when a is beyond the table.
  double angle_for_arc(double a, double* slope) const;
  // q (meridian coordinate on the sampling plane) of the chief ray at arc a (linear between
  // nodes): a starting guess for the pupil sampler; nullopt beyond the table.
  std::optional<double> chief_q_for_arc(double a) const;

 private:
  std::vector<double> arcs_, angles_, chief_q_;
  std::vector<double> inverse_;       // arc at angle j / inverse_scale_
  double inverse_scale_ = 0.0;        // samples per degree
  std::vector<double> inverse_step_;  // 1 / (inverse_[i + 1] - inverse_[i]), 0 for an empty segment
  double degrees_per_sample_ = 0.0;   // 1 / inverse_scale_
  // Guide for angle_for_arc: guide_[g] is the last segment of inverse_ starting at or below arc
  // g / guide_scale_; its cells are narrower than any segment, so a lookup steps at most once.
  std::vector<uint32_t> guide_;
  double guide_scale_ = 0.0;  // guide cells per mm of arc
};

class RetinaMapping {
 public:
  RetinaMapping() = default;
  // kind with its edge: the shorter half-axis of the image (screen radius 1) is at field angle
  // half_fov_deg (angle), or at the height/arc of the chief ray at that angle (flat, retina).
  // Throws optics::OpticsError when the chief ray does not reach half_fov_deg and the mapping
  // needs it (flat, retina).
  RetinaMapping(FieldMapping kind, double half_fov_deg, const FieldAngleTable& table, const RetinaSurface& retina);
  // A physical flat film: screen radius 1 at lateral height half_extent_mm.
  RetinaMapping(double half_extent_mm, const RetinaSurface& retina);

  FieldMapping kind() const { return kind_; }
  // Retina arc length of a point at screen radius s >= 0; negative when it maps to nothing
  // (beyond the traced field or the retina's reach). table: the one given at construction.
  double arc_for_screen_radius(double s, const FieldAngleTable& table) const {
    switch (kind_) {
      case FieldMapping::Angle: return table.arc_for_angle(s * edge_);
      case FieldMapping::Retina: return s * edge_;
      case FieldMapping::Flat: {
        const double h = s * edge_;
        return h * std::abs(retina_curvature_) < 1.0 ? arc_for_height_(h) : -1.0;
      }
    }
    return -1.0;
  }
  // d arc / d screen radius at screen radius s >= 0 (where arc_for_screen_radius is not
  // negative): the slope screen_radius_for_arc gives, without inverting the mapping.
  double arc_slope(double s, const FieldAngleTable& table) const {
    switch (kind_) {
      case FieldMapping::Angle: return table.arc_slope_for_angle(s * edge_) * edge_;
      case FieldMapping::Retina: return edge_;
      case FieldMapping::Flat: {
        const double ch = s * edge_ * retina_curvature_;  // sin(c a): d arc / d h = 1 / cos(c a)
        return edge_ / std::sqrt(1.0 - ch * ch);
      }
    }
    return 0.0;
  }
  // The inverse: the screen radius whose retina point is at arc a (negative when none is), and
  // d arc / d screen radius there. A dispersive camera uses it to find which pixel a ray that
  // left the eye at another wavelength comes from (spectral MIS).
  double screen_radius_for_arc(double a, const FieldAngleTable& table, double* slope) const;
  double edge() const { return edge_; }  // degrees (angle) or mm (flat, retina)

 private:
  double arc_for_height_(double h) const { return RetinaSurface{0.0, retina_curvature_}.arc_for_height(h); }
  FieldMapping kind_ = FieldMapping::Angle;
  double edge_ = 1.0;
  double retina_curvature_ = 0.0;
};

}  // namespace eyetrace
