#include "cameras/retina_mapping.h"

#include <cmath>

#include <fmt/format.h>

#include "cameras/chief_ray.h"
#include "optics/optics_error.h"

namespace eyetrace {

namespace {

// Node spacing along the retina. Linear interpolation between nodes then errs by
// theta'' da^2 / 8, about 1e-4 degrees for the eyes.
constexpr double kNodeStep_mm = 0.05;
// Uniform angle samples of the inverse table per degree.
constexpr double kInverseSamplesPerDegree = 32.0;

// Index of the node interval containing x in a sorted vector (clamped).
size_t interval_of(const std::vector<double>& xs, double x) {
  const auto it = std::upper_bound(xs.begin(), xs.end(), x);
  const size_t i = it == xs.begin() ? 0 : static_cast<size_t>(it - xs.begin()) - 1;
  return std::min(i, xs.size() - 2);
}

}  // namespace

const char* to_string(FieldMapping m) {
  switch (m) {
    case FieldMapping::Angle: return "angle";
    case FieldMapping::Flat: return "flat";
    case FieldMapping::Retina: return "retina";
  }
  return "?";
}

bool parse_field_mapping(const std::string& text, FieldMapping* out) {
  for (FieldMapping m : {FieldMapping::Angle, FieldMapping::Flat, FieldMapping::Retina})
    if (text == to_string(m)) {
      *out = m;
      return true;
    }
  return false;
}

FieldAngleTable::FieldAngleTable(const optics::CompiledSystem& system, const RetinaSurface& retina, double z_plane,
                                 double angle_limit_deg, double max_arc_mm) {
  arcs_ = {0.0};
  angles_ = {0.0};
  chief_q_ = {0.0};
  const double arc_limit = std::fmin(max_arc_mm, retina.max_arc_mm());
  for (double a = kNodeStep_mm; a <= arc_limit && angles_.back() < angle_limit_deg; a += kNodeStep_mm) {
    const glm::dvec2 p = retina.point(a);
    if (p.y - z_plane < kMinPlaneGap_mm) break;
    const glm::dvec3 from(p.x, 0.0, p.y);
    const std::optional<double> q = aim_chief_ray(system, from, z_plane, chief_q_.back());
    if (!q) break;
    const optics::TraceResult r = trace_towards_plane(system, from, *q, 0.0, z_plane);
    if (!r.ok()) break;
    // A retina point on +x images a field point on -x (the eye inverts): the angle of the
    // leaving ray from the -z axis, positive towards -x.
    const double angle = std::atan2(-r.ray.direction.x, -r.ray.direction.z) * kDegreesPerRadian;
    if (!(angle > angles_.back())) break;
    arcs_.push_back(a);
    angles_.push_back(angle);
    chief_q_.push_back(*q);
  }
  if (empty()) return;
  const size_t n = static_cast<size_t>(std::ceil(max_angle_deg() * kInverseSamplesPerDegree)) + 1;
  inverse_scale_ = static_cast<double>(n - 1) / max_angle_deg();
  degrees_per_sample_ = 1.0 / inverse_scale_;
  inverse_.resize(n);
  for (size_t j = 0; j < n; ++j) {
    const double angle = std::fmin(static_cast<double>(j) / inverse_scale_, max_angle_deg());
    const size_t i = interval_of(angles_, angle);
    const double t = (angle - angles_[i]) / (angles_[i + 1] - angles_[i]);
    inverse_[j] = arcs_[i] + t * (arcs_[i + 1] - arcs_[i]);
  }
  // Guide cells narrower than the narrowest segment: a cell then meets at most two segments, so
  // a lookup steps at most once from the guide's segment (angle_for_arc, without a loop).
  double narrowest = inverse_.back();
  inverse_step_.resize(n - 1);
  for (size_t i = 0; i + 1 < n; ++i) {
    const double width = inverse_[i + 1] - inverse_[i];
    narrowest = std::fmin(narrowest, width);
    inverse_step_[i] = width > 0.0 ? 1.0 / width : 0.0;
  }
  const double cells = std::fmin(inverse_.back() / std::fmax(narrowest, 1e-12) * 1.25, 64.0 * double(n));
  guide_scale_ = std::ceil(cells) / std::fmax(inverse_.back(), 1e-12);
  guide_.resize(static_cast<size_t>(std::ceil(cells)) + 1);
  for (size_t g = 0, i = 0; g < guide_.size(); ++g) {
    while (i + 2 < n && inverse_[i + 1] <= static_cast<double>(g) / guide_scale_) ++i;
    guide_[g] = static_cast<uint32_t>(i);
  }
}

double FieldAngleTable::angle_for_arc(double a, double* slope) const {
  if (empty() || !(a >= inverse_.front() && a <= inverse_.back())) return -1.0;
  // The segment of the resampled inverse that holds a (arc_for_angle interpolates linearly in
  // it): the guide's segment, or the next one when that starts at or below a (a guide cell meets
  // at most two segments). Branch-free: which of the two it is is as good as random.
  const size_t g = std::min(static_cast<size_t>(a * guide_scale_), guide_.size() - 1);
  size_t i = guide_[g];
  i += static_cast<size_t>((i + 2 < inverse_.size()) & (inverse_[i + 1] <= a));
  while (i + 2 < inverse_.size() && inverse_[i + 1] <= a) ++i;  // only if the guide's size was capped
  const double width = inverse_[i + 1] - inverse_[i];
  *slope = width * inverse_scale_;
  return (static_cast<double>(i) + (a - inverse_[i]) * inverse_step_[i]) * degrees_per_sample_;
}

std::optional<double> FieldAngleTable::chief_q_for_arc(double a) const {
  if (empty() || a < 0.0 || a > max_arc_mm()) return std::nullopt;
  const size_t i = interval_of(arcs_, a);
  const double t = (a - arcs_[i]) / (arcs_[i + 1] - arcs_[i]);
  return chief_q_[i] + t * (chief_q_[i + 1] - chief_q_[i]);
}

RetinaMapping::RetinaMapping(FieldMapping kind, double half_fov_deg, const FieldAngleTable& table,
                             const RetinaSurface& retina)
    : kind_(kind), retina_curvature_(retina.curvature) {
  if (kind == FieldMapping::Angle) {
    edge_ = half_fov_deg;
    return;
  }
  const double a = table.arc_for_angle(half_fov_deg);
  if (a < 0.0)
    throw optics::OpticsError(
        fmt::format("the chief ray of this eye reaches only {:.2f} degrees from the axis, so a field of view of "
                    "{:.4g} degrees cannot set the scale of mapping \"{}\"; use a smaller fov or mapping \"angle\"",
                    table.max_angle_deg(), 2.0 * half_fov_deg, to_string(kind)));
  edge_ = kind == FieldMapping::Retina ? a : retina.point(a).x;
}

double RetinaMapping::screen_radius_for_arc(double a, const FieldAngleTable& table, double* slope) const {
  switch (kind_) {
    case FieldMapping::Angle: {
      const double angle = table.angle_for_arc(a, slope);
      *slope *= edge_;
      return angle < 0.0 ? -1.0 : angle / edge_;
    }
    case FieldMapping::Retina: *slope = edge_; return a / edge_;
    case FieldMapping::Flat: {
      // h = sin(c a) / c, so d arc / d h = 1 / cos(c a); the near half of the sphere only.
      const RetinaSurface surface{0.0, retina_curvature_};
      const double cos_ca = -surface.normal(a).y;
      if (!(cos_ca > 0.0)) return -1.0;
      *slope = edge_ / cos_ca;
      return surface.point(a).x / edge_;
    }
  }
  return -1.0;
}

RetinaMapping::RetinaMapping(double half_extent_mm, const RetinaSurface& retina)
    : kind_(FieldMapping::Flat), edge_(half_extent_mm), retina_curvature_(retina.curvature) {}

}  // namespace eyetrace
