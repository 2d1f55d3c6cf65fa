// Chromatic difference of refraction and transverse chromatic aberration (see chromatic.h).
#include "optics/chromatic.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "optics/launch_plane.h"
#include "optics/medium.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/sequential_trace.h"
#include "optics/spot.h"

namespace eyetrace::optics {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kAimTolerance_mm = 1e-12;    // chief ray at the stop plane
constexpr double kImageTolerance_mm = 1e-10;  // reference chief ray on the image point (2e-8 arcmin)
constexpr int kMaxNewton = 60;

void check_wavelength(const char* option, double lambda_nm) {
  if (!(lambda_nm >= kMinWavelength_nm && lambda_nm <= kMaxWavelength_nm))
    throw OpticsError(fmt::format("{}: {} nm is outside [{}, {}] nm, the wavelengths the dispersion laws are used for",
                                  option, lambda_nm, kMinWavelength_nm, kMaxWavelength_nm));
}

std::string describe_loss(const Prescription& p, const TraceResult& t) {
  const int i = std::clamp(t.surface, 0, p.image_index());
  return fmt::format("{} at surface {} '{}'", to_string(t.status), i, p.surfaces[i].name);
}

// The rays of one object point, by one parameter q: object at infinity, the ray along
// `direction` through (0, q, z_start); finite object, the ray from `source` through
// (0, q, z_pupil). Both start on the plane z_start, in front of the first surface.
struct ObjectPoint {
  bool at_infinity = true;
  glm::dvec3 direction{0.0, 0.0, 1.0};
  glm::dvec3 source{0.0};
  double z_pupil = 0.0;
  double z_start = 0.0;

  Ray ray(double q) const {
    Ray r;
    if (at_infinity) {
      r.origin = {0.0, q, z_start};
      r.direction = direction;
    } else {
      // From the source through (0, q, z_pupil), started on the plane z_start: the tracer's
      // intersections lose precision with the origin's distance (2 um at 1 km).
      const glm::dvec3 target(0.0, q, z_pupil), d = target - source;
      r.direction = d / std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
      r.origin = target - (z_pupil - z_start) / r.direction.z * r.direction;
    }
    return r;
  }
};

ObjectPoint object_point(const Prescription& object_p, const Prescription& p, double field_deg,
                         double object_distance_m) {
  if (!(std::abs(field_deg) < 85.0))
    throw OpticsError(fmt::format("chief ray: field {} deg must be within (-85, 85) deg", field_deg));
  if (!(object_distance_m > 0.0))
    throw OpticsError(fmt::format("chief ray: object distance {} m must be positive", object_distance_m));
  const double theta = field_deg * kDeg;
  ObjectPoint o;
  o.direction = {0.0, -std::sin(theta), std::cos(theta)};
  o.at_infinity = std::isinf(object_distance_m);
  const double object_pupil = paraxial_analysis(object_p).entrance_pupil.position_mm;
  const double pupil = paraxial_analysis(p).entrance_pupil.position_mm;
  o.z_start = std::min(launch_plane(p), std::min(object_pupil, pupil) - 1.0);
  if (o.at_infinity) {
    o.z_pupil = pupil;
  } else {
    o.z_pupil = object_pupil;
    o.source = glm::dvec3(0.0, 0.0, object_pupil) - object_distance_m * 1000.0 * o.direction;
    if (o.source.z >= o.z_start)
      throw OpticsError(fmt::format("chief ray: object at {} m lies inside the system", object_distance_m));
  }
  return o;
}

// Height at which the ray of parameter q crosses the stop plane (the stop's own opening does not
// clip it); NaN when it is lost before.
double stop_height(const CompiledSystem& sys, const ObjectPoint& o, double q) {
  const int stop = sys.stop_index();
  Ray r = o.ray(q);
  if (stop > 0) {
    const TraceResult t = sys.trace_range(r, 0, stop - 1);
    if (!t.ok()) return std::nan("");
    r = t.ray;
  }
  const double z_stop = sys.vertex_z(stop);
  if (!(r.direction.z > 0.0)) return std::nan("");
  return r.origin.y + (z_stop - r.origin.z) / r.direction.z * r.direction.y;
}

// Newton on a scalar function with a central-difference derivative, to |f| < tolerance. When
// rounding stops it short of that (a far object: ray origins 1e4 mm away carry 1e-12 mm of
// rounding), the best point is taken if |f| < 1000 tolerance. NaN when f is NaN somewhere on the
// way or nothing comes that close.
template <class F>
double solve(F f, double x, double h, double tolerance) {
  double best_x = std::nan(""), best_v = std::numeric_limits<double>::infinity();
  for (int i = 0; i < kMaxNewton; ++i) {
    const double v = f(x);
    if (!std::isfinite(v)) return std::nan("");
    if (std::abs(v) < best_v) best_x = x, best_v = std::abs(v);
    if (std::abs(v) < tolerance) return x;
    const double slope = (f(x + h) - f(x - h)) / (2.0 * h);
    if (!std::isfinite(slope) || slope == 0.0) break;
    const double step = v / slope;
    x -= step;
    if (std::abs(step) <= 1e-15 * (1.0 + std::abs(x))) break;  // rounding reached
  }
  return best_v < 1000.0 * tolerance ? best_x : std::nan("");
}

}  // namespace

void validate(const ChromaticOptions& o) {
  check_wavelength("chromatic range", o.min_wavelength_nm);
  check_wavelength("chromatic range", o.max_wavelength_nm);
  if (!(o.min_wavelength_nm < o.max_wavelength_nm))
    throw OpticsError(fmt::format("chromatic range: {} to {} nm is empty (the first wavelength must be the shorter)",
                                  o.min_wavelength_nm, o.max_wavelength_nm));
  if (!(o.step_nm > 0.0 && o.step_nm <= o.max_wavelength_nm - o.min_wavelength_nm))
    throw OpticsError(fmt::format("chromatic step: {} nm must be in (0, {}] nm (the range's width)", o.step_nm,
                                  o.max_wavelength_nm - o.min_wavelength_nm));
  check_wavelength("tca wavelengths", o.tca_short_nm);
  check_wavelength("tca wavelengths", o.tca_long_nm);
  if (!(o.tca_short_nm < o.tca_long_nm))
    throw OpticsError(
        fmt::format("tca wavelengths: {} and {} nm: the first must be the shorter", o.tca_short_nm, o.tca_long_nm));
  if (o.centroid_grid != 0 && (o.centroid_grid < 2 || o.centroid_grid > 4096))
    throw OpticsError(fmt::format("centroid grid: {} must be 0 (none) or in [2, 4096]", o.centroid_grid));
}

std::vector<RefractionAtWavelength> chromatic_refraction(const Prescription& p, const ChromaticOptions& o) {
  validate(o);
  std::vector<double> wavelengths;
  const double span = o.max_wavelength_nm - o.min_wavelength_nm;
  const int steps = static_cast<int>(std::floor(span / o.step_nm + 1e-9));
  for (int k = 0; k <= steps; ++k) wavelengths.push_back(o.min_wavelength_nm + k * o.step_nm);
  if (wavelengths.back() < o.max_wavelength_nm - 1e-9 * o.step_nm) wavelengths.push_back(o.max_wavelength_nm);
  wavelengths.back() = std::min(wavelengths.back(), o.max_wavelength_nm);  // no 700.0000000001
  std::vector<RefractionAtWavelength> out;
  for (double lambda : wavelengths) out.push_back({lambda, refraction_D(at_wavelength(p, lambda))});
  return out;
}

ChiefRay trace_chief_ray(const Prescription& p, double field_deg, double object_distance_m,
                         const Prescription* object_p) {
  const ObjectPoint o = object_point(object_p ? *object_p : p, p, field_deg, object_distance_m);
  const CompiledSystem sys(p);
  ChiefRay out;
  double q0 = 0.0;  // towards the entrance-pupil centre
  if (o.at_infinity) q0 = (-(o.z_pupil - o.z_start) / o.direction.z * o.direction).y;
  const double q = solve([&](double x) { return stop_height(sys, o, x); }, q0, 1e-6, kAimTolerance_mm);
  if (!std::isfinite(q)) {
    out.lost = fmt::format("no ray of field {} deg reaches the centre of the stop", field_deg);
    return out;
  }
  const TraceResult t = sys.trace_forward(o.ray(q));
  if (!t.ok()) {
    out.lost = describe_loss(p, t);
    return out;
  }
  out.ok = true;
  out.object_ray = o.ray(q);
  out.image_mm = t.ray.origin;
  out.image_coordinate_mm = image_coordinate_mm(p, t.ray.origin);
  return out;
}

double image_coordinate_mm(const Prescription& p, const glm::dvec3& point) {
  const SurfaceProfile& image = p.surfaces.back().profile;
  if (image.is_flat()) return -point.y;
  const double radius = 1.0 / image.curvature;
  const double z_centre = p.axial_length_mm() + radius;
  // Angle at the centre of curvature from the vertex to the point, > 0 towards -y.
  const double axial = (point.z - z_centre) * (radius < 0.0 ? 1.0 : -1.0);
  return std::abs(radius) * std::atan2(-point.y, axial);
}

double visual_angle_deg(const Prescription& p, double coordinate_mm) {
  if (coordinate_mm == 0.0) return 0.0;
  const ParaxialData d = paraxial_analysis(p);
  const double nodal_to_image = p.vertex_z_mm().back() - d.back_nodal_point_mm;
  const double guess = std::atan(coordinate_mm / nodal_to_image) / kDeg;
  auto miss = [&](double field) {
    if (!(std::abs(field) < 85.0)) return std::nan("");
    const ChiefRay c = trace_chief_ray(p, field);
    return c.ok ? c.image_coordinate_mm - coordinate_mm : std::nan("");
  };
  return solve(miss, guess, 1e-4, kImageTolerance_mm);
}

TransverseChromatic transverse_chromatic_aberration(const Prescription& p, double field_deg, double object_distance_m,
                                                    const ChromaticOptions& options) {
  validate(options);
  TransverseChromatic out;
  out.field_deg = field_deg;
  const ChiefRay s = trace_chief_ray(at_wavelength(p, options.tca_short_nm), field_deg, object_distance_m, &p);
  const ChiefRay l = trace_chief_ray(at_wavelength(p, options.tca_long_nm), field_deg, object_distance_m, &p);
  for (const auto& [ray, lambda] : {std::pair{&s, options.tca_short_nm}, std::pair{&l, options.tca_long_nm}})
    if (!ray->ok) {
      out.lost = fmt::format("{} nm chief ray: {}", lambda, ray->lost);
      return out;
    }
  out.short_angle_deg = visual_angle_deg(p, s.image_coordinate_mm);
  out.long_angle_deg = visual_angle_deg(p, l.image_coordinate_mm);
  if (!std::isfinite(out.short_angle_deg) || !std::isfinite(out.long_angle_deg)) {
    out.lost = "no reference chief ray reaches the image of one of the wavelengths";
    return out;
  }
  const double sign = field_deg < 0.0 ? -1.0 : 1.0;  // + = short image farther out along the field
  out.ok = true;
  out.tca_arcmin = sign * 60.0 * (out.short_angle_deg - out.long_angle_deg);
  out.retina_um = sign * 1000.0 * (s.image_coordinate_mm - l.image_coordinate_mm);

  if (options.centroid_grid > 0) {
    // trace_spot places a finite source relative to the entrance pupil of the system it traces,
    // and the pupil moves with wavelength (13 um from 450 to 650 nm for Navarro's eye: 0.06 arcmin
    // at 0.25 m). So each wavelength gets the field and distance that put its source at p's
    // object point.
    auto spot = [&](double lambda) {
      const Prescription at = at_wavelength(p, lambda);
      SpotOptions so{field_deg, object_distance_m, options.centroid_grid};
      if (std::isfinite(object_distance_m)) {
        const double shift = paraxial_analysis(at).entrance_pupil.position_mm -
                             paraxial_analysis(p).entrance_pupil.position_mm;  // mm, +z
        const double d = object_distance_m * 1000.0, theta = field_deg * kDeg;
        const double y = d * std::sin(theta), z = d * std::cos(theta) + shift;  // from the new pupil
        so.field_deg = std::atan2(y, z) / kDeg;
        so.object_distance_m = std::hypot(y, z) / 1000.0;
      }
      return trace_spot(at, so);
    };
    const SpotResult a = spot(options.tca_short_nm), b = spot(options.tca_long_nm);
    if (a.rays > 0 && b.rays > 0) {
      const double ca = image_coordinate_mm(p, a.centroid_mm), cb = image_coordinate_mm(p, b.centroid_mm);
      const double angle_a = visual_angle_deg(p, ca), angle_b = visual_angle_deg(p, cb);
      if (std::isfinite(angle_a) && std::isfinite(angle_b)) {
        out.centroid_ok = true;
        out.centroid_tca_arcmin = sign * 60.0 * (angle_a - angle_b);
        out.centroid_retina_um = sign * 1000.0 * (ca - cb);
      }
    }
  }
  return out;
}

const char* to_string(DispersionLaw law) {
  switch (law) {
    case DispersionLaw::None: return "none";
    case DispersionLaw::NavarroHerzberger: return "navarro-herzberger";
    case DispersionLaw::Cornu: return "cornu";
    case DispersionLaw::AbbeLinear: return "abbe-linear";
  }
  return "?";
}

}  // namespace eyetrace::optics
