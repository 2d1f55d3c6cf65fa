#include "shapes/curve_basis.h"

#include <fmt/format.h>

#include "core/lerp.h"

namespace eyetrace {

namespace {

// Degree elevation: the cubic whose control points are these is the quadratic (q0, q1, q2).
BezierSegment elevate_quadratic(const Vec3& q0, const Vec3& q1, const Vec3& q2) {
  return {q0, lerp(2.f / 3.f, q0, q1), lerp(1.f / 3.f, q1, q2), q2};
}

// Uniform quadratic B-spline segment (p01, p12, p23 in blossom labels) to Bezier p11 p12 p22.
BezierSegment quadratic_bspline_segment(const Vec3* p) {
  return elevate_quadratic(lerp(0.5f, p[0], p[1]), p[1], lerp(0.5f, p[1], p[2]));
}

// Uniform cubic B-spline segment (p012 p123 p234 p345) to Bezier p222 p223 p233 p333.
BezierSegment cubic_bspline_segment(const Vec3* p) {
  const Vec3 p122 = lerp(2.f / 3.f, p[0], p[1]), p223 = lerp(1.f / 3.f, p[1], p[2]);
  const Vec3 p233 = lerp(2.f / 3.f, p[1], p[2]), p334 = lerp(1.f / 3.f, p[2], p[3]);
  return {lerp(0.5f, p122, p223), p223, p233, lerp(0.5f, p233, p334)};
}

}  // namespace

std::optional<int> curve_segment_count(size_t points, CurveBasis basis, int degree) {
  if (degree != 2 && degree != 3) return std::nullopt;
  const size_t d = size_t(degree);
  if (points < d + 1) return std::nullopt;
  if (basis == CurveBasis::BSpline) return int(points - d);
  // Bezier: the first segment takes degree + 1 points, each further one `degree` more.
  if ((points - 1) % d != 0) return std::nullopt;
  return int((points - 1) / d);
}

std::string curve_point_count_rule(CurveBasis basis, int degree) {
  if (basis == CurveBasis::BSpline)
    return fmt::format("a degree-{} B-spline needs at least {} control points", degree, degree + 1);
  return fmt::format("a degree-{} Bezier curve needs {} + {} n control points (n >= 0)", degree, degree + 1, degree);
}

std::vector<BezierSegment> cubic_bezier_segments(const std::vector<Vec3>& points, CurveBasis basis, int degree) {
  const int n = curve_segment_count(points.size(), basis, degree).value();
  std::vector<BezierSegment> segments;
  segments.reserve(size_t(n));
  for (int s = 0; s < n; ++s) {
    if (basis == CurveBasis::BSpline) {
      const Vec3* p = &points[size_t(s)];
      segments.push_back(degree == 2 ? quadratic_bspline_segment(p) : cubic_bspline_segment(p));
    } else {
      const Vec3* p = &points[size_t(s * degree)];
      segments.push_back(degree == 2 ? elevate_quadratic(p[0], p[1], p[2]) : BezierSegment{p[0], p[1], p[2], p[3]});
    }
  }
  return segments;
}

Vec3 bezier_point(const BezierSegment& cp, float u) {
  // de Casteljau: convex combinations only, stable for any u in [0, 1].
  const Vec3 a = lerp(u, cp[0], cp[1]), b = lerp(u, cp[1], cp[2]), c = lerp(u, cp[2], cp[3]);
  return lerp(u, lerp(u, a, b), lerp(u, b, c));
}

Vec3 bezier_derivative(const BezierSegment& cp, float u) {
  const Vec3 a = lerp(u, cp[0], cp[1]), b = lerp(u, cp[1], cp[2]), c = lerp(u, cp[2], cp[3]);
  return 3.f * (lerp(u, b, c) - lerp(u, a, b));
}

}  // namespace eyetrace
