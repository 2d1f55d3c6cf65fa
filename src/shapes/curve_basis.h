// The control points of pbrt-v4's "curve" shape turned into cubic Bezier segments, as pbrt-v4
// turns them: a degree-3 Bezier curve is 4 + 3 n points (segments share their end points), a
// degree-2 one 3 + 2 n points, each quadratic segment raised to the cubic with the same shape;
// a uniform B-spline of degree d has one segment per point beyond the first d, converted to
// Bezier form by blossoming. Also the evaluation of a cubic Bezier segment and its derivative.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/math.h"

namespace eyetrace {

using BezierSegment = std::array<Vec3, 4>;

enum class CurveBasis { Bezier, BSpline };

// The number of segments `points` control points make, or nothing when that count is not
// valid for the basis and degree (2 or 3).
std::optional<int> curve_segment_count(size_t points, CurveBasis basis, int degree);
// A message saying how many control points the basis and degree need.
std::string curve_point_count_rule(CurveBasis basis, int degree);

// The cubic Bezier segments of a valid control-point list (curve_segment_count says how many).
std::vector<BezierSegment> cubic_bezier_segments(const std::vector<Vec3>& points, CurveBasis basis, int degree);

// Point and derivative d/du of a cubic Bezier segment at u in [0, 1].
Vec3 bezier_point(const BezierSegment& cp, float u);
Vec3 bezier_derivative(const BezierSegment& cp, float u);

}  // namespace eyetrace
