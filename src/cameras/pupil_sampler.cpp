#include "cameras/pupil_sampler.h"

#include <limits>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>

#include "cameras/chief_ray.h"
#include "core/constants.h"

namespace eyetrace {

namespace {

// Boundary search: bisection stops at this fraction of the radius (the returned radius is the
// outer end, so the tolerance only widens the polygon).
constexpr double kBoundaryTolerance = 1e-4;
constexpr int kScanSteps = 512;
// Sanity cap on the convexity widening (reached only by a degenerate, needle-like region).
constexpr double kMaxConvexityFactor = 4.0;

double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

// Traces the region boundary of one retina point. Construction only.
struct RegionTracer {
  const optics::CompiledSystem& system;
  double z_plane;
  double scan_half_width;
  const std::vector<double>& cos_dir;
  const std::vector<double>& sin_dir;

  int directions() const { return static_cast<int>(cos_dir.size()); }

  bool passes(const glm::dvec3& from, glm::dvec2 q) const {
    return trace_towards_plane(system, from, q.x, q.y, z_plane).ok();
  }

  // Largest distance from c along direction j at which rays still pass (outer end of the
  // bisection). From a passing centre the passing set along the line is an interval starting at
  // 0 (the region is convex up to the slight distortion of refraction); from a blocked centre
  // (only where the region shrinks to nothing) it is found by marching.
  double outer_radius(const glm::dvec3& from, glm::dvec2 c, int j, bool centre_passes, double hint) const {
    const glm::dvec2 dir(cos_dir[static_cast<size_t>(j)], sin_dir[static_cast<size_t>(j)]);
    double lo = 0.0, hi = std::fmax(hint, 1e-3);
    if (centre_passes) {
      for (int i = 0; i < 80 && passes(from, c + hi * dir); ++i) {
        lo = hi;
        hi *= 1.5;
      }
    } else {
      const double far = 2.0 * scan_half_width;
      int last = -1;
      for (int i = 1; i <= kScanSteps; ++i)
        if (passes(from, c + (far * i / kScanSteps) * dir)) last = i;
      if (last < 0) return 0.0;
      lo = far * last / kScanSteps;
      hi = far * (last + 1) / kScanSteps;
    }
    while (hi - lo > kBoundaryTolerance * hi) {
      const double mid = 0.5 * (lo + hi);
      (passes(from, c + mid * dir) ? lo : hi) = mid;
    }
    return hi;
  }

  // Boundary radii from centre (cx, 0) along every direction; the region is symmetric about the
  // meridian, so only the upper half is traced.
  std::vector<double> boundary(const glm::dvec3& from, double cx, double hint) const {
    const int n = directions();
    std::vector<double> r(static_cast<size_t>(n), 0.0);
    const glm::dvec2 c(cx, 0.0);
    const bool inside = passes(from, c);
    for (int j = 0; j <= n / 2; ++j) {
      r[static_cast<size_t>(j)] = outer_radius(from, c, j, inside, hint);
      if (r[static_cast<size_t>(j)] > 0.0) hint = r[static_cast<size_t>(j)];
    }
    for (int j = n / 2 + 1; j < n; ++j) r[static_cast<size_t>(j)] = r[static_cast<size_t>(n - j)];
    return r;
  }

  // A point of the meridian inside the region: the chief ray if it passes, else the middle of
  // the longest passing run of a scan along the meridian.
  std::optional<double> find_inside(const glm::dvec3& from, std::optional<double> chief_guess,
                                    double scan_centre) const {
    if (chief_guess) {
      const std::optional<double> q = aim_chief_ray(system, from, z_plane, *chief_guess);
      if (q && passes(from, {*q, 0.0})) return q;
    }
    int best_start = -1, best_len = 0, start = -1;
    for (int i = 0; i <= kScanSteps + 1; ++i) {
      const double x = scan_centre + scan_half_width * (2.0 * i / kScanSteps - 1.0);
      if (i <= kScanSteps && passes(from, {x, 0.0})) {
        if (start < 0) start = i;
      } else if (start >= 0) {
        if (i - start > best_len) best_start = start, best_len = i - start;
        start = -1;
      }
    }
    if (best_len == 0) return std::nullopt;
    const double mid = best_start + 0.5 * (best_len - 1);
    return scan_centre + scan_half_width * (2.0 * mid / kScanSteps - 1.0);
  }

  // Radii widened so the polygon holds the true boundary between traced directions: for a
  // convex region the boundary between vertices V_j and V_j+1 lies in the triangle formed by
  // their chord and the extensions of the neighbouring chords V_j-1 V_j and V_j+2 V_j+1.
  std::vector<double> widen_for_convexity(const std::vector<double>& r) const {
    const int n = directions();
    auto vertex = [&](int j) {
      const size_t k = static_cast<size_t>((j % n + n) % n);
      return r[k] * glm::dvec2(cos_dir[k], sin_dir[k]);
    };
    std::vector<double> factor(static_cast<size_t>(n), 1.0);  // per bin j: between j and j+1
    for (int j = 0; j < n; ++j) {
      if (r[static_cast<size_t>(j)] <= 0.0 || r[static_cast<size_t>((j + 1) % n)] <= 0.0) continue;
      factor[static_cast<size_t>(j)] = bin_factor(vertex(j - 1), vertex(j), vertex(j + 1), vertex(j + 2));
    }
    std::vector<double> out(r);
    for (int j = 0; j < n; ++j)
      out[static_cast<size_t>(j)] *=
          std::fmax(factor[static_cast<size_t>(j)], factor[static_cast<size_t>((j - 1 + n) % n)]);
    return out;
  }

  // Factor by which the chord b-c must grow (about the centre) to hold the part of the
  // convexity triangle (b, c, T) inside the wedge between the directions of b and c. Growth
  // is linear, f(x) = cross(x, c - b) / cross(b, c - b), so its maximum over that convex piece
  // lies at one of its corners: T itself, or where an edge towards T crosses a wedge ray.
  static double bin_factor(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d) {
    const glm::dvec2 chord = c - b;
    const double base = cross(b, chord);
    if (!(base > 0.0)) return 1.0;
    auto f = [&](glm::dvec2 x) { return cross(x, chord) / base; };
    // Edges leave b along e1 (continuing a -> b) and c along e2 (continuing d -> c).
    const glm::dvec2 e1 = b - a, e2 = c - d;
    const double den = cross(e1, e2);
    // Where the edges meet: b + s e1 = c + t e2. Parallel edges meet at infinity: a long
    // stretch stands in for it (the wedge clips it anyway).
    double s = 1e6, t = 1e6;
    if (std::abs(den) > 1e-12 * glm::length(e1) * glm::length(e2)) {
      s = cross(c - b, e2) / den;
      t = cross(c - b, e1) / den;
      if (s <= 0.0 || t <= 0.0) return 1.0;  // the edges turn inwards: locally not convex
    }
    double best = 1.0;
    const glm::dvec2 tip = b + s * e1;
    if (cross(b, tip) >= 0.0 && cross(tip, c) >= 0.0) best = std::fmax(best, f(tip));
    // Edge b -> tip against the ray through c, and edge c -> tip against the ray through b.
    auto cross_ray = [&](glm::dvec2 from, glm::dvec2 dir, double len, glm::dvec2 ray) {
      const double dd = cross(dir, ray);
      if (dd == 0.0) return;
      const double u = -cross(from, ray) / dd;  // from + u dir lies on the line of the ray
      if (u < 0.0 || u > len) return;
      const glm::dvec2 x = from + u * dir;
      if (glm::dot(x, ray) > 0.0) best = std::fmax(best, f(x));
    };
    cross_ray(b, e1, s, c);
    cross_ray(c, e2, t, b);
    return std::fmin(best, kMaxConvexityFactor);
  }
};

}  // namespace

namespace {

// The traced region at one retina position: a centre on the meridian and boundary radii.
struct Node {
  std::optional<double> centre;  // empty: no ray from here passes (as far as the search sees)
  double size = 1.0;             // half the meridian extent: a starting bracket for the search
  std::vector<double> radii;
};

std::vector<Node> trace_nodes(const RegionTracer& tracer, const RetinaSurface& retina, const FieldAngleTable& chief,
                              int count, double step) {
  std::vector<Node> nodes(static_cast<size_t>(count));
  std::optional<double> last_q;
  double scan_centre = 0.0, size = 1.0;
  for (int i = 0; i < count; ++i) {
    const double a = i * step;
    const glm::dvec2 p = retina.point(a);
    const glm::dvec3 from(p.x, 0.0, p.y);
    std::optional<double> guess = chief.chief_q_for_arc(a);
    if (!guess) guess = last_q ? last_q : std::optional<double>(0.0);
    const std::optional<double> inside = tracer.find_inside(from, guess, scan_centre);
    if (!inside) continue;
    last_q = inside;
    const double x_plus = tracer.outer_radius(from, {*inside, 0.0}, 0, true, size);
    const double x_minus = tracer.outer_radius(from, {*inside, 0.0}, tracer.directions() / 2, true, size);
    Node& n = nodes[static_cast<size_t>(i)];
    n.centre = *inside + 0.5 * (x_plus - x_minus);
    n.size = size = 0.5 * (x_plus + x_minus);
    n.radii = tracer.widen_for_convexity(tracer.boundary(from, *n.centre, n.size));
    scan_centre = *n.centre;
  }
  return nodes;
}

// Node centres, dark nodes taking their nearest lit neighbour's so a region growing out of
// darkness is traced from near where it appears.
std::vector<double> centres_of(const std::vector<Node>& nodes) {
  std::vector<double> c(nodes.size(), 0.0);
  for (size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].centre) {
      c[i] = *nodes[i].centre;
      continue;
    }
    for (size_t d = 1; d < nodes.size(); ++d) {
      if (i >= d && nodes[i - d].centre) {
        c[i] = *nodes[i - d].centre;
        break;
      }
      if (i + d < nodes.size() && nodes[i + d].centre) {
        c[i] = *nodes[i + d].centre;
        break;
      }
    }
  }
  return c;
}

}  // namespace

PupilSampler::PupilSampler(const optics::CompiledSystem& system, const RetinaSurface& retina, double z_plane,
                           double max_arc_mm, const FieldAngleTable& chief, const Options& o)
    : mapping_(o.mapping),
      z_plane_(z_plane),
      max_arc_(std::fmax(max_arc_mm, 1e-3)),
      intervals_(o.intervals),
      directions_(o.directions) {
  inv_step_ = intervals_ / max_arc_;
  for (int j = 0; j < directions_; ++j) {
    cos_.push_back(std::cos(kTwoPiDouble * j / directions_));
    sin_.push_back(std::sin(kTwoPiDouble * j / directions_));
  }
  const RegionTracer tracer{system, z_plane, o.scan_half_width_mm, cos_, sin_};
  const std::vector<Node> nodes = trace_nodes(tracer, retina, chief, intervals_ + 1, 1.0 / inv_step_);
  centres_ = centres_of(nodes);
  regions_.resize(static_cast<size_t>(intervals_));
  radii_.assign(static_cast<size_t>(intervals_ * directions_), 0.f);
  cdf_.assign(static_cast<size_t>(intervals_ * directions_), 0.f);
  guide_.assign(static_cast<size_t>(intervals_ * kGuideSize), 0);
  inv_width_.assign(static_cast<size_t>(intervals_ * directions_), 0.f);
  for (size_t i = 0; i < static_cast<size_t>(intervals_); ++i) {
    const Node &n0 = nodes[i], &n1 = nodes[i + 1];
    if (!n0.centre && !n1.centre) continue;  // dark at both ends: treated as dark
    const glm::dvec2 p = retina.point((i + 0.5) / inv_step_);
    const std::vector<double> mid = tracer.widen_for_convexity(
        tracer.boundary({p.x, 0.0, p.y}, 0.5 * (centres_[i] + centres_[i + 1]), n0.centre ? n0.size : n1.size));
    float* radii = &radii_[i * static_cast<size_t>(directions_)];
    for (size_t j = 0; j < static_cast<size_t>(directions_); ++j) {
      const double r0 = n0.centre ? n0.radii[j] : 0.0, r1 = n1.centre ? n1.radii[j] : 0.0;
      const double r = std::fmax(mid[j], std::fmax(r0, r1));
      if (r <= 0.0) continue;
      // Between the three traced positions the radius can bulge past all of them where it
      // changes nonlinearly (near the field edge, where vignetting closes the pupil); the
      // second difference bounds that bulge for a quadratic change (by a factor 4 at the
      // quarter points).
      const double bulge = std::abs(r0 + r1 - 2.0 * mid[j]);
      radii[j] =
          std::nextafter(static_cast<float>((r + bulge) * (1.0 + o.relative_margin) + o.absolute_margin_mm), 1e30f);
    }
    build_distribution(i);
  }
}

// Fan-triangle areas from the stored radii (so the density matches what is sampled), their
// cdf, its inverse widths and the guide table.
void PupilSampler::build_distribution(size_t i) {
  const size_t k = static_cast<size_t>(directions_);
  const float* radii = &radii_[i * k];
  float* cdf = &cdf_[i * k];
  const double sin_step = std::sin(kTwoPiDouble / directions_);
  double total = 0.0;
  for (int j = 0; j < directions_; ++j) {
    total += 0.5 * double(radii[j]) * double(radii[(j + 1) % directions_]) * sin_step;
    cdf[j] = static_cast<float>(total);
  }
  if (total <= 0.0) return;
  for (int j = 0; j < directions_; ++j) cdf[j] = static_cast<float>(cdf[j] / total);
  cdf[directions_ - 1] = 1.f;
  regions_[i].area = total;
  double inner = std::numeric_limits<double>::infinity(), outer = 0.0;
  for (int j = 0; j < directions_; ++j) {
    const int n = (j + 1) % directions_;
    const glm::dvec2 b = double(radii[j]) * glm::dvec2(cos_[size_t(j)], sin_[size_t(j)]);
    const glm::dvec2 c = double(radii[n]) * glm::dvec2(cos_[size_t(n)], sin_[size_t(n)]);
    const double chord = glm::length(c - b);
    inner = std::min(inner, chord > 0.0 ? std::abs(b.x * c.y - b.y * c.x) / chord : 0.0);
    outer = std::max(outer, double(radii[j]));
  }
  regions_[i].inner2 = inner * inner * (1.0 - 1e-9);
  regions_[i].outer2 = outer * outer * (1.0 + 1e-9);
  for (int j = 0; j < directions_; ++j) {
    const double width = double(cdf[j]) - (j == 0 ? 0.0 : double(cdf[j - 1]));
    inv_width_[i * k + static_cast<size_t>(j)] = width > 0.0 ? static_cast<float>(1.0 / width) : 0.f;
  }
  std::uint8_t* guide = &guide_[i * kGuideSize];
  for (int g = 0, j = 0; g < kGuideSize; ++g) {
    const float u = static_cast<float>(g) / kGuideSize;
    while (j < directions_ - 1 && cdf[j] <= u) ++j;
    guide[g] = static_cast<std::uint8_t>(j);
  }
}

double PupilSampler::area(double a) const {
  if (!(a >= 0.0 && a <= max_arc_)) return 0.0;
  return regions_[static_cast<size_t>(std::min(static_cast<int>(a * inv_step_), intervals_ - 1))].area;
}

glm::dvec2 PupilSampler::centre(double a) const {
  const double x = std::clamp(a, 0.0, max_arc_) * inv_step_;
  const int i = std::min(static_cast<int>(x), intervals_ - 1);
  const double t = x - i;
  const size_t k = static_cast<size_t>(i);
  return {centres_[k] + t * (centres_[k + 1] - centres_[k]), 0.0};
}

namespace {

// atan2 within 1e-5 rad (a minimax polynomial for atan on [0, 1]), in [0, 2 pi): a first guess
// of the sector, which cross products then settle exactly (std::atan2 was 3 % of a dispersive
// render, called three times per sample).
double rough_angle(glm::dvec2 p) {
  const double ax = std::abs(p.x), ay = std::abs(p.y);
  const double big = std::max(ax, ay);
  const double t = big > 0.0 ? std::min(ax, ay) / big : 0.0, t2 = t * t;
  double r = ((-0.0464964749 * t2 + 0.15931422) * t2 - 0.327622764) * t2 * t + t;
  if (ay > ax) r = 0.5 * std::numbers::pi - r;
  if (p.x < 0.0) r = std::numbers::pi - r;
  return p.y < 0.0 ? kTwoPiDouble - r : r;
}

}  // namespace

// The fan triangle whose cone, between directions j and j + 1, holds p (the sampler puts its
// points there as w0 dir_j + w1 dir_j+1, w >= 0). The guess is at most one sector off (the
// angle's error is far below a sector's width), and the cross products are the cones' own
// definition, so a point on a shared edge goes to one of its two triangles, both of which hold it.
int PupilSampler::sector_of(glm::dvec2 p) const {
  int j = std::min(static_cast<int>(rough_angle(p) / kTwoPiDouble * directions_), directions_ - 1);
  auto side = [&](int i) { return cos_[size_t(i)] * p.y - sin_[size_t(i)] * p.x; };  // > 0: p is past direction i
  if (side(j) < 0.0) return j == 0 ? directions_ - 1 : j - 1;
  const int k = j + 1 == directions_ ? 0 : j + 1;
  return side(k) > 0.0 ? k : j;
}

double PupilSampler::polygon_radius(double a, int j) const {
  if (area(a) <= 0.0 || j < 0 || j >= directions_) return 0.0;
  const int i = std::min(static_cast<int>(a * inv_step_), intervals_ - 1);
  return radii_[static_cast<size_t>(i * directions_ + j)];
}

bool PupilSampler::contains(double a, glm::dvec2 q) const {
  if (area(a) <= 0.0) return false;
  const int i = std::min(static_cast<int>(a * inv_step_), intervals_ - 1);
  const glm::dvec2 p = q - centre(a);
  const Region& region = regions_[size_t(i)];
  const double d2 = glm::dot(p, p);
  if (d2 < region.inner2) return true;
  if (d2 > region.outer2) return false;
  const int j = sector_of(p);
  const int k = (j + 1) % directions_;
  const float* radii = &radii_[static_cast<size_t>(i * directions_)];
  const glm::dvec2 b = double(radii[j]) * glm::dvec2(cos_[static_cast<size_t>(j)], sin_[static_cast<size_t>(j)]);
  const glm::dvec2 c = double(radii[k]) * glm::dvec2(cos_[static_cast<size_t>(k)], sin_[static_cast<size_t>(k)]);
  // Inside the fan triangle (0, b, c) iff p is on the origin's side of the chord b-c.
  return cross(c - b, p - b) >= 0.0;
}

}  // namespace eyetrace
