// Where to aim rays from a retina point so they pass the iris: for every retina position the
// region of a sampling plane (z = z_plane, the vertex plane of the last surface in front of the
// retina) through which rays reach the scene, found by tracing at construction and stored as a
// star-shaped polygon around a centre. Rays are then drawn uniformly inside the polygon.
//
// The unit square reaches the polygon through (angle fraction t, radius fraction s): t picks a
// fan triangle by area and a point along its outer edge, s = the distance out from the centre.
// How (ux, uy) becomes (t, s) is the Options::mapping: "polar" takes t = ux, s = sqrt(uy), which
// squeezes the square's strata into slivers near the centre; "concentric" first maps the square
// to the unit disc by Shirley and Chiu's concentric map (strata stay compact, the map is
// continuous) and takes t = the disc point's angle / 2 pi, s = its radius. Both are uniform
// in the polygon.
//
// Layout: the retina arc [0, max_arc] is cut into intervals; each interval stores one polygon
// (radii along fixed directions) whose centre moves linearly between the interval's end nodes.
// The system is rotationally symmetric, so the tables live on the +x meridian (retina point
// (h, 0, z)) and the caller rotates the sampled point to the pixel's azimuth.
//
// Containment (the polygon must hold every passing ray, else the image darkens at the pupil
// edge): each interval's polygon covers the regions traced at both ends and the middle; at each
// of them the boundary between two traced directions is bounded by the convexity triangle of
// the neighbouring boundary chords, and the polygon is widened to hold it; the second
// difference of the three traced radii plus a small margin covers the change between them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "cameras/retina_mapping.h"
#include "cameras/retina_surface.h"
#include "optics/sequential_trace.h"

namespace eyetrace {

class PupilSampler {
 public:
  enum class Mapping { Polar, Concentric };
  struct Options {
    Mapping mapping = Mapping::Concentric;
    int intervals = 128;  // retina intervals over [0, max_arc]
    // Polygon vertices (a multiple of 4, at most 256). Rays drawn between the polygon and the
    // true region are lost, and that thin rim adds variance no stratification removes (about
    // lost fraction / spp in relMSE): 64 directions lose 1.3% of a 4 mm pupil's rays, 128 lose
    // 0.72% (256: 0.57%, the margins below being the rest) for 0.07 s more construction.
    int directions = 128;
    double relative_margin = 0.002;
    double absolute_margin_mm = 2e-4;
    double scan_half_width_mm = 10.0;  // meridian scan used when the chief ray is blocked
  };

  PupilSampler() = default;
  // chief (may be empty) gives starting points; max_arc_mm is the farthest retina arc needed.
  PupilSampler(const optics::CompiledSystem& system, const RetinaSurface& retina, double z_plane, double max_arc_mm,
               const FieldAngleTable& chief, const Options& options);

  double z_plane() const { return z_plane_; }
  double max_arc_mm() const { return max_arc_; }

  // Draws a point q of the sampling plane (meridian frame) uniformly in the region for the retina
  // point at arc a; area receives the region's area (the density is 1 / area). False when no ray
  // from there passes (or a is beyond the table).
  bool sample(double a, double ux, double uy, glm::dvec2* q, double* area) const {
    if (!(a >= 0.0 && a <= max_arc_)) return false;
    const double x = a * inv_step_;
    const int i = std::min(static_cast<int>(x), intervals_ - 1);
    const Region& r = regions_[static_cast<size_t>(i)];
    if (r.area <= 0.0) return false;
    const double t = x - i;
    const double cx = centres_[static_cast<size_t>(i)] +
                      t * (centres_[static_cast<size_t>(i) + 1] - centres_[static_cast<size_t>(i)]);
    double s = 0.0;
    if (mapping_ == Mapping::Concentric) {
      concentric(ux, uy, &ux, &s);
    } else {
      s = std::sqrt(uy);
    }
    // Pick a fan triangle by area, then a uniform point in it: with s uniform in area (s^2
    // uniform), the point c + s ((1 - v) V_j + v V_j+1) is uniform in the triangle (c, V_j, V_j+1).
    const float* cdf = &cdf_[static_cast<size_t>(i) * directions_];
    // Guide table: the first candidate triangle for this u, then a short linear search.
    const float uf = static_cast<float>(ux);
    int j = guide_[static_cast<size_t>(i) * kGuideSize + std::min(static_cast<int>(uf * kGuideSize), kGuideSize - 1)];
    // With 4 guide cells per triangle one step almost always suffices: taken without a branch.
    j += (j < directions_ - 1) & (cdf[j] <= uf);
    while (j < directions_ - 1 && cdf[j] <= uf) ++j;
    const double lo = j == 0 ? 0.0 : cdf[j - 1];
    const double v = std::clamp((ux - lo) * inv_width_[static_cast<size_t>(i) * directions_ + j], 0.0, 1.0);
    const int k = j + 1 == directions_ ? 0 : j + 1;
    const float* radii = &radii_[static_cast<size_t>(i) * directions_];
    const double w0 = s * (1.0 - v) * radii[j], w1 = s * v * radii[k];
    *q = {cx + w0 * cos_[j] + w1 * cos_[k], w0 * sin_[j] + w1 * sin_[k]};
    *area = r.area;
    return true;
  }

  // The region's area at arc a (0 when dark) and whether it contains q (the spectral MIS
  // weights ask whether a secondary wavelength's ray could have been sampled).
  double area(double a) const;
  bool contains(double a, glm::dvec2 q) const;
  // Centre of the region at arc a (meridian frame) and its polygon radius along direction j
  // (at angle 2 pi j / directions() from the meridian; 0 when dark).
  glm::dvec2 centre(double a) const;
  int directions() const { return directions_; }
  double polygon_radius(double a, int j) const;

 private:
  // Shirley and Chiu's concentric map of the unit square to the unit disc, returned as the
  // angle fraction t in [0, 1) and the radius r in [0, 1]. Uniform in, uniform in the disc out:
  // t and r^2 are then independent and uniform, as the fan mapping needs.
  static void concentric(double ux, double uy, double* t, double* r) {
    constexpr double kEighth = 0.125;  // pi / 4 as a fraction of a turn
    const double x = 2.0 * ux - 1.0, y = 2.0 * uy - 1.0;
    if (x == 0.0 && y == 0.0) {  // the centre: any angle
      *t = 0.0, *r = 0.0;
      return;
    }
    // Square ring |x| or |y| = r maps to the circle of radius r; the position along the ring
    // to the angle. A negative r is the opposite half-turn.
    double turn = 0.0;
    if (std::abs(x) > std::abs(y)) {
      *r = x, turn = kEighth * (y / x);
    } else {
      *r = y, turn = 2.0 * kEighth - kEighth * (x / y);
    }
    if (*r < 0.0) *r = -*r, turn += 0.5;
    if (turn < 0.0) turn += 1.0;
    // ux = 1 is outside the sampler's [0, 1) range, but rounding of turn may reach 1.
    *t = std::fmin(turn, std::nextafter(1.0, 0.0));
  }
  Mapping mapping_ = Mapping::Concentric;
  struct Region {
    double area = 0.0;  // 0 = dark: no ray from this interval passes
    // Squared radii of the largest circle inside the polygon (its nearest chord) and of the
    // smallest around it (its farthest vertex), shrunk and grown by a rounding margin: contains()
    // answers from them without finding the fan triangle for most points.
    double inner2 = 0.0, outer2 = 0.0;
  };
  void build_distribution(size_t interval);
  int sector_of(glm::dvec2 p) const;  // the fan triangle of p, relative to the region's centre
  double z_plane_ = 0.0;
  double max_arc_ = 0.0;
  double inv_step_ = 0.0;
  int intervals_ = 0;
  int directions_ = 0;
  std::vector<double> cos_, sin_;   // polygon directions
  std::vector<double> centres_;     // per node: x of the region centre (y = 0 by symmetry)
  std::vector<Region> regions_;     // per interval
  std::vector<float> radii_, cdf_;  // per interval x direction
  std::vector<float> inv_width_;    // 1 / (cdf[j] - cdf[j-1]), 0 for empty triangles
  static constexpr int kGuideSize = 256;
  std::vector<std::uint8_t> guide_;  // per interval x kGuideSize: first triangle whose cdf > g / size
};

}  // namespace eyetrace
