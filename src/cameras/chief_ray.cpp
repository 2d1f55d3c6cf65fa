#include "cameras/chief_ray.h"

#include "optics/optics_error.h"

#include <cmath>

namespace eyetrace {

optics::Prescription with_extended_apertures(const optics::Prescription& p) {
  // Heights beyond this are never reached by an eye or camera lens; it keeps the searches finite.
  constexpr double kLargest = 50.0;
  optics::Prescription out = p;
  const std::vector<double> z = p.vertex_z_mm();
  const int n = static_cast<int>(p.surfaces.size());
  for (int i = 0; i + 1 < n; ++i) {
    const optics::Surface& s = p.surfaces[static_cast<size_t>(i)];
    if (s.role != optics::SurfaceRole::Refract || !s.limited()) continue;
    double h = std::fmin(s.profile.max_height(), kLargest);
    for (int j : {i - 1, i + 1}) {
      if (j < 0 || j >= n - 1) continue;  // the retina does not bound a lens
      const optics::Surface& t = p.surfaces[static_cast<size_t>(j)];
      const double reach =
          t.limited() && t.role == optics::SurfaceRole::Stop ? t.semi_diameter_mm : t.profile.max_height();
      const double probe = std::fmin(h, reach);
      const double meet = j < i ? optics::meeting_height(t.profile, z[static_cast<size_t>(j)], s.profile,
                                                         z[static_cast<size_t>(i)], probe)
                                : optics::meeting_height(s.profile, z[static_cast<size_t>(i)], t.profile,
                                                         z[static_cast<size_t>(j)], probe);
      if (meet < probe) h = std::fmin(h, meet);
    }
    out.surfaces[static_cast<size_t>(i)].semi_diameter_mm = std::fmax(h, s.semi_diameter_mm);
  }
  return out;
}

optics::TraceResult trace_towards_plane(const optics::CompiledSystem& system, const glm::dvec3& from, double q,
                                        double y, double z_plane, int last) {
  const optics::Ray ray{from, glm::dvec3(q, y, z_plane) - from};
  return system.trace_range(ray, system.image_index() - 1, last);
}

namespace {

// Height at which the ray towards q crosses the stop (nullopt when it is lost before it; the
// stop itself does not clip here, its opening is what we are aiming into).
std::optional<double> stop_height(const optics::CompiledSystem& system, const glm::dvec3& from, double q,
                                  double z_plane) {
  const int stop = system.stop_index();
  const optics::TraceResult r = trace_towards_plane(system, from, q, 0.0, z_plane, stop);
  if (r.ok()) return r.ray.origin.x;
  if (r.status == optics::TraceStatus::StopBlocked && r.surface == stop) {
    // Blocked by the stop: extend the ray to the stop plane ourselves.
    const double t = (system.vertex_z(stop) - r.ray.origin.z) / r.ray.direction.z;
    return r.ray.origin.x + t * r.ray.direction.x;
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> aim_chief_ray(const optics::CompiledSystem& system, const glm::dvec3& from, double z_plane,
                                    double q_guess) {
  // Bracket the root by stepping away from the guess (towards lower |g| first; the stop height
  // normally grows with q), then bisect: bisection cannot jump into a region where rays are
  // lost the way a secant step can.
  auto g = [&](double q) { return stop_height(system, from, q, z_plane); };
  const std::optional<double> g0 = g(q_guess);
  if (!g0) return std::nullopt;
  if (*g0 == 0.0) return q_guess;
  double a = q_guess, ga = *g0, b = 0.0;
  bool bracketed = false;
  for (double dir : {ga > 0.0 ? -1.0 : 1.0, ga > 0.0 ? 1.0 : -1.0}) {
    a = q_guess;
    ga = *g0;
    double step = std::fmax(1e-3, std::abs(ga));
    for (int i = 0; i < 60 && !bracketed; ++i) {
      b = a + dir * step;
      const std::optional<double> gb = g(b);
      if (!gb) {
        step *= 0.5;  // stepped into lost rays: approach more carefully
      } else if ((*gb > 0.0) != (ga > 0.0) || *gb == 0.0) {
        bracketed = true;
      } else {
        a = b;
        ga = *gb;
        step *= 2.0;
      }
    }
    if (bracketed) break;
  }
  if (!bracketed) return std::nullopt;
  const bool a_positive = ga > 0.0;
  for (int i = 0; i < 200 && std::abs(b - a) > 1e-13 * (1.0 + std::abs(a)); ++i) {
    const double mid = 0.5 * (a + b);
    const std::optional<double> gm = g(mid);
    if (!gm) return std::nullopt;
    if (*gm == 0.0) return mid;
    ((*gm > 0.0) == a_positive ? a : b) = mid;
  }
  return 0.5 * (a + b);
}

optics::Prescription aiming_prescription(const optics::Prescription& p) {
  try {
    optics::Prescription opened = with_extended_apertures(p);
    optics::validate(opened);
    return opened;
  } catch (const optics::OpticsError&) {
    return p;
  }
}

}  // namespace eyetrace
