// A scene big enough for Embree's compact BVH layout (Scene::kCompactPrimitives, and
// kCompactObjectPrimitives for an instanced object) still finds every hit where it is: rays at a
// flat grid hit the plane at the point they were aimed at, at the analytic distance.
#include <embree3/rtcore.h>
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "../support/unity_id.h"
#include "render/scene.h"
#include "scene/params.h"
#include "shapes/triangle_mesh.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// The unit square z = 0, |x|, |y| <= 1, as a grid of n x n vertices: 2 (n - 1)^2 triangles.
Primitive grid(int n) {
  const float step = 2.f / float(n - 1);
  MeshData mesh;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) mesh.positions.push_back(Vec3(-1.f + step * float(x), -1.f + step * float(y), 0.f));
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      const int a = y * n + x, b = a + 1, c = a + n + 1, d = a + n;
      for (int i : {a, b, c, a, c, d}) mesh.indices.push_back(i);
    }
  ParameterList params(SourceLoc{"grid.pbrt", 1, 1});
  Primitive prim;
  prim.shape = std::make_unique<TriangleMesh>(std::move(mesh), Transform(), false, MeshSource(params));
  return prim;
}

// Rays from random points above the plane z = z0 towards random points on it (within the square
// |x - x0|, |y| < 0.99): each hits that point, at t = |o - target| for a unit direction.
void expect_hits_on_plane(const Scene& scene, float x0, float z0) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-0.99f, 0.99f), h(0.1f, 3.f);
  for (int i = 0; i < 20000; ++i) {
    const Vec3 target(x0 + u(rng), u(rng), z0), o(x0 + u(rng), u(rng), z0 + h(rng));
    const Vec3 d = glm::normalize(target - o);
    SurfaceInteraction si;
    ASSERT_TRUE(scene.intersect(Ray{o, d}, &si)) << i;
    EXPECT_NEAR(si.p.x, target.x, 1e-4f);
    EXPECT_NEAR(si.p.y, target.y, 1e-4f);
    EXPECT_NEAR(si.p.z, z0, 1e-5f);
    EXPECT_NEAR(glm::length(si.p - o), glm::length(target - o), 1e-4f);
  }
}

TEST(CompactBvh, AMillionTriangleGridIsHitWhereThePlaneIs) {
  Primitive prim = grid(726);  // 2 * 725^2 = 1,051,250 triangles, just over 2^20
  ASSERT_GE(prim.shape->primitive_count(), Scene::kCompactPrimitives);
  Scene scene;
  scene.add_primitive(std::move(prim));
  scene.commit();
  EXPECT_TRUE(rtcGetSceneFlags(scene.embree_scene()) & RTC_SCENE_FLAG_COMPACT);
  expect_hits_on_plane(scene, 0.f, 0.f);
}

// An object of just over 2^16 triangles (compact from there, Scene::kCompactObjectPrimitives),
// placed twice: both placements are hit where their planes are.
TEST(CompactBvh, AnInstancedGridIsHitWhereEachPlacementPutsIt) {
  Primitive prim = grid(183);  // 2 * 182^2 = 66,248 triangles
  ASSERT_GE(prim.shape->primitive_count(), Scene::kCompactObjectPrimitives);
  ASSERT_LT(prim.shape->primitive_count(), Scene::kCompactPrimitives);
  Scene scene;
  std::vector<Primitive> prims;
  prims.push_back(std::move(prim));
  scene.define_instance("grid", std::move(prims));
  scene.add_instance("grid", translate(Vec3(-5.f, 0.f, 1.f)));
  scene.add_instance("grid", translate(Vec3(5.f, 0.f, -2.f)));
  scene.commit();
  expect_hits_on_plane(scene, -5.f, 1.f);
  expect_hits_on_plane(scene, 5.f, -2.f);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
