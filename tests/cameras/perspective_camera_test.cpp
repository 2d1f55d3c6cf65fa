// Pinhole and thin-lens cameras against analytic projections.
#include "cameras/perspective_camera.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <random>
#include <tuple>

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// World point hit by the ray through a pixel centre, on the plane z = depth in front of a
// camera at the origin looking down +z; compared with the analytic perspective projection.
TEST(PerspectiveCamera, PixelCentreRaysHitAnalyticPoints) {
  IVec2 res(64, 48);
  PerspectiveCamera::Settings s;
  s.fov_deg = 60.f;
  PerspectiveCamera cam(Transform(), res, s);
  float aspect = 64.f / 48.f, t = std::tan(radians(30.f)), depth = 10.f;
  for (int y = 0; y < res.y; y += 7)
    for (int x = 0; x < res.x; x += 5) {
      CameraSample cs;
      cs.p_film = Vec2(x + 0.5f, y + 0.5f);
      auto r = cam.generate_ray(cs);
      ASSERT_TRUE(r);
      Vec3 hit = r->ray.at(depth / r->ray.d.z);
      // The shorter (vertical) axis spans the fov; raster y grows downwards.
      float ex = ((x + 0.5f) / res.x * 2.f - 1.f) * aspect * t * depth;
      float ey = (1.f - (y + 0.5f) / res.y * 2.f) * t * depth;
      EXPECT_NEAR(hit.x, ex, 1e-4f);
      EXPECT_NEAR(hit.y, ey, 1e-4f);
      EXPECT_NEAR(glm::length(r->ray.d), 1.f, 1e-6f);
      EXPECT_EQ(r->weight[0], 1.f);
    }
}

// pbrt's LookAt: a camera at (0,0,-5) looking at the origin sees the origin at the image centre
// and world +y up in the image (smaller raster y).
TEST(PerspectiveCamera, LookAtPlacesTargetAtCentre) {
  Transform camera_from_world = look_at(Vec3(0, 0, -5), Vec3(0), Vec3(0, 1, 0));
  PerspectiveCamera cam(camera_from_world.inverse(), IVec2(101, 101), {});
  CameraSample cs;
  cs.p_film = Vec2(50.5f, 50.5f);
  auto r = cam.generate_ray(cs);
  ASSERT_TRUE(r);
  EXPECT_NEAR(r->ray.o.z, -5.f, 1e-5f);
  EXPECT_NEAR(r->ray.d.z, 1.f, 1e-6f);
  cs.p_film = Vec2(50.5f, 10.f);
  EXPECT_GT(cam.generate_ray(cs)->ray.d.y, 0.f);
}

// Motion blur (pbrt-v4's CameraBase::SampleTime and AnimatedTransform): the time sample u
// becomes (1 - u) shutteropen + u shutterclose, and the camera sits where its transform is at
// that time: with TransformTimes 0 2 and the shutter 1 to 3, u = 0.25 is time 1.5 (3/4 of the
// way), u = 0.75 is time 2.5 (past the end time: held at the end).
TEST(PerspectiveCamera, MovingCameraRayLeavesFromItsPlaceAtTheShutterTime) {
  PerspectiveCamera::Settings s;
  s.shutter = Shutter{1.f, 3.f};
  const AnimatedTransform motion(Transform(), 0.f, translate(Vec3(4, 0, 0)) * rotate(90, Vec3(0, 1, 0)), 2.f);
  PerspectiveCamera cam(Transform(), IVec2(32, 32), s, motion);
  CameraSample cs;
  cs.p_film = Vec2(16.f, 16.f);  // the image centre: the camera's own +z
  for (auto [u, time, fraction] : {std::tuple{0.25f, 1.5f, 0.75f}, std::tuple{0.75f, 2.5f, 1.f}}) {
    cs.time = u;
    auto r = cam.generate_ray(cs);
    ASSERT_TRUE(r);
    EXPECT_FLOAT_EQ(r->ray.time, time);
    EXPECT_NEAR(glm::length(r->ray.o - Vec3(4.f * fraction, 0, 0)), 0.f, 1e-5f);
    // +z turned about +y by 90 fraction degrees.
    const float a = radians(90.f * fraction);
    EXPECT_NEAR(glm::length(r->ray.d - Vec3(std::sin(a), 0, std::cos(a))), 0.f, 1e-5f);
  }
}

// Every thin-lens ray from one film point passes through the same point on the plane of
// focus: the point the pinhole ray from that film point reaches there.
TEST(ThinLensCamera, RaysFromOneFilmPointConvergeAtFocalDistance) {
  PerspectiveCamera::Settings s;
  s.fov_deg = 40.f;
  s.lens_radius = 0.05f;
  s.focal_distance = 3.f;
  PerspectiveCamera cam(Transform(), IVec2(32, 32), s);
  PerspectiveCamera pin(Transform(), IVec2(32, 32), {40.f, Vec4(0.f), 0.f, 1e6f});
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  for (int k = 0; k < 200; ++k) {
    CameraSample cs;
    cs.p_film = Vec2(u(rng) * 32, u(rng) * 32);
    Ray p = pin.generate_ray(cs)->ray;
    Vec3 focus = p.at(s.focal_distance / p.d.z);
    cs.p_lens = Vec2(u(rng), u(rng));
    Ray r = cam.generate_ray(cs)->ray;
    EXPECT_LE(std::hypot(r.o.x, r.o.y), s.lens_radius * 1.0001f);
    Vec3 at = r.at((s.focal_distance - r.o.z) / r.d.z);
    EXPECT_NEAR(at.x, focus.x, 1e-4f);
    EXPECT_NEAR(at.y, focus.y, 1e-4f);
  }
}

TEST(PinholeCamera, RejectsLensRadius) {
  ParameterList p;
  Param lr;
  lr.type = "float";
  lr.name = "lensradius";
  lr.numbers = {0.1};
  lr.loc = SourceLoc{"scene.pbrt", 3, 9};
  p.add(lr);
  CameraContext ctx{p, Transform(), IVec2(8, 8), "."};
  try {
    create_pinhole_camera(ctx);
    FAIL() << "expected an error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("scene.pbrt:3:9"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("lensradius"), std::string::npos) << e.what();
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
