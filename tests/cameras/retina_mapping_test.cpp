// Pixel -> retina mappings of the eye cameras, checked with an independent chief-ray search:
// the ray from a pixel's retina point through the centre of the stop leaves the eye at the
// pixel's field angle ("angle"), and "flat"/"retina" are linear in height/arc length.
#include "cameras/retina_mapping.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "cameras/lens_system_camera.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

constexpr double kDeg = kRadiansPerDegree;

std::unique_ptr<LensSystemCamera> camera(const std::string& params, int res) {
  SceneEntity e = parse_directive_text("Camera \"eye\" " + params, "Camera", "test");
  CameraContext ctx{e.params, Transform(), IVec2(res, res), ""};
  std::unique_ptr<Camera> c = create_eye_camera(ctx);
  return std::unique_ptr<LensSystemCamera>(dynamic_cast<LensSystemCamera*>(c.release()));
}

// Independent chief ray: the direction from the retina point, tilted by angle alpha from -z
// within its meridian plane, for which the ray crosses the stop plane on the axis; found by
// bisection on alpha (the camera aims by a different parameter, a plane point, with its own
// search). Traced with the stop opened to 9 mm so it never clips; returns the exit direction
// in camera space.
glm::dvec3 chief_ray_direction(const LensSystemCamera& cam, const LensSystemCamera::RetinaPoint& rp) {
  optics::Prescription p = cam.prescription();
  optics::set_stop_diameter(p, 9.0);
  const optics::CompiledSystem sys(p);
  const glm::dvec3 m(rp.meridian.x, rp.meridian.y, 0.0);
  auto dir = [&](double alpha) { return glm::dvec3(std::sin(alpha) * m.x, std::sin(alpha) * m.y, -std::cos(alpha)); };
  // Stop height of the ray at alpha (nullopt when lost before the stop).
  auto height = [&](double alpha) -> std::optional<double> {
    const optics::TraceResult r = sys.trace_range({rp.position, dir(alpha)}, sys.image_index() - 1, sys.stop_index());
    if (!r.ok()) return std::nullopt;
    return glm::dot(glm::dvec3(r.ray.origin.x, r.ray.origin.y, 0.0), m);
  };
  // Bracket: scan around the unrefracted direction to the stop centre for a sign change.
  const double rho = std::hypot(rp.position.x, rp.position.y);
  const double alpha0 = -std::atan2(rho, rp.position.z - sys.vertex_z(sys.stop_index()));
  double lo = 0.0, hi = 0.0;
  bool found = false;
  std::optional<double> prev;
  for (int i = 0; i <= 240 && !found; ++i) {
    const double alpha = alpha0 - 0.3 + 0.0025 * i;
    const std::optional<double> h = height(alpha);
    if (h && prev && (*prev < 0.0) != (*h < 0.0)) lo = alpha - 0.0025, hi = alpha, found = true;
    prev = h;
  }
  EXPECT_TRUE(found);
  const bool lo_negative = *height(lo) < 0.0;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    const std::optional<double> h = height(mid);
    if (!h) break;
    ((*h < 0.0) == lo_negative ? lo : hi) = mid;
  }
  const optics::TraceResult r = sys.trace_range({rp.position, dir(0.5 * (lo + hi))}, sys.image_index() - 1, 0);
  EXPECT_TRUE(r.ok());
  return {-r.ray.direction.x, r.ray.direction.y, -r.ray.direction.z};
}

// Every preset: the chief ray of the pixel at field angle theta leaves at theta (0.01 deg),
// in the pixel's azimuth (upright image).
TEST(RetinaMapping, AngleMappingChiefRayLeavesAtPixelFieldAngle) {
  const int res = 400;
  const double fov = 120.0;
  for (const char* model : {"navarro", "gullstrand", "legrand", "kooijman", "arizona", "escudero-sanz"}) {
    for (const char* extra : {"", "\"float accommodation\" 4"}) {
      if (std::string(model) == "kooijman" && *extra) continue;  // Kooijman has no accommodation
      auto cam = camera(fmt::format("\"string model\" \"{}\" \"float fov\" {} {}", model, fov, extra), res);
      for (double theta : {2.0, 15.0, 30.0, 45.0, 58.0})
        for (double azimuth : {0.0, 135.0, 250.0}) {
          const double s = theta / (0.5 * fov);
          const Vec2 p(float(0.5 * res * (1.0 + s * std::cos(azimuth * kDeg))),
                       float(0.5 * res * (1.0 - s * std::sin(azimuth * kDeg))));
          // The raster position is float: use its exact screen angle.
          const double sx = (p.x / (0.5 * res) - 1.0), sy = (1.0 - p.y / (0.5 * res));
          const double expected = std::hypot(sx, sy) * 0.5 * fov;
          const auto rp = cam->retina_point(p);
          ASSERT_TRUE(rp) << model << " " << theta;
          const glm::dvec3 d = chief_ray_direction(*cam, *rp);
          EXPECT_NEAR(std::acos(d.z) / kDeg, expected, 0.01) << model << extra << " theta " << theta;
          EXPECT_NEAR(std::atan2(d.y, d.x), std::atan2(sy, sx), 1e-9) << model << " azimuth " << azimuth;
        }
    }
  }
}

// "flat": lateral retina height linear in screen radius, and the chief ray at the edge of the
// shorter axis leaves at fov/2. "retina": the same for arc length.
TEST(RetinaMapping, FlatAndRetinaMappingsAreLinearWithFovAtTheEdge) {
  const int res = 200;
  for (const char* mapping : {"flat", "retina"}) {
    auto cam = camera(fmt::format("\"string mapping\" \"{}\" \"float fov\" 70", mapping), res);
    const auto edge = cam->retina_point(Vec2(float(res), 100.f));  // right edge, screen radius 1
    ASSERT_TRUE(edge);
    EXPECT_NEAR(std::acos(chief_ray_direction(*cam, *edge).z) / kDeg, 35.0, 0.01) << mapping;
    const double edge_value =
        std::string(mapping) == "flat" ? std::hypot(edge->position.x, edge->position.y) : edge->arc_mm;
    for (double s : {0.1, 0.4, 0.77, 1.3}) {
      const auto rp = cam->retina_point(Vec2(100.f, float(100.0 - 100.0 * s)));
      ASSERT_TRUE(rp);
      const double value = std::string(mapping) == "flat" ? std::hypot(rp->position.x, rp->position.y) : rp->arc_mm;
      EXPECT_NEAR(value, s * edge_value, 1e-5) << mapping << " " << s;
      // The point lies on the retina sphere (Navarro: radius 12 mm, vertex 24.004).
      const glm::dvec3 centre(0.0, 0.0, cam->retina().vertex_z_mm - 12.0);
      EXPECT_NEAR(glm::length(rp->position - centre), 12.0, 1e-9);
    }
  }
}

// A field of view the chief ray cannot reach cannot scale "flat"/"retina": a clear error
// naming "fov" (the "angle" mapping shows such pixels black instead).
// The inverse the spectral MIS uses (screen radius of a retina arc, and d arc / d radius) undoes
// the forward mapping, and its slope is the forward mapping's finite difference, for each kind;
// arc_slope (the slope without the inverse) gives the same slope.
TEST(RetinaMapping, InverseUndoesTheMappingAndGivesItsSlope) {
  auto cam = camera("\"string model\" \"navarro\" \"float fov\" 60 \"float wavelength\" 589.3", 64);
  const FieldAngleTable& table = cam->field_angles();
  for (FieldMapping kind : {FieldMapping::Angle, FieldMapping::Flat, FieldMapping::Retina}) {
    const RetinaMapping m(kind, 30.0, table, cam->retina());
    for (double s = 0.0; s <= 1.0; s += 0.0173) {
      const double a = m.arc_for_screen_radius(s, table);
      double slope = 0.0;
      EXPECT_NEAR(m.screen_radius_for_arc(a, table, &slope), s, 1e-12) << to_string(kind) << " s " << s;
      const double h = 1e-6, fd = (m.arc_for_screen_radius(s + h, table) - m.arc_for_screen_radius(s, table)) / h;
      EXPECT_NEAR(slope, fd, 1e-4 * fd) << to_string(kind) << " s " << s;
      EXPECT_NEAR(m.arc_slope(s, table), slope, 1e-12 * slope) << to_string(kind) << " s " << s;
    }
  }
}

// The table's inverse at every segment (its guide steps at most once): angle -> arc -> angle on
// a grid much finer than the table's (32 segments per degree), and the slope is the segment's.
TEST(RetinaMapping, FieldAngleInverseHoldsOnEverySegment) {
  auto cam = camera("\"string model\" \"navarro\" \"float fov\" 80 \"float wavelength\" 589.3", 64);
  const FieldAngleTable& table = cam->field_angles();
  int worst_steps = 0;
  for (double angle = 0.0; angle <= table.max_angle_deg(); angle += 0.0007) {
    const double a = table.arc_for_angle(angle);
    double slope = 0.0;
    ASSERT_NEAR(table.angle_for_arc(a, &slope), angle, 1e-10) << angle;
    const double fd = (table.arc_for_angle(angle + 1e-7) - a) / 1e-7;
    if (std::abs(slope - fd) > 1e-5 * fd) ++worst_steps;  // only where angle + 1e-7 crosses a node
  }
  EXPECT_LT(worst_steps, 5);
}

TEST(RetinaMapping, UnreachableFovIsAnErrorForFlatMapping) {
  SceneEntity e =
      parse_directive_text("Camera \"gullstrand\" \"string mapping\" \"flat\" \"float fov\" 179", "Camera", "t");
  CameraContext ctx{e.params, Transform(), IVec2(32, 32), ""};
  try {
    create_named_eye_camera("gullstrand")(ctx);  // its chief ray reaches 86 degrees
    FAIL() << "expected an error";
  } catch (const SceneError& err) {
    const std::string m = err.what();
    EXPECT_NE(m.find("\"fov\""), std::string::npos) << m;
    EXPECT_NE(m.find("chief ray"), std::string::npos) << m;
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
