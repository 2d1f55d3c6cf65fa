// Prescription queries and validation. Validation runs once when a system is built, so it can
// afford to be thorough and to say exactly what is wrong.
#include "optics/prescription.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <fmt/format.h>

#include "optics/optics_error.h"
#include "optics/phase_plate.h"

namespace eyetrace::optics {

const char* to_string(SurfaceRole role) {
  switch (role) {
    case SurfaceRole::Refract: return "refract";
    case SurfaceRole::Stop: return "stop";
    case SurfaceRole::Image: return "image";
  }
  return "?";
}

int Prescription::stop_index() const {
  for (size_t i = 0; i < surfaces.size(); ++i)
    if (surfaces[i].role == SurfaceRole::Stop) return static_cast<int>(i);
  return -1;
}

double Prescription::stop_diameter_mm() const {
  const int s = stop_index();
  return s < 0 ? 0.0 : 2.0 * surfaces[s].semi_diameter_mm;
}

std::vector<double> Prescription::vertex_z_mm() const {
  std::vector<double> z(surfaces.size(), 0.0);
  for (size_t i = 1; i < surfaces.size(); ++i) z[i] = z[i - 1] + surfaces[i - 1].thickness_mm;
  return z;
}

double Prescription::axial_length_mm() const { return surfaces.empty() ? 0.0 : vertex_z_mm().back(); }

bool Prescription::rotationally_symmetric() const {
  for (const Surface& s : surfaces)
    if (!s.profile.rotationally_symmetric() || !s.placement.is_identity() || s.phase_plate) return false;
  return true;
}

const Medium* Prescription::find_medium(const std::string& name) const {
  for (const Medium& m : media)
    if (m.name == name) return &m;
  return nullptr;
}

double meeting_height(const SurfaceProfile& a, double z_a, const SurfaceProfile& b, double z_b, double h_max) {
  auto gap = [&](double r) { return (z_b + b.sag(r * r)) - (z_a + a.sag(r * r)); };
  if (gap(0.0) < 0.0) return 0.0;
  // Sample first (the gap need not be monotonic for conics of opposite kinds), then bisect
  // the first sign change.
  constexpr int kSteps = 256;
  double lo = 0.0;
  for (int i = 1; i <= kSteps; ++i) {
    double hi = h_max * i / kSteps;
    if (gap(hi) < 0.0) {
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (gap(mid) < 0.0 ? hi : lo) = mid;
      }
      return lo;
    }
    lo = hi;
  }
  return h_max;
}

namespace {

constexpr double kMaxIndex = 10.0;
constexpr double kMaxSurfaceThickness_mm = 1e6;  // 1 km

std::string label(const Prescription& p, size_t i) { return fmt::format("surface {} '{}'", i, p.surfaces[i].name); }

void check_finite(const Prescription& p, size_t i, const char* what, double value) {
  if (!std::isfinite(value))
    throw OpticsError(fmt::format("{}: {} is not a finite number ({})", label(p, i), what, value));
}

// Height up to which a surface is used: its semi-diameter, else the conic's own reach.
double used_height(const Surface& s) { return s.limited() ? s.semi_diameter_mm : s.profile.max_height(); }

// The biconic's second meridian and the placement: finite, axis in [0, 180), tilts and
// decentrations within their limits.
void validate_shape(const Prescription& p, size_t i) {
  const Surface& s = p.surfaces[i];
  const SurfacePlacement& at = s.placement;
  check_finite(p, i, "decentre_x_mm", at.decentre_x_mm);
  check_finite(p, i, "decentre_y_mm", at.decentre_y_mm);
  check_finite(p, i, "tilt_x_deg", at.tilt_x_deg);
  check_finite(p, i, "tilt_y_deg", at.tilt_y_deg);
  for (const double d : {at.decentre_x_mm, at.decentre_y_mm})
    if (std::abs(d) > kMaxDecentre_mm)
      throw OpticsError(fmt::format("{}: decentration {} mm is beyond +-{} mm", label(p, i), d, kMaxDecentre_mm));
  for (const double t : {at.tilt_x_deg, at.tilt_y_deg})
    if (!(std::abs(t) < kMaxTilt_deg))
      throw OpticsError(
          fmt::format("{}: tilt {} deg is outside (-{}, {}) deg", label(p, i), t, kMaxTilt_deg, kMaxTilt_deg));
  if (s.profile.kind != ProfileKind::Biconic) return;
  check_finite(p, i, "cross curvature", s.profile.cross_curvature);
  check_finite(p, i, "cross conic", s.profile.cross_conic);
  check_finite(p, i, "axis_deg", s.profile.axis_deg);
  if (!(s.profile.axis_deg >= 0.0 && s.profile.axis_deg < 180.0))
    throw OpticsError(fmt::format("{}: axis_deg {} is outside [0, 180)", label(p, i), s.profile.axis_deg));
}

void validate_surface(const Prescription& p, size_t i) {
  const Surface& s = p.surfaces[i];
  check_finite(p, i, "curvature", s.profile.curvature);
  check_finite(p, i, "conic", s.profile.conic);
  check_finite(p, i, "thickness_mm", s.thickness_mm);
  check_finite(p, i, "index", s.index_after);
  if (std::isnan(s.semi_diameter_mm) || s.semi_diameter_mm < 0.0)
    throw OpticsError(
        fmt::format("{}: semi-diameter {} mm must be >= 0 (0 = unlimited)", label(p, i), s.semi_diameter_mm));
  if (s.thickness_mm < 0.0)
    throw OpticsError(fmt::format("{}: thickness {} mm is negative", label(p, i), s.thickness_mm));
  // Beyond this, squared distances in the ray-conic intersection lose every significant digit.
  if (s.thickness_mm > kMaxSurfaceThickness_mm)
    throw OpticsError(
        fmt::format("{}: thickness {} mm is more than {} mm", label(p, i), s.thickness_mm, kMaxSurfaceThickness_mm));
  if (s.index_after < 1.0)
    throw OpticsError(fmt::format("{}: index {} of medium '{}' is below 1", label(p, i), s.index_after, s.medium));
  // No optical material comes near this; far beyond it, eta^2 in Snell's law overflows.
  if (s.index_after > kMaxIndex)
    throw OpticsError(
        fmt::format("{}: index {} of medium '{}' is above {}", label(p, i), s.index_after, s.medium, kMaxIndex));
  validate_shape(p, i);
  // The plate's rule (phase_plate.h) bends the direction tangential to a plane.
  if (s.phase_plate && !s.profile.is_flat())
    throw OpticsError(fmt::format("{}: a phase plate ({}) needs a flat surface", label(p, i), s.phase_plate->origin));
  if (s.profile.kind == ProfileKind::Plane && s.profile.curvature != 0.0)
    throw OpticsError(fmt::format("{}: a plane profile has curvature {}", label(p, i), s.profile.curvature));
  const double reach = s.profile.max_height();
  if (s.limited() && s.semi_diameter_mm > reach * (1.0 + 1e-12))
    throw OpticsError(fmt::format("{}: semi-diameter {:.6g} mm is beyond the conic's reach (max {:.6g} mm)",
                                  label(p, i), s.semi_diameter_mm, reach));
  if (s.role == SurfaceRole::Stop) {
    if (!s.profile.is_flat()) throw OpticsError(fmt::format("{}: the aperture stop must be flat", label(p, i)));
    if (!s.limited())
      throw OpticsError(fmt::format("{}: the aperture stop needs a finite semi-diameter > 0 (got {})", label(p, i),
                                    s.semi_diameter_mm));
    if (s.index_after != p.index_before(static_cast<int>(i)))
      throw OpticsError(
          fmt::format("{}: the medium after a stop must be the medium before it "
                      "(index {} vs {})",
                      label(p, i), s.index_after, p.index_before(static_cast<int>(i))));
  }
}

// z (system frame) where the line parallel to the axis through (x, y) meets the surface whose
// vertex is at z_vertex, if it does so inside the surface's clear aperture (or reach).
std::optional<double> surface_z_at(const Surface& s, double z_vertex, double x, double y) {
  const glm::dmat3 r = s.placement.system_from_local();
  const glm::dvec3 centre(s.placement.decentre_x_mm, s.placement.decentre_y_mm, z_vertex);
  // From 1 m in front, along +z, in the local frame (the rotation's inverse is its transpose).
  const glm::dmat3 local_from_system = glm::transpose(r);
  const glm::dvec3 o = local_from_system * (glm::dvec3(x, y, z_vertex - 1000.0) - centre);
  const glm::dvec3 d = local_from_system * glm::dvec3(0.0, 0.0, 1.0);
  const ProfileHit hit = intersect(s.profile, o, d, 0.0);
  if (!hit.hit) return std::nullopt;
  const glm::dvec3 at = o + hit.t * d;
  const double h = used_height(s);
  if (std::isfinite(h) && at.x * at.x + at.y * at.y > h * h) return std::nullopt;
  return z_vertex - 1000.0 + hit.t;
}

// The crossing check of two adjacent surfaces when either is biconic or placed: on a polar grid
// (32 azimuths, 64 radii) over the smaller used height about the axis, wherever both surfaces
// are present.
void check_crossing_2d(const Prescription& p, size_t i, const std::vector<double>& z) {
  const Surface& a = p.surfaces[i];
  const Surface& b = p.surfaces[i + 1];
  double h = std::fmin(used_height(a), used_height(b));
  if (!std::isfinite(h)) h = 50.0;  // two unbounded sheets: the central 50 mm
  for (int k = 0; k < 32; ++k) {
    const double phi = 2.0 * std::numbers::pi * k / 32;
    for (int j = 0; j <= 64; ++j) {
      const double r = h * j / 64, x = r * std::cos(phi), y = r * std::sin(phi);
      const std::optional<double> za = surface_z_at(a, z[i], x, y), zb = surface_z_at(b, z[i + 1], x, y);
      if (!za || !zb || *zb - *za >= -1e-9) continue;
      throw OpticsError(
          fmt::format("{} and surface {} '{}' cross at ({:.4g}, {:.4g}) mm, inside their clear apertures: "
                      "thickness {} mm is too small for their sags, tilts and decentrations",
                      label(p, i), i + 1, b.name, x, y, a.thickness_mm));
    }
  }
}

}  // namespace

void validate(const Prescription& p) {
  const std::string who = p.name.empty() ? "prescription" : fmt::format("prescription '{}'", p.name);
  if (p.surfaces.size() < 2) throw OpticsError(fmt::format("{}: needs at least one surface and an image surface", who));
  if (!std::isfinite(p.object_index) || p.object_index < 1.0 || p.object_index > kMaxIndex)
    throw OpticsError(fmt::format("{}: object-space index {} is invalid", who, p.object_index));
  if (!std::isfinite(p.wavelength_nm) || p.wavelength_nm <= 0.0)
    throw OpticsError(fmt::format("{}: wavelength {} nm is invalid", who, p.wavelength_nm));
  int stops = 0;
  for (size_t i = 0; i < p.surfaces.size(); ++i) {
    validate_surface(p, i);
    const bool last = i + 1 == p.surfaces.size();
    if (last != (p.surfaces[i].role == SurfaceRole::Image))
      throw OpticsError(fmt::format(
          "{}: {}", label(p, i),
          last ? "the last surface must have role 'image'" : "only the last surface may have role 'image'"));
    stops += p.surfaces[i].role == SurfaceRole::Stop;
  }
  if (stops != 1)
    throw OpticsError(fmt::format("{}: needs exactly one aperture stop (role 'stop'), found {}", who, stops));

  // Adjacent surfaces must not cross inside the smaller clear aperture: a crossing means a
  // ray would have to travel backwards between them.
  const std::vector<double> z = p.vertex_z_mm();
  for (size_t i = 0; i + 1 < p.surfaces.size(); ++i) {
    const Surface& a = p.surfaces[i];
    const Surface& b = p.surfaces[i + 1];
    if (!a.profile.rotationally_symmetric() || !b.profile.rotationally_symmetric() || !a.placement.is_identity() ||
        !b.placement.is_identity()) {
      check_crossing_2d(p, i, z);
      continue;
    }
    const double h = std::fmin(used_height(a), used_height(b));
    if (!std::isfinite(h)) continue;  // two unbounded sheets: only the axis gap matters
    for (int j = 1; j <= 128; ++j) {
      const double r = h * j / 128;
      const double gap = (z[i + 1] + b.profile.sag(r * r)) - (z[i] + a.profile.sag(r * r));
      if (gap >= -1e-9) continue;  // touching at the rim (a lens edge) is allowed
      const double meet = meeting_height(a.profile, z[i], b.profile, z[i + 1], h);
      throw OpticsError(
          fmt::format("{} and surface {} '{}' cross at height {:.4g} mm, inside the clear aperture "
                      "({:.4g} mm): thickness {} mm is too small for their sags",
                      label(p, i), i + 1, b.name, meet, h, a.thickness_mm));
    }
  }
}

Prescription at_wavelength(const Prescription& p, double lambda_nm) {
  if (!std::isfinite(lambda_nm) || lambda_nm < kMinWavelength_nm || lambda_nm > kMaxWavelength_nm)
    throw OpticsError(
        fmt::format("wavelength {} nm is outside [{}, {}] nm", lambda_nm, kMinWavelength_nm, kMaxWavelength_nm));
  Prescription out = p;
  out.wavelength_nm = lambda_nm;
  for (size_t i = 0; i < out.surfaces.size(); ++i) {
    Surface& s = out.surfaces[i];
    const Medium* m = p.find_medium(s.medium);
    if (!m) throw OpticsError(fmt::format("{}: medium '{}' is not in the media table", label(p, i), s.medium));
    s.index_after = m->index_at(lambda_nm);
  }
  return out;
}

void set_stop_diameter(Prescription& p, double diameter_mm) {
  const int s = p.stop_index();
  if (s < 0) throw OpticsError("set_stop_diameter: the prescription has no aperture stop");
  p.surfaces[s].semi_diameter_mm = 0.5 * diameter_mm;
}

namespace {

// "; biconic: cross radius 7.5 conic -0.2, axis 90 deg; decentre (0.3, 0) mm, tilt (2, 0) deg"
// for a surface that is not rotationally symmetric, "" otherwise.
std::string shape_note(const Surface& s) {
  std::string out;
  if (s.profile.kind == ProfileKind::Biconic)
    out += fmt::format(
        "; biconic: cross radius {}, conic {:.5g}, axis {:g} deg",
        s.profile.cross_curvature == 0.0 ? std::string("flat") : fmt::format("{:.5g}", 1.0 / s.profile.cross_curvature),
        s.profile.cross_conic, s.profile.axis_deg);
  if (!s.placement.is_identity())
    out += fmt::format("; decentre ({:g}, {:g}) mm, tilt ({:g}, {:g}) deg", s.placement.decentre_x_mm,
                       s.placement.decentre_y_mm, s.placement.tilt_x_deg, s.placement.tilt_y_deg);
  if (const PhasePlate* plate = s.phase_plate.get())
    out += fmt::format("; phase plate {}: order {}, measured over a {:g} mm pupil, {:.4g} mm here", plate->origin,
                       plate->max_order(), plate->measured_pupil_diameter_mm, 2.0 * plate->radius_mm());
  return out;
}

}  // namespace

std::string describe(const Prescription& p) {
  std::string out =
      fmt::format("{}{} ({} nm)\n", p.name, p.variant.empty() ? "" : " [" + p.variant + "]", p.wavelength_nm);
  out += fmt::format("{:>3} {:<24} {:>10} {:>9} {:>10} {:>9} {:>8} {:<10} {}\n", "#", "name", "radius", "conic",
                     "thickness", "index", "semi-d", "medium", "role");
  for (size_t i = 0; i < p.surfaces.size(); ++i) {
    const Surface& s = p.surfaces[i];
    const std::string radius = s.profile.is_flat() ? "flat" : fmt::format("{:.5g}", 1.0 / s.profile.curvature);
    const std::string sd = s.limited() ? fmt::format("{:.4g}", s.semi_diameter_mm) : "-";
    out += fmt::format("{:>3} {:<24} {:>10} {:>9.5g} {:>10.6g} {:>9.6g} {:>8} {:<10} {}{}\n", i, s.name, radius,
                       s.profile.conic, s.thickness_mm, s.index_after, sd, s.medium, to_string(s.role), shape_note(s));
  }
  return out;
}

}  // namespace eyetrace::optics
