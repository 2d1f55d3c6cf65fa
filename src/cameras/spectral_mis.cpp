// Spectral MIS of the dispersive lens-system camera: one scene path serves all four wavelengths
// of a sample although the eye sends each wavelength its own way (docs/spectral.md).
//
// The hero wavelength's camera ray r was sampled as usual: a raster point s (pixel filter), the
// retina point x(s), a point q of the sampling plane, traced out of the eye. At a secondary
// wavelength k the same object-space ray r enters the eye and lands elsewhere: traced back in,
// it meets the sampling plane at q_k and the retina at x_k (raster point s_k). Every wavelength
// k is a sampling technique (the sample's wavelengths are a rotation-symmetric set, so each is
// the hero with probability 1/4) whose density of producing r, in the object-space measure of
// rays, is p_k = p_filter(s_k) / (area(x_k) n_k^2 G(x_k, q_k) J(s_k)): n_k the vitreous index,
// G = cos cos / d^2 between x_k and q_k, J the retina area per raster area; this follows from
// the etendue n^2 G dx dq of the ray pencil, which the eye conserves. The pixel measures at
// wavelength k the integral of f_P(s_k) C L_k / (n_k^2 J(s_k)) over rays (C the camera's
// normalisation). With balance-heuristic weights u_k / sum u (u_k = |f_P(s_k)| / (area n^2 G J),
// a density up to the filter's normalisation, which is the same for every k) the estimate of
// wavelength k, divided by what the film already multiplies (the hero's filter weight and the
// radiance), is
//     weight_k = 4 C sign(f_P(s_hero)) f_P(s_k) / (n_k^2 J(s_k) sum_j u_j),
// which is C area G (times 4, the hero's share of the set) when no secondary can produce r.
// Unbiased: for every ray the weights of the techniques that can produce it sum to 1 (u_k = 0
// where technique k cannot: outside the pixel's filter, outside the pupil region, or lost in
// the eye).
//
// With a box filter every wavelength can instead count in the pixel where it lands (a splat):
// every pixel samples its square uniformly, so the film as a whole samples the raster with one
// density and f = 1 for every technique. A wavelength is splatted only into a pixel of the
// sample's own tile (so each pixel is written by one thread); the techniques whose landing
// pixels lie in that tile share the weight (the balance heuristic over them: for a pair of
// wavelengths "both in one tile" is symmetric, so the weights of every ray still sum to 1).
// Each wavelength also reports its share of the sample, 4 u_k / sum u (CameraRay::share), by
// whose sums the film divides instead of the pixel's sample count (render/film.h, "Normalised
// splats").
//
// With a smooth filter (generate_rays_splatting) every wavelength k splats into every pixel P'
// of the sample's tile T whose filter reaches its landing point s_k, with the filter's value
// f_P'(s_k), as pbrt-v3 splatted whole samples. The techniques are then "a sample of any pixel
// P of T, hero wavelength j", and the balance heuristic over all of them uses
// u_j = D(s_j) / (area n^2 G J)_j with D(s) = sum over P in T of |filter_weight_P| pdf_P(s)
// integral f (the density, in the filter's units, with which the tile's samples put their hero
// at s). A pixel whose filter stays in the tile draws its film point uniformly in its square
// with filter weight 1 (its term: integral f over the square); a pixel on the tile's rim draws
// through the filter, pdf_P(s_0) = |f_P(s_0)| / (|filter_weight| integral f) (its term:
// |f_P(s)|), so that the tile's samples reach the points outside it that the rim's filters see
// (SplattingCamera::uniform_in_pixel, docs/spectral.md). The sample that was drawn, from pixel
// P, then gives pixel P' at wavelength k
//     |filter_weight| 4 C f_P'(s_k) L_k / (n_k^2 J(s_k) sum_j u_j):
// the weights of every ray sum to 1 over all (P, j) for every target pixel, and the sampler's
// own filter weight carries the difference between its tabulated density and |f| / integral f,
// so the estimate of every pixel is unbiased. On a sample whose four wavelengths land together
// this is the pbrt-v3 splat f_P'(s) / D(s) of the whole sample, without its colour noise.
#include <algorithm>
#include <cmath>

#include "cameras/lens_system_camera.h"
#include "core/splatting_camera.h"

namespace eyetrace {

namespace {

// floor and ceil for |v| < 2^31, by truncation: the baseline instruction set has no rounding
// instruction, and std::floor's stand-in for it covers the whole double range.
int floor_to_int(double v) {
  const int t = static_cast<int>(v);
  return t - static_cast<int>(v < static_cast<double>(t));
}
int ceil_to_int(double v) {
  const int t = static_cast<int>(v);
  return t + static_cast<int>(v > static_cast<double>(t));
}

}  // namespace

// The film's filter at the raster point of screen radius rho along the retina meridian m,
// relative to the centre of the sample's pixel; 0 outside the filter's support. A sample that
// may splat (constant filter) counts the point in whichever pixel of its tile holds it: offset
// receives that pixel's position relative to the sample's own.
double LensSystemCamera::filter_at(const CameraSample& cs, glm::dvec2 centre, double rho, glm::dvec2 m, IVec2* offset,
                                   WavelengthSplat* spread) const {
  // Upright image: retina direction (mx, my) is screen direction (mx, -my) (see the header).
  const double px = (rho * m.x - screen_window_[0]) * inv_screen_scale_.x;
  const double py = (screen_window_[3] + rho * m.y) * inv_screen_scale_.y;
  if (spread) return spread_at(cs, glm::dvec2(px, py), spread);
  if (cs.splat) {
    const IVec2 pixel(int(std::floor(px)), int(std::floor(py)));
    if (!(pixel.x >= cs.splat_lo.x && pixel.y >= cs.splat_lo.y && pixel.x < cs.splat_hi.x && pixel.y < cs.splat_hi.y))
      return 0.0;
    *offset = pixel - IVec2(int(std::floor(centre.x)), int(std::floor(centre.y)));
    return 1.0;
  }
  const Vec2 o(float(px - centre.x), float(py - centre.y)), r = cs.filter->radius();
  if (!(std::abs(o.x) <= r.x && std::abs(o.y) <= r.y)) return 0.0;
  return cs.filter->evaluate(o);
}

// A smooth filter's splat of a wavelength landing at raster point s: the pixels of the tile whose
// filter reaches s, the filter's one-dimensional factors there (Filter::evaluate_axis_row), and
// D(s), the density with which the tile's samples put a hero at s, in the filter's units: |f_P(s)|
// for each of those pixels P that draws through the filter, plus the filter's integral when the
// pixel whose square holds s draws uniformly (SplattingCamera::uniform_in_pixel); 0 when no
// pixel of the tile is reached.
double LensSystemCamera::spread_at(const CameraSample& cs, glm::dvec2 s, WavelengthSplat* spread) {
  const Filter& f = *cs.filter;
  const Vec2 r = f.radius();
  spread->nx = spread->ny = 0;
  // Far outside any raster (or NaN): nothing to reach, and the integer rounding below is safe.
  if (!(std::abs(s.x) < 1e9 && std::abs(s.y) < 1e9)) return 0.0;
  // Pixel x (centre x + 0.5) is reached when |s.x - x - 0.5| <= r.x.
  const int x0 = std::max(cs.splat_lo.x, ceil_to_int(s.x - 0.5 - r.x));
  const int x1 = std::min(cs.splat_hi.x - 1, floor_to_int(s.x - 0.5 + r.x));
  const int y0 = std::max(cs.splat_lo.y, ceil_to_int(s.y - 0.5 - r.y));
  const int y1 = std::min(cs.splat_hi.y - 1, floor_to_int(s.y - 0.5 + r.y));
  if (!(x1 >= x0 && y1 >= y0)) return 0.0;
  spread->first = IVec2(x0, y0);
  spread->nx = std::min(x1 - x0 + 1, WavelengthSplat::kMaxSpan);
  spread->ny = std::min(y1 - y0 + 1, WavelengthSplat::kMaxSpan);
  f.evaluate_axis_row(s.x - (x0 + 0.5), spread->nx, 0, spread->wx);
  f.evaluate_axis_row(s.y - (y0 + 0.5), spread->ny, 1, spread->wy);
  // A pixel draws uniformly when its filter stays in the tile along both axes (the inner
  // rectangle [in_lo, in_hi) of SplattingCamera::uniform_in_pixel), so the sum of |f| over the
  // pixels that draw through the filter is separable: all of them minus those inside.
  const IVec2 rim(SplattingCamera::rim(r.x), SplattingCamera::rim(r.y));
  const IVec2 in_lo = cs.splat_lo + rim, in_hi = cs.splat_hi - rim;
  double sx = 0.0, sy = 0.0, sx_in = 0.0, sy_in = 0.0;
  for (int i = 0; i < spread->nx; ++i) {
    const double a = std::abs(spread->wx[i]);
    sx += a;
    sx_in += x0 + i >= in_lo.x && x0 + i < in_hi.x ? a : 0.0;
  }
  for (int i = 0; i < spread->ny; ++i) {
    const double a = std::abs(spread->wy[i]);
    sy += a;
    sy_in += y0 + i >= in_lo.y && y0 + i < in_hi.y ? a : 0.0;
  }
  const IVec2 square(floor_to_int(s.x), floor_to_int(s.y));
  const bool uniform = square.x >= in_lo.x && square.x < in_hi.x && square.y >= in_lo.y && square.y < in_hi.y;
  const double d = (sx * sy - sx_in * sy_in) + (uniform ? double(f.integral()) : 0.0);
  if (!(d > 0.0)) spread->nx = spread->ny = 0;
  return d;
}

// 1 / (n^2 J), J the retina area per screen area at screen radius rho (arc a at height h,
// d arc / d rho = slope): the mapping is radial, so J = (d arc / d rho) (h / rho), which tends
// to slope^2 at the centre (dh / da = 1 there). The reciprocal, so that the weights multiply.
double LensSystemCamera::inverse_n2_jacobian(double n, double rho, double h, double slope) {
  return rho > 1e-12 ? rho / (n * n * slope * h) : 1.0 / (n * n * slope * slope);
}

LensSystemCamera::WavelengthTerms LensSystemCamera::hero_terms(const CameraSample& cs, const PendingRay& hero,
                                                               double lambda_nm, WavelengthSplat* spread) const {
  WavelengthTerms t;
  t.filter = spread     ? spread_at(cs, glm::dvec2(cs.p_film), spread)
             : cs.splat ? 1.0
                        : cs.filter->evaluate(cs.filter_offset);
  const double slope = mapping_.arc_slope(hero.screen_radius, angles_);
  const double n = system_.index_after(system_.image_index() - 1, lambda_nm);
  glm::dvec2 p, normal;
  retina_points_.at(hero.arc, &p, &normal);
  t.inv_n2_jacobian = inverse_n2_jacobian(n, hero.screen_radius, p.x, slope);
  const glm::dvec3& d = hero.d_local;
  const double d2 = glm::dot(d, d);
  // G = cos cos / d^2 = (d.normal) (-d.z) / d2^2, so u = |f| / (area n^2 J G) in one division.
  t.u = std::abs(t.filter) * (d2 * d2) * t.inv_n2_jacobian /
        (hero.area * (d.x * hero.normal.x + d.z * hero.normal.y) * -d.z);
  return t;
}

// A secondary wavelength: where the hero's ray, traced back in at this wavelength, meets the
// retina (the trace's end) and the sampling plane (its straight path in the vitreous).
LensSystemCamera::WavelengthTerms LensSystemCamera::secondary_terms(const CameraSample& cs, glm::dvec2 centre,
                                                                    const optics::TraceResult& forward,
                                                                    double lambda_nm, WavelengthSplat* spread) const {
  if (!forward.ok()) return {};
  const glm::dvec3& x = forward.ray.origin;
  const glm::dvec3& dir = forward.ray.direction;  // towards the retina (+z), unit (the trace's)
  const double h = std::sqrt(x.x * x.x + x.y * x.y);
  if (retina_.curvature != 0.0 && !(h * std::abs(retina_.curvature) < 1.0)) return {};
  const double a = retina_.arc_for_height(h);
  if (!(a <= pupil_.max_arc_mm()) || !(dir.z > 0.0)) return {};  // beyond the camera's retina
  // The meridian through x, by one division.
  const glm::dvec2 m = h > 0.0 ? glm::dvec2(x.x, x.y) * (1.0 / h) : glm::dvec2(1.0, 0.0);
  double slope = 0.0;
  const double rho = mapping_.screen_radius_for_arc(a, angles_, &slope);
  if (rho < 0.0) return {};
  WavelengthTerms t;
  t.filter = filter_at(cs, centre, rho, m, &t.offset, spread);
  if (t.filter == 0.0) return {};
  const double n = system_.index_after(system_.image_index() - 1, lambda_nm);
  glm::dvec2 p, nr;
  retina_points_.at(a, &p, &nr);
  t.inv_n2_jacobian = inverse_n2_jacobian(n, rho, p.x, slope);
  const double cos_retina = -(dir.x * nr.x * m.x + dir.y * nr.x * m.y + dir.z * nr.y);
  if (!(cos_retina > 0.0)) return t;  // seen, but not sampled at k (it would leave through the retina)
  // u = |f| / (area n^2 J G), G = cos_retina cos_plane / s^2 with cos_plane = dir.z; one
  // division gives both 1 / dir.z (for s) and u.
  const double rest = pupil_.area(a) * cos_retina;
  const double inv = 1.0 / (rest * dir.z);
  // Back along the ray to the plane: d = s dir with s < 0 (the plane is in front of the retina).
  const double s = (z_plane_ - x.z) * (inv * rest);
  const glm::dvec2 q = glm::dvec2(x.x, x.y) + s * glm::dvec2(dir.x, dir.y);
  const glm::dvec2 q_local(q.x * m.x + q.y * m.y, -q.x * m.y + q.y * m.x);  // meridian frame
  // Not finite where the pupil region has no area (no ray passes there): not sampled at k either.
  if (!std::isfinite(s) || !pupil_.contains(a, q_local)) return t;  // seen, but not sampled at k
  t.u = std::abs(t.filter) * (s * s) * inv * t.inv_n2_jacobian;
  return t;
}

void LensSystemCamera::weigh_wavelengths(const CameraSample& cs, SampledWavelengths& lambda, const PendingRay& hero,
                                         const optics::TraceResult* forward, CameraRay* out,
                                         SampleSplats* splats) const {
  // Splats with a smooth filter (see the top of the file); a box filter keeps its own splats.
  WavelengthSplat* spread = splats && cs.splat && !cs.filter->constant() ? splats->wavelength : nullptr;
  WavelengthTerms terms[kSpectrumSamples];
  terms[0] = hero_terms(cs, hero, lambda[0], spread);
  if (!(terms[0].u > 0.0 && std::isfinite(terms[0].u))) {
    // The hero alone, with its plain weight (never seen in tests); a splatting sample splats
    // nothing (a set of rays of measure zero: grazing at the retina or the sampling plane).
    lambda.terminate_secondary();
    if (spread)
      for (int k = 0; k < kSpectrumSamples; ++k) spread[k].nx = spread[k].ny = 0;
    return;
  }
  double sum_u = terms[0].u;
  // The pixel centre: p_film is centre + offset, rounded in float; the centre is on the grid.
  const glm::dvec2 centre(std::floor(double(cs.p_film.x) - double(cs.filter_offset.x)) + 0.5,
                          std::floor(double(cs.p_film.y) - double(cs.filter_offset.y)) + 0.5);
  for (int k = 1; k < kSpectrumSamples; ++k) {
    terms[k] = secondary_terms(cs, centre, forward[k - 1], lambda[k], spread ? spread + k : nullptr);
    sum_u += terms[k].u;
  }
  if (spread) {
    // Should the scene's path keep only the hero (a dispersive dielectric), the hero is the one
    // technique: C / (n^2 J u) without the factor 4, which the terminated hero's density brings.
    const double alone = normalisation_ * terms[0].inv_n2_jacobian / terms[0].u;
    out->hero_weight = std::isfinite(alone) ? static_cast<float>(alone) : 0.f;
    const double scale = kSpectrumSamples * normalisation_ / sum_u;
    for (int k = 0; k < kSpectrumSamples; ++k) {
      const double w = terms[k].filter == 0.0 ? 0.0 : scale * terms[k].inv_n2_jacobian;
      out->weight[k] = std::isfinite(w) ? static_cast<float>(w) : 0.f;
      if (out->weight[k] == 0.f) spread[k].nx = spread[k].ny = 0;
    }
    return;
  }
  const double scale = kSpectrumSamples * normalisation_ * (terms[0].filter < 0.0 ? -1.0 : 1.0) / sum_u;
  for (int k = 0; k < kSpectrumSamples; ++k) {
    const double w = terms[k].filter == 0.0 ? 0.0 : scale * terms[k].filter * terms[k].inv_n2_jacobian;
    out->weight[k] = std::isfinite(w) ? static_cast<float>(w) : 0.f;  // never NaN into the film
    out->pixel_offset[k] = terms[k].offset;
    out->share[k] = static_cast<float>(kSpectrumSamples * terms[k].u / sum_u);
  }
}

}  // namespace eyetrace
