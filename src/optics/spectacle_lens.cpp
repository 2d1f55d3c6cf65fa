// A spectacle lens before the eye (see spectacle_lens.h).
#include "optics/spectacle_lens.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "optics/optics_error.h"
#include "optics/sphero_cylinder.h"

namespace eyetrace::optics {

namespace {

constexpr double kMaxSpectacleCylinder_D = 10.0;
constexpr double kMaxVertexDistance_mm = 50.0;
constexpr double kMaxSpectacleThickness_mm = 30.0;

void check(const char* option, double value, double lo, double hi, const char* unit) {
  if (!std::isfinite(value) || value < lo || value > hi)
    throw OpticsError(option, fmt::format("{} {} is outside [{}, {}] {}", value, unit, lo, hi, unit));
}

void check_options(const SpectacleLens& l) {
  check("spectaclesphere", l.sphere_D, -kMaxSpectaclePower_D, kMaxSpectaclePower_D, "D");
  check("spectaclecylinder", l.cylinder_D, -kMaxSpectacleCylinder_D, kMaxSpectacleCylinder_D, "D");
  check("spectacleaxis", l.axis_deg, 0.0, 180.0, "deg");
  if (!std::isfinite(l.vertex_distance_mm) || !(l.vertex_distance_mm > 0.0) ||
      l.vertex_distance_mm > kMaxVertexDistance_mm)
    throw OpticsError("vertexdistance",
                      fmt::format("{} mm is outside (0, {}] mm: the lens's back vertex must lie in front of the eye",
                                  l.vertex_distance_mm, kMaxVertexDistance_mm));
  check("spectacleindex", l.index, 1.3, 2.0, "");
  if (l.centre_thickness_mm && !(std::isfinite(*l.centre_thickness_mm) && *l.centre_thickness_mm > 0.0 &&
                                 *l.centre_thickness_mm <= kMaxSpectacleThickness_mm))
    throw OpticsError("spectaclethickness",
                      fmt::format("{} mm is outside (0, {}] mm", *l.centre_thickness_mm, kMaxSpectacleThickness_mm));
  if (l.base_curve_D) check("spectaclebasecurve", *l.base_curve_D, -kMaxSpectaclePower_D, kMaxSpectaclePower_D, "D");
}

// The lens's two surfaces for a centre thickness t (mm): front of power F1, back solved per
// principal meridian so the back-vertex power is S (meridian A) and S + C (meridian A + 90):
// F2 = BVP - F1 / (1 - (t/n) F1), c2 = F2 / (1 - n).
struct LensShape {
  SurfaceProfile front, back;
};
LensShape shape(const SpectacleLens& l, double front_D, double t_mm) {
  const double n = l.index;
  const double front_vergence_D = front_D / (1.0 - t_mm / 1000.0 / n * front_D);
  auto back_curvature = [&](double bvp_D) { return (bvp_D - front_vergence_D) / (1.0 - n) / 1000.0; };
  LensShape s;
  s.front = SurfaceProfile::from_curvature(front_D / (n - 1.0) / 1000.0, 0.0);
  const double c_axis = back_curvature(l.sphere_D);
  if (l.cylinder_D == 0.0) {
    s.back = SurfaceProfile::from_curvature(c_axis, 0.0);
  } else {
    // The biconic's first meridian in the prescription frame (the axis is in TABO notation).
    s.back =
        SurfaceProfile::biconic(c_axis, 0.0, back_curvature(l.sphere_D + l.cylinder_D), 0.0, tabo_axis_deg(l.axis_deg));
  }
  return s;
}

// Thinnest edge (mm) at the lens's rim over azimuths every 5 degrees (a biconic's sag varies
// smoothly between its principal meridians, which this grid contains for any axis up to 2.5
// degrees); -inf when a surface does not reach the rim.
double edge_thickness_mm(const LensShape& s, double t_mm) {
  const double h = 0.5 * kSpectacleDiameter_mm;
  if (s.front.max_height() < h || s.back.max_height() < h) return -INFINITY;
  double edge = INFINITY;
  for (int k = 0; k < 72; ++k) {
    const double a = k * M_PI / 36.0;
    edge = std::min(
        edge, t_mm + s.back.sag(h * std::cos(a), h * std::sin(a)) - s.front.sag(h * std::cos(a), h * std::sin(a)));
  }
  return edge;
}

// The default centre thickness: 2 mm, or (a plus lens) the one whose edge is exactly 1 mm. The
// edge thickness increases monotonically with t (the back curve depends on t only through the
// front's reduced vergence, weakly), so bisection on [2, 30] mm finds it.
double default_thickness_mm(const SpectacleLens& l, double front_D) {
  auto edge = [&](double t) { return edge_thickness_mm(shape(l, front_D, t), t); };
  double lo = kDefaultSpectacleThickness_mm, hi = kMaxSpectacleThickness_mm;
  if (!(edge(lo) < kMinSpectacleEdge_mm)) return lo;
  if (!(edge(hi) >= kMinSpectacleEdge_mm)) return hi;  // too strong a lens: add_spectacle_lens says so
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (edge(mid) < kMinSpectacleEdge_mm ? lo : hi) = mid;
  }
  return hi;
}

// The smallest height (mm) at which surface b (vertex at z_b) comes in front of surface a (vertex
// at 0), over a polar grid up to h; h when it does not. A grid rather than meeting_height's one
// meridian, because either surface may be a biconic.
double meeting_height_any_meridian(const SurfaceProfile& a, const SurfaceProfile& b, double z_b, double h) {
  constexpr int kRadii = 128;
  for (int i = 0; i <= kRadii; ++i) {
    const double r = h * i / kRadii;
    for (int k = 0; k < 72; ++k) {
      const double x = r * std::cos(k * M_PI / 36.0), y = r * std::sin(k * M_PI / 36.0);
      if (z_b + b.sag(x, y) - a.sag(x, y) <= 0.0) return r;
    }
  }
  return h;
}

void add_media(Prescription& p, double index) {
  if (!p.find_medium("air")) p.media.push_back(Medium{"air", 1.0, p.reference_wavelength_nm, {}});
  p.media.push_back(Medium{"spectacle lens", index, p.reference_wavelength_nm, {}});
}

}  // namespace

double vogel_base_curve_D(double se_D) { return std::max(kMinBaseCurve_D, se_D >= 0.0 ? se_D + 6.0 : se_D / 2 + 6.0); }

void add_spectacle_lens(Prescription& eye, const SpectacleLens& l) {
  check_options(l);
  if (eye.object_index != 1.0) throw OpticsError("spectaclesphere", "a spectacle lens needs an eye in air");
  const double front_D = l.base_curve_D ? *l.base_curve_D : vogel_base_curve_D(l.sphere_D + 0.5 * l.cylinder_D);
  const double t = l.centre_thickness_mm ? *l.centre_thickness_mm : default_thickness_mm(l, front_D);
  const LensShape s = shape(l, front_D, t);
  const double edge = edge_thickness_mm(s, t);
  if (!(edge > 0.0))
    throw OpticsError(l.centre_thickness_mm ? "spectaclethickness" : "spectaclesphere",
                      std::isfinite(edge)
                          ? fmt::format("the lens's surfaces meet inside its {} mm diameter: its edge is {:.3f} mm "
                                        "thick with a {} mm centre; give a thicker centre or a weaker lens",
                                        kSpectacleDiameter_mm, edge, t)
                          : fmt::format("a lens of {} D front and {} D back-vertex power cannot span its {} mm "
                                        "diameter (a surface curves too steeply)",
                                        front_D, l.sphere_D, kSpectacleDiameter_mm));

  // On or inside the eye: the back surface must stay in front of the eye's first surface across
  // that surface's clear aperture (at the vertex that is vertexdistance > 0).
  const Surface& first = eye.surfaces[0];
  const double h_eye = first.limited() ? first.semi_diameter_mm : 0.5 * kSpectacleDiameter_mm;
  const double meet = meeting_height_any_meridian(s.back, first.profile, l.vertex_distance_mm, h_eye);
  if (meet < h_eye)
    throw OpticsError("vertexdistance", fmt::format("{} mm puts the lens inside the eye: its back surface meets the "
                                                    "eye's first surface '{}' {:.3g} mm from the axis",
                                                    l.vertex_distance_mm, first.name, meet));

  Surface front{"spectacle front", s.front, t, "spectacle lens", l.index, 0.5 * kSpectacleDiameter_mm};
  Surface back{"spectacle back", s.back, l.vertex_distance_mm, "air", 1.0, 0.5 * kSpectacleDiameter_mm};
  eye.surfaces.insert(eye.surfaces.begin(), {front, back});
  add_media(eye, l.index);
  eye.notes.push_back(fmt::format(
      "spectacle lens {:+.2f} / {:+.2f} x {:g} (n {:g}, no dispersion) at vertex distance {:g} mm: base curve {:+.2f} "
      "D, "
      "centre {:.2f} mm, edge {:.2f} mm at {:g} mm diameter; z = 0 is its front vertex",
      l.sphere_D, l.cylinder_D, l.axis_deg, l.index, l.vertex_distance_mm, front_D, t, edge, kSpectacleDiameter_mm));
  validate(eye);
}

}  // namespace eyetrace::optics
