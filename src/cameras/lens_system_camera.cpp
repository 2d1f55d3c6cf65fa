#include "cameras/lens_system_camera.h"

#include <cmath>

#include <fmt/format.h>

#include "cameras/chief_ray.h"
#include "cameras/eye_params.h"
#include "cameras/perspective_camera.h"
#include "cameras/symmetric_stand_in.h"
#include "core/error.h"
#include "optics/optics_error.h"

namespace eyetrace {

namespace {

// Relative widening of the pupil tables of a dispersive eye: they are traced at the reference
// wavelength, and the region through which rays pass moves with the wavelength (the lens
// between the sampling plane and the iris disperses). The dense containment test at 360 and
// 830 nm (PupilSampler.DispersiveEyeHoldsEveryWavelength) finds 120 of 1.18 million passing
// rays of Navarro's 5 mm pupil outside the unwidened tables at 360 nm, none with 1 %.
constexpr double kDispersiveMargin = 0.01;

// Largest clear semi-diameter of the system: the width of the meridian scans.
double largest_semi_diameter(const optics::Prescription& p) {
  double r = 0.0;
  for (const optics::Surface& s : p.surfaces)
    if (s.limited()) r = std::fmax(r, s.semi_diameter_mm);
  return r > 0.0 ? r : 10.0;
}

RetinaSurface retina_of(const optics::Prescription& p, const optics::CompiledSystem& system) {
  const optics::Surface& image = p.surfaces.back();
  if (!image.profile.is_flat() && image.profile.conic != 0.0)
    throw optics::OpticsError(
        fmt::format("the image surface '{}' is a conic (Q = {}); the camera supports "
                    "a sphere or a plane",
                    image.name, image.profile.conic));
  return {system.vertex_z(system.image_index()), image.profile.is_flat() ? 0.0 : image.profile.curvature};
}

// Largest retina arc whose point stays kMinPlaneGap_mm behind the sampling plane.
double arc_limit(const RetinaSurface& retina, double z_plane) {
  double limit = std::fmin(retina.max_arc_mm(), 200.0);
  if (retina.curvature < 0.0) {
    for (int i = 1; i <= 4096; ++i) {
      const double a = limit * i / 4096;
      if (retina.point(a).y - z_plane < kMinPlaneGap_mm) return limit * (i - 1) / 4096;
    }
  }
  return limit;
}

}  // namespace

LensSystemCamera::LensSystemCamera(const optics::Prescription& prescription, const Transform& world_from_camera,
                                   IVec2 resolution, const Settings& settings)
    : prescription_(prescription),
      system_(prescription),
      aiming_system_(aiming_prescription(prescription.rotationally_symmetric() ? prescription
                                                                               : symmetric_equivalent(prescription))),
      world_from_camera_(world_from_camera),
      resolution_(resolution),
      settings_(settings),
      dispersive_(settings.dispersive && system_.dispersive()) {
  // The tables below rotate one traced meridian to every azimuth. A system that is not
  // rotationally symmetric gets them from its symmetric stand-ins (symmetric_stand_in.h).
  const bool symmetric = prescription.rotationally_symmetric();
  if (!symmetric && settings.diffraction)
    throw optics::OpticsError("diffraction",
                              "the wave PSF table is traced along one meridian and needs a rotationally symmetric "
                              "eye; this one has a biconic, decentred or tilted surface or a phase plate");
  const optics::CompiledSystem equivalent(symmetric ? prescription : symmetric_equivalent(prescription));
  const optics::CompiledSystem envelope(symmetric ? prescription : pupil_envelope(prescription));
  const Vec4 w = default_screen_window(resolution);
  screen_window_ = glm::dvec4(w);
  screen_scale_ = {(screen_window_[1] - screen_window_[0]) / resolution.x,
                   (screen_window_[3] - screen_window_[2]) / resolution.y};
  inv_screen_scale_ = 1.0 / screen_scale_;
  const double corner = std::sqrt(double(w[1]) * w[1] + double(w[3]) * w[3]);  // screen radius of a corner
  retina_ = retina_of(prescription_, equivalent);
  z_plane_ = system_.vertex_z(system_.image_index() - 1);
  if (retina_.vertex_z_mm - z_plane_ < kMinPlaneGap_mm)
    throw optics::OpticsError(
        fmt::format("the image surface is only {:.4g} mm behind the last surface; the "
                    "camera needs at least {} mm",
                    retina_.vertex_z_mm - z_plane_, kMinPlaneGap_mm));
  const double max_arc = arc_limit(retina_, z_plane_);

  if (settings_.film_half_mm > 0.0) {
    mapping_ = RetinaMapping(settings_.film_half_mm, retina_);
  } else {
    const double half_fov = 0.5 * settings_.fov_deg;
    const double needed = settings_.mapping == FieldMapping::Angle ? corner * half_fov : half_fov;
    angles_ = FieldAngleTable(aiming_system_, retina_, z_plane_, needed, max_arc);
    try {
      mapping_ = RetinaMapping(settings_.mapping, half_fov, angles_, retina_);
    } catch (const optics::OpticsError& e) {
      throw FieldError(e.what());
    }
  }
  // The pupil tables reach the farthest pixel (an image corner), or as far as the mapping goes.
  double corner_arc = mapping_.arc_for_screen_radius(corner, angles_);
  if (!(corner_arc >= 0.0)) corner_arc = mapping_.kind() == FieldMapping::Angle ? angles_.max_arc_mm() : max_arc;
  PupilSampler::Options po = settings_.pupil;
  po.scan_half_width_mm = 1.5 * largest_semi_diameter(prescription_);
  if (dispersive_) po.relative_margin = std::fmax(po.relative_margin, kDispersiveMargin);
  pupil_ = PupilSampler(envelope, retina_, z_plane_, std::fmin(corner_arc, max_arc), angles_, po);
  retina_points_ = RetinaPointTable(retina_, pupil_.max_arc_mm());
  compute_normalisation(equivalent);
  if (settings_.diffraction) build_psf_table(std::fmin(corner_arc, pupil_.max_arc_mm()));
}

// The mean weight at the image centre is C times the integral of cos(theta_retina)
// cos(theta_plane) / d^2 over the passing disc of radius R on the plane at distance L, which is
// pi R^2 / (R^2 + L^2): the solid angle integral of cos(theta) over the passing cone.
// `system` is the camera's system or, when that is not rotationally symmetric, its symmetric
// equivalent: an eye exposes as the same eye without its astigmatism and decentrations.
void LensSystemCamera::compute_normalisation(const optics::CompiledSystem& system) {
  const glm::dvec3 vertex(0.0, 0.0, retina_.vertex_z_mm);
  if (!trace_towards_plane(system, vertex, 0.0, 0.0, z_plane_).ok())
    throw optics::OpticsError("no ray from the centre of the retina passes the system along the axis");
  double lo = 0.0, hi = 1.0;
  while (trace_towards_plane(system, vertex, hi, 0.0, z_plane_).ok() && hi < 1e6) lo = hi, hi *= 2.0;
  for (int i = 0; i < 100 && hi - lo > 1e-14 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (trace_towards_plane(system, vertex, mid, 0.0, z_plane_).ok() ? lo : hi) = mid;
  }
  const double radius = 0.5 * (lo + hi), length = retina_.vertex_z_mm - z_plane_;
  normalisation_ = (radius * radius + length * length) / (kPiDouble * radius * radius);
  // Bound: cos terms <= 1 and cos(theta_plane) / d^2 <= 1 / L^2 with L the retina point's
  // distance from the plane, smallest at the far end of an interval.
  const int n = 1024;
  for (int i = 0; i < n; ++i) {
    const double a0 = pupil_.max_arc_mm() * i / n, a1 = pupil_.max_arc_mm() * (i + 1) / n;
    const double area = std::fmax(pupil_.area(a0), pupil_.area(std::nextafter(a1, 0.0)));
    const double gap = std::fmin(retina_.point(a0).y, retina_.point(a1).y) - z_plane_;
    max_weight_ = std::fmax(max_weight_, normalisation_ * area / (gap * gap));
  }
}

glm::dvec2 LensSystemCamera::screen(Vec2 p) const {
  return {screen_window_[0] + double(p.x) * screen_scale_.x, screen_window_[3] - double(p.y) * screen_scale_.y};
}

std::optional<LensSystemCamera::RetinaPoint> LensSystemCamera::retina_point(Vec2 p_film) const {
  const glm::dvec2 s = screen(p_film);
  const double radius = std::sqrt(s.x * s.x + s.y * s.y);
  const double a = mapping_.arc_for_screen_radius(radius, angles_);
  if (!(a >= 0.0 && a <= pupil_.max_arc_mm())) return std::nullopt;
  // Upright image: screen direction (sx, sy) -> retina direction (sx, -sy) (see the header).
  const glm::dvec2 m = radius > 0.0 ? glm::dvec2(s.x, -s.y) / radius : glm::dvec2(1.0, 0.0);
  const glm::dvec2 p = retina_.point(a), n = retina_.normal(a);
  return RetinaPoint{{p.x * m.x, p.x * m.y, p.y}, {n.x * m.x, n.x * m.y, n.y}, a, m};
}

// The part of a camera sample before the lens trace: the retina point, the sampled point of the
// sampling plane and the ray between them. False when the pupil tables say no ray passes.
bool LensSystemCamera::start_ray(const CameraSample& cs, PendingRay* pending) const {
  const double sx = screen_window_[0] + double(cs.p_film.x) * screen_scale_.x;
  const double sy = screen_window_[3] - double(cs.p_film.y) * screen_scale_.y;
  const double radius = std::sqrt(sx * sx + sy * sy);
  const double a = mapping_.arc_for_screen_radius(radius, angles_);
  glm::dvec2 q;
  if (!pupil_.sample(a, cs.p_lens.x, cs.p_lens.y, &q, &pending->area)) return false;
  pending->arc = a;
  pending->screen_radius = radius;
  // Upright image: screen direction (sx, sy) -> retina direction (sx, -sy) (see the header).
  const double inv_radius = radius > 0.0 ? 1.0 / radius : 0.0;
  const glm::dvec2 m = radius > 0.0 ? glm::dvec2(sx * inv_radius, -sy * inv_radius) : glm::dvec2(1.0, 0.0);
  glm::dvec2 p;
  retina_points_.at(a, &p, &pending->normal);
  // Meridian frame: retina point (p.x, 0, p.y), plane point (q.x, q.y, z_plane).
  const glm::dvec3 d(q.x - p.x, q.y, z_plane_ - p.y);
  pending->d_local = d;
  pending->meridian = m;
  pending->ray = {{p.x * m.x, p.x * m.y, p.y}, {d.x * m.x - d.y * m.y, d.x * m.y + d.y * m.x, d.z}};
  return true;
}

// The part after the trace: the weight and the conversion to a world-space ray.
std::optional<CameraRay> LensSystemCamera::finish_ray(const CameraSample& cs, const PendingRay& pending,
                                                      const optics::TraceResult& r, double lambda_nm) const {
  if (!r.ok()) return std::nullopt;
  // weight = C cos(theta_retina) cos(theta_plane) / d^2 / density, density = 1 / area.
  const glm::dvec3& d_local = pending.d_local;
  const double d2 = glm::dot(d_local, d_local);
  const double inv_d = 1.0 / std::sqrt(d2);
  const double cos_retina = (d_local.x * pending.normal.x + d_local.z * pending.normal.y) * inv_d;
  if (!(cos_retina > 0.0)) return std::nullopt;  // would have to leave through the retina
  const double cos_plane = -d_local.z * inv_d;
  const double weight = normalisation_ * pending.area * cos_retina * cos_plane * (inv_d * inv_d);

  const double k = settings_.scene_units_per_mm;
  const glm::dvec3 dir = psf_table_ ? diffracted_direction(cs, pending, r, lambda_nm) : r.ray.direction;
  const Vec3 o(float(-r.ray.origin.x * k), float(r.ray.origin.y * k), float(-r.ray.origin.z * k));
  const Vec3 d(float(-dir.x), float(dir.y), float(-dir.z));
  const float w = static_cast<float>(weight);
  const float time = settings_.shutter.time(cs.time);
  Transform scratch;
  const Transform& world_from_camera = placed_at(motion_, world_from_camera_, time, scratch);
  return CameraRay{Ray{world_from_camera.point(o), glm::normalize(world_from_camera.vector(d)), kInfinity, time},
                   SampledSpectrum(w), w};
}

// The ray that left the eye, turned round to enter it again from 1 mm outside the cornea.
optics::Ray LensSystemCamera::back_in(const optics::TraceResult& left) {
  return {left.ray.origin + left.ray.direction, -left.ray.direction};
}

// As generate_rays for one sample (the batch trace equals the scalar one bit for bit), without
// the batch's arrays: tools and tests call it ray by ray.
std::optional<CameraRay> LensSystemCamera::generate_ray(const CameraSample& cs, SampledWavelengths& lambda) const {
  // Without the pixel's filter, or with diffraction (each wavelength's density of the ray would
  // be a convolution of its PSF over the pixels), the hero wavelength goes alone: the plain
  // estimator that spectral MIS only makes less noisy. So it does when the sample asks.
  if (hero_alone(cs)) lambda.terminate_secondary();
  PendingRay pending;
  if (!start_ray(cs, &pending)) return std::nullopt;
  const int first = system_.image_index() - 1;
  const optics::TraceResult hero = dispersive_ ? system_.trace_range(pending.ray, first, 0, double(lambda[0]))
                                               : system_.trace_range(pending.ray, first, 0);
  std::optional<CameraRay> ray = finish_ray(cs, pending, hero, double(lambda[0]));
  if (!ray || !dispersive_ || lambda.secondary_terminated()) return ray;
  optics::TraceResult forward[kSpectrumSamples - 1];
  for (int k = 1; k < kSpectrumSamples; ++k)
    forward[k - 1] = system_.trace_range(back_in(hero), 0, system_.image_index(), double(lambda[k]));
  weigh_wavelengths(cs, lambda, pending, forward, &*ray, nullptr);
  return ray;
}

void LensSystemCamera::generate_rays(const CameraSample* samples, SampledWavelengths* lambdas,
                                     std::optional<CameraRay>* rays, size_t count) const {
  trace_rays(samples, lambdas, rays, nullptr, count);
}

void LensSystemCamera::generate_rays_splatting(const CameraSample* samples, SampledWavelengths* lambdas,
                                               std::optional<CameraRay>* rays, SampleSplats* splats,
                                               size_t count) const {
  trace_rays(samples, lambdas, rays, splats, count);
}

// The batch trace overlaps the rays' latency chains. A dispersive eye traces the hero
// wavelength; with the pixel's filter known, the secondaries' rays are traced back in for
// spectral MIS, else they are terminated.
void LensSystemCamera::trace_rays(const CameraSample* samples, SampledWavelengths* lambdas,
                                  std::optional<CameraRay>* rays, SampleSplats* splats, size_t count) const {
  constexpr size_t kBatch = optics::kTraceBatchSize;
  constexpr int kSecondary = kSpectrumSamples - 1;
  PendingRay pending[kBatch];
  optics::Ray traced[kBatch];
  double lambda_nm[kBatch];
  optics::TraceResult results[kBatch];
  size_t index[kBatch];
  optics::Ray forward[kBatch * kSecondary];
  double forward_nm[kBatch * kSecondary];
  optics::TraceResult forward_results[kBatch * kSecondary];
  for (size_t base = 0; base < count; base += kBatch) {
    const size_t n = std::min(kBatch, count - base);
    size_t live = 0;
    for (size_t j = 0; j < n; ++j) {
      rays[base + j].reset();
      // A sample whose wavelengths are not weighed below splats nothing (no stale rows).
      if (splats)
        for (WavelengthSplat& w : splats[base + j].wavelength) w.nx = w.ny = 0;
      if (hero_alone(samples[base + j])) lambdas[base + j].terminate_secondary();
      // A renderer that traces wavelengths apart gives each film and pupil point once per
      // wavelength in a row: the ray's start (retina point, pupil point) is the previous one's.
      if (live > 0 && index[live - 1] == base + j - 1 && same_start(samples[base + j - 1], samples[base + j])) {
        pending[live] = pending[live - 1];
      } else if (!start_ray(samples[base + j], &pending[live])) {
        continue;
      }
      traced[live] = pending[live].ray;
      lambda_nm[live] = double(lambdas[base + j][0]);
      index[live++] = base + j;
    }
    system_.trace_range_batch(traced, dispersive_ ? lambda_nm : nullptr, results, live, system_.image_index() - 1, 0);
    size_t mis = 0;
    for (size_t j = 0; j < live; ++j) {
      rays[index[j]] = finish_ray(samples[index[j]], pending[j], results[j], lambda_nm[j]);
      if (!dispersive_ || !rays[index[j]] || lambdas[index[j]].secondary_terminated()) continue;
      for (int k = 1; k <= kSecondary; ++k) {
        forward[mis] = back_in(results[j]);
        forward_nm[mis++] = double(lambdas[index[j]][k]);
      }
    }
    system_.trace_range_batch(forward, forward_nm, forward_results, mis, 0, system_.image_index());
    mis = 0;
    for (size_t j = 0; j < live; ++j) {
      const size_t i = index[j];
      if (!dispersive_ || !rays[i] || lambdas[i].secondary_terminated()) continue;
      weigh_wavelengths(samples[i], lambdas[i], pending[j], forward_results + mis, &*rays[i],
                        splats ? splats + i : nullptr);
      mis += kSecondary;
    }
  }
}

std::string LensSystemCamera::to_string() const {
  const std::string field =
      settings_.film_half_mm > 0.0
          ? fmt::format("film {:.4g} mm (shorter half-axis)", settings_.film_half_mm)
          : fmt::format("fov {} deg, mapping {}", settings_.fov_deg, eyetrace::to_string(settings_.mapping));
  return fmt::format(
      "{} camera: {}{}, stop {:.4g} mm, {}, retina {}, {}{}", settings_.name, prescription_.name,
      prescription_.variant.empty() ? "" : " [" + prescription_.variant + "]", prescription_.stop_diameter_mm(), field,
      retina_.curvature == 0.0 ? std::string("flat") : fmt::format("radius {:.4g} mm", 1.0 / retina_.curvature),
      dispersive_ ? std::string("dispersive") : fmt::format("monochromatic {:.4g} nm", prescription_.wavelength_nm),
      psf_table_ ? ", diffraction: " + psf_table_->describe() : std::string());
}

}  // namespace eyetrace

namespace eyetrace {

namespace {

// Builds the camera, reporting what the system cannot serve against the parameter behind it.
std::unique_ptr<Camera> make_camera(const CameraContext& ctx, const optics::Prescription& p,
                                    const LensSystemCamera::Settings& s, const char* system_param) {
  try {
    auto camera = std::make_unique<LensSystemCamera>(p, ctx.world_from_camera, ctx.resolution, s);
    camera->set_motion(ctx.world_from_camera_motion);
    const WavePsfTable* table = camera->psf_table();
    if (table && table->geometric_nodes() > 0)
      warn(ctx.params.loc(),
           fmt::format("diffraction: {} of the {} wave PSFs (field x wavelength) are aberration-dominated or lose "
                       "their chief ray; rays there keep their traced direction (geometric blur){}",
                       table->geometric_nodes(), table->nodes(),
                       table->geometric_nodes() == table->nodes() ? ": diffraction changes nothing here" : ""));
    return camera;
  } catch (const FieldError& e) {
    ctx.params.fail("fov", e.what());
  } catch (const optics::OpticsError& e) {
    // An error naming an option (diffraction) belongs to that parameter.
    if (!e.option().empty()) ctx.params.fail(e.option(), e.message());
    ctx.params.fail(system_param, e.what());
  }
}

}  // namespace

std::unique_ptr<Camera> create_eye_camera(const CameraContext& ctx) { return create_named_eye_camera("eye")(ctx); }

CameraFactory create_named_eye_camera(std::string model) {
  return [model](const CameraContext& ctx) -> std::unique_ptr<Camera> {
    optics::Prescription p = eye_prescription_from_params(model, ctx.params, ctx.search_dir);
    LensSystemCamera::Settings s = eye_view_settings(model, ctx.params);
    return make_camera(ctx, p, s, model == "eye" ? "model" : "pupildiameter");
  };
}

std::unique_ptr<Camera> create_realistic_camera(const CameraContext& ctx) {
  if (ctx.params.has("diffraction"))
    ctx.params.fail("diffraction",
                    "the realistic camera has no wave PSF of its lens (only the eye models' are "
                    "precomputed); diffraction is a parameter of the eye cameras (Camera \"navarro\", "
                    "\"eye\", ...)");
  optics::Prescription p = realistic_prescription_from_params(ctx.params, ctx.search_dir);
  LensSystemCamera::Settings s = realistic_view_settings(ctx.params, ctx.resolution);
  return make_camera(ctx, p, s, "lensfile");
}

}  // namespace eyetrace
