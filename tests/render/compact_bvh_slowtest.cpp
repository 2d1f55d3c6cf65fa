// A scene big enough for Embree's compact BVH layout (Scene::kCompactPrimitives) still finds every
// hit where it is: rays at a flat grid of just over 2^20 triangles hit the plane at the point they
// were aimed at, at the analytic distance.
#include <embree3/rtcore.h>
#include <gtest/gtest.h>

#include <random>

#include "render/scene.h"
#include "scene/params.h"
#include "shapes/triangle_mesh.h"

namespace eyetrace {
namespace {

TEST(CompactBvh, AMillionTriangleGridIsHitWhereThePlaneIs) {
  const int n = 726;  // vertices per side: 2 * 725^2 = 1,051,250 triangles, just over 2^20
  const float step = 2.f / float(n - 1);
  MeshData mesh;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) mesh.positions.push_back(Vec3(-1.f + step * float(x), -1.f + step * float(y), 0.f));
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      const int a = y * n + x, b = a + 1, c = a + n + 1, d = a + n;
      for (int i : {a, b, c, a, c, d}) mesh.indices.push_back(i);
    }
  const size_t triangles = mesh.indices.size() / 3;
  ASSERT_GE(triangles, Scene::kCompactPrimitives);
  ParameterList params(SourceLoc{"grid.pbrt", 1, 1});
  Scene scene;
  Primitive prim;
  prim.shape = std::make_unique<TriangleMesh>(std::move(mesh), Transform(), false, MeshSource(params));
  scene.add_primitive(std::move(prim));
  scene.commit();
  EXPECT_TRUE(rtcGetSceneFlags(scene.embree_scene()) & RTC_SCENE_FLAG_COMPACT);

  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-0.99f, 0.99f), h(0.1f, 3.f);
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    // From a point above the grid towards a point on it: the hit is that point, at t = |o - target|
    // for a unit direction.
    const Vec3 target(u(rng), u(rng), 0.f), o(u(rng), u(rng), h(rng));
    const Vec3 d = glm::normalize(target - o);
    SurfaceInteraction si;
    ASSERT_TRUE(scene.intersect(Ray{o, d}, &si)) << i;
    EXPECT_NEAR(si.p.x, target.x, 1e-4f);
    EXPECT_NEAR(si.p.y, target.y, 1e-4f);
    EXPECT_NEAR(si.p.z, 0.f, 1e-5f);
    EXPECT_NEAR(glm::length(si.p - o), glm::length(target - o), 1e-4f);
    ++hits;
  }
  EXPECT_EQ(hits, 20000);
}

}  // namespace
}  // namespace eyetrace
