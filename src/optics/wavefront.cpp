// Wavefront aberration by real-ray trace to the exit-pupil reference sphere (see wavefront.h).
#include "optics/wavefront.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include <fmt/format.h>

#include "optics/chromatic.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/sequential_trace.h"
#include "optics/zernike.h"

namespace eyetrace::optics {

namespace {

constexpr double kOpenStop_mm = 1e3;

// One ray's optical path from the object's reference surface (the plane through the chief ray's
// start perpendicular to the beam for an object at infinity, the source itself otherwise) to
// the last refracting surface, and the ray there.
struct Path {
  bool ok = false;
  glm::dvec3 last_point{0.0};  // on the last surface before the image
  glm::dvec3 direction{0.0};   // in image space
  glm::dvec3 image_point{0.0};
  double length = 0.0;  // optical path to last_point, mm
};

struct PathTracer {
  const CompiledSystem& sys;
  bool at_infinity;
  glm::dvec3 reference;  // chief ray's start (infinity) or the source
  mutable std::vector<glm::dvec3> points;

  Path trace(const Ray& ray) const {
    points.resize(static_cast<size_t>(sys.surface_count()));
    const TraceResult t = sys.trace_range(ray, 0, sys.image_index(), points.data());
    Path out;
    if (!t.ok() || t.surface != sys.image_index()) return out;
    const int last = sys.image_index() - 1;
    out.length = sys.index_before(0) *
                 (at_infinity ? glm::dot(points[0] - reference, ray.direction) : glm::distance(points[0], reference));
    for (int i = 0; i < last; ++i) out.length += sys.index_after(i) * glm::distance(points[i + 1], points[i]);
    // A phase plate (the measured wavefront of an eye) adds its path where the ray crosses it.
    if (!sys.rotationally_symmetric())
      for (int i = 0; i <= last; ++i) out.length += sys.plate_path_mm(i, points[i]);
    out.last_point = points[last];
    out.direction = t.ray.direction;
    out.image_point = t.ray.origin;
    out.ok = std::isfinite(out.length);
    return out;
  }
};

// Ray parameter (from last_point, along direction) where the image-space line meets the sphere
// |Q - centre| = radius. Of the two crossings the one nearer the pupil (smaller t) is taken: the
// ray converges on the image near the centre, so the other lies beyond the image. NaN when the
// line misses the sphere (a ray farther from the image point than the sphere's radius).
double sphere_crossing(const Path& path, const glm::dvec3& centre, double radius) {
  const glm::dvec3 oc = path.last_point - centre;
  const double b = glm::dot(oc, path.direction);
  const double c = glm::dot(oc, oc) - radius * radius;
  const double disc = b * b - c;
  if (!(disc >= 0.0)) return std::nan("");
  return -b - std::sqrt(disc);
}

// The object point's rays: through (x, y) on the entrance-pupil plane z_pupil, started on the
// chief ray's launch plane (in front of the first surface).
struct WavefrontLauncher {
  bool at_infinity;
  glm::dvec3 direction;  // beam direction (infinity)
  glm::dvec3 source;     // finite object
  double z_pupil, z_start;

  Ray ray(double x, double y) const {
    const glm::dvec3 target(x, y, z_pupil);
    Ray r;
    r.direction = at_infinity ? direction : glm::normalize(target - source);
    r.origin = target - (z_pupil - z_start) / r.direction.z * r.direction;
    return r;
  }
};

struct Samples {
  std::vector<glm::dvec2> points;  // normalised, OSA axes
  std::vector<double> opd_mm;
  int in_pupil = 0, lost = 0;
};

// OPD over the grid cells of the disc, relative to the chief ray (whose OPD is 0 by construction).
Samples sample_pupil(const PathTracer& tracer, const WavefrontLauncher& launch, const WavefrontResult& geo,
                     double chief_length, double n_image, int grid) {
  Samples s;
  const double r = geo.pupil_radius_mm;
  for (int i = 0; i < grid; ++i)
    for (int j = 0; j < grid; ++j) {
      const glm::dvec2 u(-1.0 + (i + 0.5) * 2.0 / grid, -1.0 + (j + 0.5) * 2.0 / grid);
      if (glm::dot(u, u) > 1.0) continue;
      ++s.in_pupil;
      const Path path = tracer.trace(launch.ray(geo.pupil_centre_mm.x + r * u.x, geo.pupil_centre_mm.y + r * u.y));
      const double t = path.ok ? sphere_crossing(path, geo.image_point_mm, geo.reference_radius_mm) : std::nan("");
      const double opd = chief_length - (path.length + n_image * t);
      if (!std::isfinite(opd)) {
        ++s.lost;
        continue;
      }
      s.points.emplace_back(-u.x, u.y);  // prescription x -> OSA x (see wavefront.h)
      s.opd_mm.push_back(opd);
    }
  return s;
}

// The stop opened wider than any other aperture could pass (the disc is then the pupil). Its
// position, and so the chief ray and the pupils, are unchanged.
Prescription without_stop_clipping(Prescription p) {
  p.surfaces[p.stop_index()].semi_diameter_mm = kOpenStop_mm;
  return p;
}

void summarise(const Samples& s, double wave_mm, WavefrontResult& out) {
  double mean = 0.0;
  for (double w : s.opd_mm) mean += w;
  mean /= static_cast<double>(s.opd_mm.size());
  double sum2 = 0.0, lo = 1e300, hi = -1e300;
  out.opd_waves.reserve(s.opd_mm.size());
  for (double w : s.opd_mm) {
    sum2 += (w - mean) * (w - mean);
    lo = std::min(lo, w), hi = std::max(hi, w);
    out.opd_waves.push_back(w / wave_mm);
  }
  out.rms_sampled_waves = std::sqrt(sum2 / static_cast<double>(s.opd_mm.size())) / wave_mm;
  out.pv_waves = (hi - lo) / wave_mm;
}

}  // namespace

void validate(const WavefrontOptions& o) {
  if (!(std::abs(o.field_deg) < 85.0))
    throw OpticsError(fmt::format("wavefront: field {} deg must be within (-85, 85) deg", o.field_deg));
  if (!(o.object_distance_m > 0.0))
    throw OpticsError(fmt::format("wavefront: object distance {} m must be positive", o.object_distance_m));
  if (!(o.wavelength_nm == 0.0 || (o.wavelength_nm >= kMinWavelength_nm && o.wavelength_nm <= kMaxWavelength_nm)))
    throw OpticsError(fmt::format("wavefront: wavelength {} nm is outside [{}, {}] nm", o.wavelength_nm,
                                  kMinWavelength_nm, kMaxWavelength_nm));
  if (!(o.pupil_radius_mm >= 0.0 && o.pupil_radius_mm <= 50.0))
    throw OpticsError(
        fmt::format("wavefront: pupil radius {} mm must be in [0, 50] (0 = paraxial)", o.pupil_radius_mm));
  if (o.grid < 8 || o.grid > 1024) throw OpticsError(fmt::format("wavefront: grid {} must be in [8, 1024]", o.grid));
  if (o.zernike_order < 2 || o.zernike_order > 12)
    throw OpticsError(fmt::format("wavefront: Zernike order {} must be in [2, 12]", o.zernike_order));
}

WavefrontResult trace_wavefront(const Prescription& p, const WavefrontOptions& o) {
  validate(o);
  const double lambda = o.wavelength_nm == 0.0 ? p.wavelength_nm : o.wavelength_nm;
  const Prescription p_lambda = lambda == p.wavelength_nm ? p : at_wavelength(p, lambda);
  // Pupil geometry (plane, default radius, the finite object's position) from the prescription
  // at its own wavelength, so that every wavelength is analysed over the same pupil and point.
  const ParaxialData object_para = paraxial_analysis(p);
  const ParaxialData image_para = paraxial_analysis(p_lambda);

  const ChiefRay chief = trace_chief_ray(p_lambda, o.field_deg, o.object_distance_m, &p);
  if (!chief.ok) throw OpticsError(fmt::format("wavefront: field {} deg: chief ray lost: {}", o.field_deg, chief.lost));

  WavefrontResult out;
  out.field_deg = o.field_deg;
  out.wavelength_nm = lambda;
  out.zernike_order = o.zernike_order;
  out.grid = o.grid;
  out.pupil_radius_mm = o.pupil_radius_mm > 0.0 ? o.pupil_radius_mm : 0.5 * object_para.entrance_pupil.diameter_mm;
  out.entrance_pupil_z_mm = object_para.entrance_pupil.position_mm;
  out.exit_pupil_z_mm = image_para.exit_pupil.position_mm;

  const double theta = o.field_deg * std::numbers::pi / 180.0;
  const glm::dvec3 beam(0.0, -std::sin(theta), std::cos(theta));  // as trace_chief_ray
  const bool at_infinity = std::isinf(o.object_distance_m);
  const glm::dvec3 source = glm::dvec3(0.0, 0.0, out.entrance_pupil_z_mm) - o.object_distance_m * 1000.0 * beam;
  const Ray& c = chief.object_ray;
  const WavefrontLauncher launch{at_infinity, beam, source, out.entrance_pupil_z_mm, c.origin.z};
  out.pupil_centre_mm = glm::dvec2(c.origin + (out.entrance_pupil_z_mm - c.origin.z) / c.direction.z * c.direction);

  const CompiledSystem sys(o.clip_at_stop ? p_lambda : without_stop_clipping(p_lambda));
  const PathTracer tracer{sys, at_infinity, at_infinity ? c.origin : source, {}};
  const Path chief_path = tracer.trace(c);
  if (!chief_path.ok) throw OpticsError(fmt::format("wavefront: field {} deg: chief ray lost", o.field_deg));
  // The reference sphere: centre on the chief ray's image point, through the chief ray's
  // crossing of the exit-pupil plane (a parameter s_pupil, usually negative: behind the lens).
  const double n_image = sys.index_after(sys.image_index() - 1);
  const double s_pupil = (out.exit_pupil_z_mm - chief_path.last_point.z) / chief_path.direction.z;
  out.image_point_mm = chief_path.image_point;
  out.reference_radius_mm = glm::distance(chief_path.last_point + s_pupil * chief_path.direction, out.image_point_mm);
  const double chief_length = chief_path.length + n_image * s_pupil;

  const Samples s = sample_pupil(tracer, launch, out, chief_length, n_image, o.grid);
  out.rays_in_pupil = s.in_pupil;
  out.rays_lost = s.lost;
  const int terms = zernike_term_count(o.zernike_order);
  if (static_cast<int>(s.opd_mm.size()) < std::max(terms, 3))
    throw OpticsError(
        fmt::format("wavefront: field {} deg: only {} of {} rays of the {} mm pupil reach the image, "
                    "{} needed for order {}",
                    o.field_deg, s.opd_mm.size(), s.in_pupil, 2.0 * out.pupil_radius_mm, terms, o.zernike_order));
  if (s.lost > 0)
    out.warning = fmt::format(
        "{} of {} rays of the {:.3f} mm pupil do not reach the image (vignetted): the "
        "wavefront and its Zernike fit cover the rest only",
        s.lost, s.in_pupil, 2.0 * out.pupil_radius_mm);
  const double wave_mm = lambda * 1e-6;
  out.pupil_points = s.points;
  summarise(s, wave_mm, out);

  if (!o.fit_zernike) return out;
  std::vector<double> opd_um(s.opd_mm.size());
  for (size_t i = 0; i < opd_um.size(); ++i) opd_um[i] = s.opd_mm[i] * 1000.0;
  const ZernikeFit fit = fit_zernike(s.points, opd_um, o.zernike_order);
  out.zernike_um = fit.coefficients;
  out.fit_residual_waves = fit.residual_rms / 1000.0 / wave_mm;
  double sum2 = 0.0;
  for (size_t j = 1; j < fit.coefficients.size(); ++j) sum2 += fit.coefficients[j] * fit.coefficients[j];
  out.rms_waves = std::sqrt(sum2) / 1000.0 / wave_mm;
  out.least_squares = least_squares_refraction(fit.coefficients, out.pupil_radius_mm);
  out.paraxial = paraxial_refraction(fit.coefficients, out.pupil_radius_mm);
  return out;
}

}  // namespace eyetrace::optics
