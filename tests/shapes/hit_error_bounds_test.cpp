// The rounding-error boxes shapes attach to hits (SurfaceInteraction::p_error): at scene
// scales 1e-4 .. 1e5 and far from the origin, the exact surface point, computed in double
// from the primitive's own definition, lies within p +- p_error, for triangles (bilinear
// patches are triangulated, so the same code), spheres and disks.
#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "../support/sample_count.h"
#include "../support/unity_id.h"
#include "core/sampling.h"
#include "render/scene.h"
#include "shapes/cylinder.h"
#include "shapes/disk.h"
#include "shapes/sphere.h"
#include "shapes/triangle_mesh.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

Param param(const std::string& type, const std::string& name, std::vector<double> numbers) {
  Param p;
  p.type = type;
  p.name = name;
  p.loc = SourceLoc{"bounds.pbrt", 1, 1};
  p.numbers = std::move(numbers);
  return p;
}

std::unique_ptr<Scene> one_shape_scene(std::unique_ptr<Shape> shape) {
  auto scene = std::make_unique<Scene>();
  scene->add_primitive(Primitive{std::move(shape), nullptr, nullptr});
  scene->commit();
  return scene;
}

constexpr float kScales[] = {1e-4f, 1e-2f, 1.f, 1e2f, 1e5f};
constexpr float kOffsetsInRadii[] = {0.f, 1e4f};
// Each ray is checked on its own, so the sanitizer build's tenth checks the same property.
constexpr int kRays = test::sample_count(100000);

// A ray from a random point 10 scene units (times s) away towards a random point near c.
Ray random_ray_towards(const Vec3& c, float s, std::mt19937& rng) {
  std::uniform_real_distribution<float> U(0.f, 1.f);
  Vec3 dir = sample_uniform_sphere(Vec2(U(rng), U(rng)));
  Vec3 aim = c + 0.9f * s * Vec3(U(rng) - 0.5f, U(rng) - 0.5f, U(rng) - 0.5f);
  return Ray{aim - 10.f * s * dir, dir};
}

// The triangle's float world-space corners are given directly (identity transform), and its
// uv corners (0,0) (1,0) (0,1) make si.uv = (b1, b2), Embree's barycentrics, exactly: the
// exact point with these barycentrics is then (1 - b1 - b2) p0 + b1 p1 + b2 p2 in double.
TEST(HitErrorBounds, TriangleExactPointInsideBox) {
  for (float s : kScales)
    for (float off : kOffsetsInRadii) {
      Vec3 base = s * off * Vec3(1.f, -0.7f, 0.4f);
      Vec3 p[3] = {base + s * Vec3(-1.f, -1.f, 0.1f), base + s * Vec3(1.3f, -0.8f, -0.2f),
                   base + s * Vec3(0.f, 1.2f, 0.3f)};
      ParameterList pl(SourceLoc{"bounds.pbrt", 1, 1});
      pl.add(param("point3", "P", {p[0].x, p[0].y, p[0].z, p[1].x, p[1].y, p[1].z, p[2].x, p[2].y, p[2].z}));
      pl.add(param("integer", "indices", {0, 1, 2}));
      pl.add(param("point2", "uv", {0, 0, 1, 0, 0, 1}));
      auto scene = one_shape_scene(std::move(create_trianglemesh_shapes(ShapeContext{pl, Transform(), false, ""})[0]));
      std::mt19937 rng(5);
      int hits = 0, outside = 0;
      for (int i = 0; i < kRays; ++i) {
        SurfaceInteraction si;
        if (!scene->intersect(random_ray_towards(base, s, rng), &si)) continue;
        ++hits;
        double b1 = si.uv.x, b2 = si.uv.y, b0 = 1.0 - b1 - b2;
        for (int k = 0; k < 3; ++k) {
          double exact = b0 * double(p[0][k]) + b1 * double(p[1][k]) + b2 * double(p[2][k]);
          if (std::abs(exact - double(si.p[k])) > double(si.p_error[k])) ++outside;
        }
      }
      EXPECT_GT(hits, kRays / 10) << "scale " << s;
      EXPECT_EQ(outside, 0) << "scale " << s << ", offset " << off << " radii";
    }
}

// The world sphere of a translate * uniform-scale transform has centre M[3] and radius
// s * r exactly (in double from the float matrix). A point within the box p +- e of the
// sphere is within |e| (2-norm) of its radius, which is what is checked.
TEST(HitErrorBounds, SphereExactSurfaceWithinBox) {
  for (float s : kScales)
    for (float off : kOffsetsInRadii) {
      Transform t = translate(s * off * Vec3(1.f, -0.7f, 0.4f)) * scale(Vec3(s));
      ParameterList pl(SourceLoc{"bounds.pbrt", 1, 1});
      auto scene = one_shape_scene(std::move(create_sphere_shapes(ShapeContext{pl, t, false, ""})[0]));
      glm::dvec3 centre(glm::dvec4(t.matrix()[3]));
      double radius = double(t.matrix()[0][0]);
      std::mt19937 rng(6);
      int hits = 0, outside = 0;
      for (int i = 0; i < kRays; ++i) {
        SurfaceInteraction si;
        if (!scene->intersect(random_ray_towards(Vec3(centre), s, rng), &si)) continue;
        ++hits;
        double dist = glm::length(glm::dvec3(si.p) - centre);
        if (std::abs(dist - radius) > glm::length(glm::dvec3(si.p_error))) ++outside;
      }
      EXPECT_GT(hits, kRays / 10) << "scale " << s;
      EXPECT_EQ(outside, 0) << "scale " << s << ", offset " << off << " radii";
    }
}

// A disk at height h under translate * scale lies in the world plane z = M[3].z + s h
// (double); the hit's z must be within p_error.z of it.
TEST(HitErrorBounds, DiskExactPlaneWithinBox) {
  for (float s : kScales)
    for (float off : kOffsetsInRadii) {
      Transform t = translate(s * off * Vec3(1.f, -0.7f, 0.4f)) * scale(Vec3(s));
      ParameterList pl(SourceLoc{"bounds.pbrt", 1, 1});
      pl.add(param("float", "height", {0.3}));
      auto scene = one_shape_scene(std::move(create_disk_shapes(ShapeContext{pl, t, false, ""})[0]));
      double plane_z = double(t.matrix()[3][2]) + double(t.matrix()[2][2]) * double(0.3f);
      std::mt19937 rng(7);
      int hits = 0, outside = 0;
      for (int i = 0; i < kRays; ++i) {
        SurfaceInteraction si;
        if (!scene->intersect(random_ray_towards(t.point(Vec3(0.f, 0.f, 0.3f)), s, rng), &si)) continue;
        ++hits;
        if (std::abs(double(si.p.z) - plane_z) > double(si.p_error.z)) ++outside;
      }
      EXPECT_GT(hits, kRays / 10) << "scale " << s;
      EXPECT_EQ(outside, 0) << "scale " << s << ", offset " << off << " radii";
    }
}

// Rays leaving a disk or a triangle mesh quad (either side) in random directions find
// nothing: the spawned origin is past the error box, so the primitive it leaves cannot be
// re-hit. Both are tilted, and the quad also lies exactly in z = 0, where p_error.z is 0
// and only Embree's own rounding (TriangleMesh::embree_plane_error) keeps rays off it.
// `outward_only`: directions on the normal's side only, for a shape that is not convex (an open
// tube, whose far wall a ray into it may rightly hit); one leaving to the outside of the solid
// it bounds can meet nothing of it.
void expect_no_self_hits(const std::function<std::unique_ptr<Shape>(const Transform&)>& make, const Vec3& axis,
                         float degrees, bool outward_only = false) {
  for (float s : kScales)
    for (float off : kOffsetsInRadii) {
      Transform t = translate(s * off * Vec3(1.f, -0.7f, 0.4f)) * scale(Vec3(s)) * rotate(degrees, axis);
      auto scene = one_shape_scene(make(t));
      std::mt19937 rng(8);
      std::uniform_real_distribution<float> U(0.f, 1.f);
      int hits = 0, bad = 0;
      for (int i = 0; i < kRays; ++i) {
        SurfaceInteraction si, next;
        if (!scene->intersect(random_ray_towards(t.point(Vec3(0.f)), s, rng), &si)) continue;
        ++hits;
        Vec3 w = sample_uniform_sphere(Vec2(U(rng), U(rng)));
        if (outward_only && glm::dot(w, si.n) < 0.f) w = -w;
        if (scene->intersect(spawn_ray(si, w), &next)) ++bad;
      }
      EXPECT_GT(hits, kRays / 10) << "scale " << s;
      EXPECT_EQ(bad, 0) << "scale " << s << ", offset " << off << " radii, rotation " << degrees;
    }
}

std::unique_ptr<Shape> make_disk(const Transform& t) {
  ParameterList pl(SourceLoc{"bounds.pbrt", 1, 1});
  return std::move(create_disk_shapes(ShapeContext{pl, t, false, ""})[0]);
}

std::unique_ptr<Shape> make_quad(const Transform& t) {
  ParameterList pl(SourceLoc{"bounds.pbrt", 1, 1});
  pl.add(param("point3", "P", {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}));
  pl.add(param("integer", "indices", {0, 1, 2, 0, 2, 3}));
  return std::move(create_trianglemesh_shapes(ShapeContext{pl, t, false, ""})[0]);
}

TEST(HitErrorBounds, SpawnedRaysLeaveDisks) {
  expect_no_self_hits(make_disk, Vec3(1, 2, 0), 30.f);
  expect_no_self_hits(make_disk, Vec3(0, 0, 1), 0.f);
}

std::unique_ptr<Shape> make_cylinder(const Transform& t) {
  ParameterList pl(SourceLoc{"bounds.pbrt", 1, 1});
  return std::move(create_cylinder_shapes(ShapeContext{pl, t, false, ""})[0]);
}

TEST(HitErrorBounds, SpawnedRaysLeaveCylinders) {
  expect_no_self_hits(make_cylinder, Vec3(1, 2, 0), 30.f, true);
  expect_no_self_hits(make_cylinder, Vec3(0, 0, 1), 0.f, true);
}

TEST(HitErrorBounds, SpawnedRaysLeaveTriangles) {
  expect_no_self_hits(make_quad, Vec3(1, 2, 0), 30.f);
  expect_no_self_hits(make_quad, Vec3(0, 0, 1), 0.f);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
