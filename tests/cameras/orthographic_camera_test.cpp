// The orthographic camera against its analytic projection: parallel rays along the camera's +z
// from the screen window's points, pbrt-v4's thin lens (every ray of a film point through one
// point of the plane of focus, from the lens disc at the origin), the shutter, and the
// parameters' errors.
#include "cameras/orthographic_camera.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <random>

#include "core/error.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

Param number_param(const std::string& type, const std::string& name, std::vector<double> v) {
  Param p;
  p.type = type;
  p.name = name;
  p.numbers = std::move(v);
  p.loc = SourceLoc{"scene.pbrt", 2, 21};
  return p;
}

std::unique_ptr<Camera> make_camera(std::vector<Param> params, IVec2 res, const Transform& world_from_camera = {}) {
  ParameterList list(SourceLoc{"scene.pbrt", 2, 1});
  for (Param& p : params) list.add(std::move(p));
  return create_orthographic_camera(CameraContext{list, world_from_camera, res, "."});
}

// With a camera placed by LookAt, every ray has the camera's forward direction, and its origin
// is the screen-window point of its raster position, (x0 + (x1 - x0) px / W, y1 - (y1 - y0) py / H)
// on the camera's x and y axes.
TEST(OrthographicCamera, ParallelRaysFromTheScreenWindow) {
  const Vec3 eye(1, 2, 3), target(-1, 0.5, -2), up(0, 1, 0);
  const Transform world_from_camera = look_at(eye, target, up).inverse();
  const IVec2 res(40, 30);
  auto cam = make_camera({number_param("float", "screenwindow", {-2, 3, -1, 0.5})}, res, world_from_camera);
  const Vec3 forward = glm::normalize(target - eye);
  const Vec3 x_axis = world_from_camera.vector(Vec3(1, 0, 0)), y_axis = world_from_camera.vector(Vec3(0, 1, 0));
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  for (int i = 0; i < 200; ++i) {
    CameraSample cs;
    cs.p_film = Vec2(u(rng) * res.x, u(rng) * res.y);
    cs.p_lens = Vec2(u(rng), u(rng));  // no lens: ignored
    auto r = cam->generate_ray(cs);
    ASSERT_TRUE(r);
    EXPECT_NEAR(glm::length(r->ray.d - forward), 0.f, 1e-5f);
    const float sx = -2.f + 5.f * cs.p_film.x / res.x, sy = 0.5f - 1.5f * cs.p_film.y / res.y;
    const Vec3 expected = eye + sx * x_axis + sy * y_axis;
    EXPECT_NEAR(glm::length(r->ray.o - expected), 0.f, 2e-5f) << cs.p_film.x << " " << cs.p_film.y;
    EXPECT_EQ(r->weight[0], 1.f);
  }
}

// Without a screen window the shorter image axis spans [-1, 1] ("frameaspectratio" replaces the
// image's aspect); pbrt's LookAt puts world +x at the image's left.
TEST(OrthographicCamera, DefaultScreenWindowFromTheAspectRatio) {
  auto corner = [](const Camera& cam, Vec2 p) {
    CameraSample cs;
    cs.p_film = p;
    return cam.generate_ray(cs)->ray.o;
  };
  auto wide = make_camera({}, IVec2(64, 32));
  EXPECT_NEAR(glm::length(corner(*wide, Vec2(0, 0)) - Vec3(-2, 1, 0)), 0.f, 1e-6f);
  EXPECT_NEAR(glm::length(corner(*wide, Vec2(64, 32)) - Vec3(2, -1, 0)), 0.f, 1e-6f);
  auto tall = make_camera({}, IVec2(20, 40));
  EXPECT_NEAR(glm::length(corner(*tall, Vec2(0, 0)) - Vec3(-1, 2, 0)), 0.f, 1e-6f);
  auto framed = make_camera({number_param("float", "frameaspectratio", {0.5})}, IVec2(64, 64));
  EXPECT_NEAR(glm::length(corner(*framed, Vec2(64, 0)) - Vec3(1, 2, 0)), 0.f, 1e-6f);
  const Transform world_from_camera = look_at(Vec3(0, 0, 5), Vec3(0), Vec3(0, 1, 0)).inverse();
  auto placed = make_camera({}, IVec2(32, 32), world_from_camera);
  EXPECT_GT(corner(*placed, Vec2(0, 16)).x, 0.5f);
}

// pbrt-v4's thin lens: origins on the disc of radius lensradius about the camera's origin, and
// every ray of one film point through (sx, sy, focaldistance).
TEST(OrthographicCamera, ThinLensRaysOfAFilmPointMeetOnThePlaneOfFocus) {
  const IVec2 res(32, 32);
  auto cam = make_camera({number_param("float", "lensradius", {0.2}), number_param("float", "focaldistance", {4}),
                          number_param("float", "screenwindow", {-3, 1, -2, 2})},
                         res);
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  double max_radius = 0;
  for (int i = 0; i < 300; ++i) {
    CameraSample cs;
    cs.p_film = Vec2(u(rng) * res.x, u(rng) * res.y);
    cs.p_lens = Vec2(u(rng), u(rng));
    Ray r = cam->generate_ray(cs)->ray;
    EXPECT_EQ(r.o.z, 0.f);
    max_radius = std::max(max_radius, double(std::hypot(r.o.x, r.o.y)));
    EXPECT_LE(std::hypot(r.o.x, r.o.y), 0.2f * 1.0001f);
    EXPECT_NEAR(glm::length(r.d), 1.f, 1e-6f);
    const Vec3 at = r.at(4.f / r.d.z);
    EXPECT_NEAR(at.x, -3.f + 4.f * cs.p_film.x / res.x, 1e-4f);
    EXPECT_NEAR(at.y, 2.f - 4.f * cs.p_film.y / res.y, 1e-4f);
  }
  EXPECT_GT(max_radius, 0.18);  // the whole disc is used
}

TEST(OrthographicCamera, RayTimesSpanTheShutter) {
  auto cam = make_camera({number_param("float", "shutteropen", {0.5}), number_param("float", "shutterclose", {1.5})},
                         IVec2(8, 8));
  CameraSample cs;
  cs.p_film = Vec2(4.f);
  for (float u : {0.f, 0.25f, 0.9f}) {
    cs.time = u;
    EXPECT_FLOAT_EQ(cam->generate_ray(cs)->ray.time, 0.5f + u);
  }
}

TEST(OrthographicCamera, BadParametersAreErrorsNamingTheParameter) {
  for (auto& [param, name] : {std::pair{number_param("float", "screenwindow", {1, -1, -1, 1}), "screenwindow"},
                              std::pair{number_param("float", "screenwindow", {-1, 1, -1}), "screenwindow"},
                              std::pair{number_param("float", "lensradius", {-0.1}), "lensradius"},
                              std::pair{number_param("float", "focaldistance", {0}), "focaldistance"},
                              std::pair{number_param("float", "fov", {45}), "fov"}}) {
    try {
      make_camera({param}, IVec2(8, 8));
      ADD_FAILURE() << name << " accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("scene.pbrt:2:21"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
