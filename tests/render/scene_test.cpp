// The Embree scene: instanced hits equal the same geometry placed directly, tmax and
// unnormalised directions, rays that must not reach Embree, the hit-to-primitive mapping,
// light preprocessing, Embree errors as SceneErrors, and spawned rays that do not hit the
// surface they leave.
#include "render/scene.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <random>

#include "core/sampling.h"
#include "shapes/disk.h"
#include "shapes/sphere.h"
#include "shapes/triangle_mesh.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

class NullMaterial : public Material {
 public:
  const BSDF* bsdf(const SurfaceInteraction&, SampledWavelengths&, ScratchBuffer&) const override { return nullptr; }
};

class RecordingLight : public Light {
 public:
  explicit RecordingLight(bool infinite) : infinite_(infinite) {}
  std::optional<LightLiSample> sample_li(const LightSampleContext&, Vec2, const SampledWavelengths&) const override {
    return std::nullopt;
  }
  float pdf_li(const LightSampleContext&, const Vec3&, const SurfaceInteraction*) const override { return 0.f; }
  bool is_delta() const override { return false; }
  bool is_infinite() const override { return infinite_; }
  float power() const override { return 1.f; }
  void preprocess(const Bounds3& b) override {
    ++calls;
    bounds = b;
  }
  int calls = 0;
  Bounds3 bounds;

 private:
  bool infinite_;
};

Param param(const std::string& type, const std::string& name, std::vector<double> numbers) {
  Param p;
  p.type = type;
  p.name = name;
  p.loc = SourceLoc{"scene.pbrt", 1, 1};
  p.numbers = std::move(numbers);
  return p;
}

// A bent two-triangle mesh with uvs and shading normals, so that every interaction field
// is exercised.
std::unique_ptr<Shape> make_mesh(const Transform& t) {
  ParameterList pl(SourceLoc{"scene.pbrt", 1, 1});
  pl.add(param("point3", "P", {0, 0, 0, 1, 0, 0.2, 1, 1, 0, 0, 1, 0.3}));
  pl.add(param("integer", "indices", {0, 1, 2, 0, 2, 3}));
  pl.add(param("point2", "uv", {0, 0, 1, 0, 1, 1, 0, 1}));
  pl.add(param("normal", "N", {0, 0.1, 1, 0.1, 0, 1, 0, 0, 1, -0.1, 0, 1}));
  return std::move(create_trianglemesh_shapes(ShapeContext{pl, t, false, ""}).at(0));
}

std::unique_ptr<Shape> make_sphere(const Transform& t) {
  ParameterList pl;
  pl.add(param("float", "radius", {0.4}));
  pl.add(param("float", "zmax", {0.3}));
  return std::move(create_sphere_shapes(ShapeContext{pl, t, false, ""}).at(0));
}

std::unique_ptr<Shape> make_disk(const Transform& t) {
  ParameterList pl;
  pl.add(param("float", "radius", {0.5}));
  pl.add(param("float", "height", {-1}));
  return std::move(create_disk_shapes(ShapeContext{pl, t, false, ""}).at(0));
}

void expect_near(const Vec3& a, const Vec3& b, float tol, const char* what) {
  EXPECT_LE(glm::distance(a, b), tol) << what << ": (" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x << ", "
                                      << b.y << ", " << b.z << ")";
}

TEST(Scene, InstanceHitEqualsSameGeometryTransformed) {
  // Includes a mirror (negative determinant) and a non-uniform scale.
  Transform place = translate(Vec3(0.5f, -1, 2)) * rotate(35.f, Vec3(1, 2, 3)) * scale(Vec3(1.5f, 1, -2));
  NullMaterial mat;
  Scene instanced, direct;
  std::vector<Primitive> group;
  group.push_back(Primitive{make_mesh(Transform()), &mat, nullptr});
  group.push_back(Primitive{make_sphere(translate(Vec3(0.5f, 0.5f, 1))), &mat, nullptr});
  group.push_back(Primitive{make_disk(translate(Vec3(0.5f, 0.5f, 0))), &mat, nullptr});
  instanced.define_instance("thing", std::move(group));
  ASSERT_TRUE(instanced.has_instance("thing"));
  instanced.add_instance("thing", place);
  instanced.commit();
  direct.add_primitive(Primitive{make_mesh(place), &mat, nullptr});
  direct.add_primitive(Primitive{make_sphere(place * translate(Vec3(0.5f, 0.5f, 1))), &mat, nullptr});
  direct.add_primitive(Primitive{make_disk(place * translate(Vec3(0.5f, 0.5f, 0))), &mat, nullptr});
  direct.commit();
  EXPECT_EQ(instanced.primitive_count(), direct.primitive_count());

  std::mt19937 rng(1);
  std::uniform_real_distribution<float> U(0.f, 1.f);
  Vec3 centre = place.point(Vec3(0.5f, 0.5f, 0.5f));
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    Vec3 dir = sample_uniform_sphere(Vec2(U(rng), U(rng)));
    Vec3 o = centre - 8.f * dir + 1.5f * Vec3(U(rng) - 0.5f, U(rng) - 0.5f, U(rng) - 0.5f);
    SurfaceInteraction a, b;
    bool ha = instanced.intersect(Ray{o, dir}, &a), hb = direct.intersect(Ray{o, dir}, &b);
    ASSERT_EQ(ha, hb) << "ray " << i;
    if (!ha) continue;
    ++hits;
    // Float geometry transformed two ways: agreement to a few ulps of the scene scale.
    EXPECT_NEAR(a.t, b.t, 2e-4f);
    expect_near(a.p, b.p, 2e-4f, "p");
    expect_near(a.n, b.n, 2e-3f, "n");
    expect_near(a.ns, b.ns, 2e-3f, "ns");
    EXPECT_NEAR(a.uv.x, b.uv.x, 2e-3f);
    EXPECT_NEAR(a.uv.y, b.uv.y, 2e-3f);
    expect_near(a.dpdu, b.dpdu, 2e-3f * std::max(1.f, glm::length(b.dpdu)), "dpdu");
    expect_near(a.dpdv, b.dpdv, 2e-3f * std::max(1.f, glm::length(b.dpdv)), "dpdv");
    expect_near(a.wo, -dir, 1e-6f, "wo");
    EXPECT_EQ(a.material, &mat);
  }
  EXPECT_GT(hits, 500);
}

TEST(Scene, InstancePlacedTwiceCountsOnceAndExtendsBounds) {
  Scene scene;
  std::vector<Primitive> group;
  group.push_back(Primitive{make_mesh(Transform()), nullptr, nullptr});
  scene.define_instance("tile", std::move(group));
  scene.add_instance("tile", translate(Vec3(10, 0, 0)));
  scene.add_instance("tile", translate(Vec3(-10, 0, 0)));
  scene.add_primitive(Primitive{make_sphere(Transform()), nullptr, nullptr});
  scene.commit();
  EXPECT_EQ(scene.primitive_count(), 3u);  // 2 triangles + 1 sphere
  EXPECT_EQ(scene.bounds().lo.x, -10.f);
  EXPECT_EQ(scene.bounds().hi.x, 11.f);
  SurfaceInteraction si;
  ASSERT_TRUE(scene.intersect(Ray{Vec3(-9.5f, 0.5f, 5), Vec3(0, 0, -1)}, &si));
  EXPECT_NEAR(si.p.x, -9.5f, 1e-6f);
  ASSERT_TRUE(scene.intersect(Ray{Vec3(10.5f, 0.5f, 5), Vec3(0, 0, -1)}, &si));
  EXPECT_NEAR(si.p.x, 10.5f, 1e-6f);
}

TEST(Scene, InstanceErrors) {
  Scene scene;
  std::vector<Primitive> group;
  group.push_back(Primitive{make_mesh(Transform()), nullptr, nullptr});
  scene.define_instance("a", std::move(group));
  EXPECT_THROW(scene.define_instance("a", {}), SceneError);
  EXPECT_THROW(scene.add_instance("b", Transform()), SceneError);
  EXPECT_FALSE(scene.has_instance("b"));
}

// A plane at z = 2 (two triangles), seen from the origin.
std::unique_ptr<Scene> plane_scene(const Material* mat = nullptr, const Light* light = nullptr) {
  ParameterList pl;
  pl.add(param("point3", "P", {-5, -5, 2, 5, -5, 2, 5, 5, 2, -5, 5, 2}));
  pl.add(param("integer", "indices", {0, 1, 2, 0, 2, 3}));
  auto scene = std::make_unique<Scene>();
  scene->add_primitive(
      Primitive{std::move(create_trianglemesh_shapes(ShapeContext{pl, Transform(), false, ""})[0]), mat, light});
  scene->commit();
  return scene;
}

TEST(Scene, OccludedAndIntersectRespectTmaxInUnitsOfD) {
  auto scene = plane_scene();
  EXPECT_FALSE(scene->occluded(Ray{Vec3(0), Vec3(0, 0, 1), 1.9f}));
  EXPECT_TRUE(scene->occluded(Ray{Vec3(0), Vec3(0, 0, 1), 2.1f}));
  EXPECT_TRUE(scene->occluded(Ray{Vec3(0), Vec3(0, 0, 1)}));  // tmax infinite
  // |d| = 2: the plane is at t = 1.
  EXPECT_FALSE(scene->occluded(Ray{Vec3(0), Vec3(0, 0, 2), 0.9f}));
  EXPECT_TRUE(scene->occluded(Ray{Vec3(0), Vec3(0, 0, 2), 1.1f}));
  // spawn_ray_to stops short of its target: a target on the plane is not occluded by it.
  EXPECT_FALSE(
      scene->occluded(spawn_ray_to(Vec3(0), Vec3(1e-6f), Vec3(0, 0, 1), 0.f, Vec3(1, 1, 2), Vec3(0), Vec3(0))));
  SurfaceInteraction si;
  EXPECT_FALSE(scene->intersect(Ray{Vec3(0), Vec3(0, 0, 2), 0.9f}, &si));
  ASSERT_TRUE(scene->intersect(Ray{Vec3(0), Vec3(0, 0, 2), 1.1f}, &si));
  EXPECT_NEAR(si.t, 1.f, 1e-6f);
  EXPECT_NEAR(si.wo.z, -1.f, 1e-6f);
}

TEST(Scene, UntraceableRaysReturnNoHit) {
  auto scene = plane_scene();
  float nan = std::numeric_limits<float>::quiet_NaN();
  SurfaceInteraction si;
  for (Ray r : {Ray{Vec3(nan, 0, 0), Vec3(0, 0, 1)}, Ray{Vec3(0), Vec3(0, kInfinity, 1)}, Ray{Vec3(0), Vec3(0, 0, nan)},
                Ray{Vec3(0), Vec3(0)}, Ray{Vec3(0), Vec3(0, 0, 1), nan}, Ray{Vec3(0), Vec3(0, 0, 1), -1.f}}) {
    EXPECT_FALSE(scene->intersect(r, &si));
    EXPECT_FALSE(scene->occluded(r));
  }
}

TEST(Scene, RecordsTheRaysItTracesWhileAsked) {
  auto scene = plane_scene();
  SurfaceInteraction si;
  RayRecord rec;
  scene->intersect(Ray{Vec3(0), Vec3(0, 0, 1)}, &si);  // before recording: not kept
  scene->record_rays(&rec);
  const Ray a{Vec3(0.5f, -1, 0), Vec3(0, 0, 2), 3.f, 0.25f}, b{Vec3(0, 2, 1), Vec3(1, 0, 0)};
  EXPECT_TRUE(scene->intersect(a, &si));
  EXPECT_FALSE(scene->occluded(b));
  scene->intersect(Ray{Vec3(0), Vec3(0)}, &si);  // untraceable: Embree never sees it
  scene->record_rays(nullptr);
  scene->occluded(a);  // after recording: not kept
  ASSERT_EQ(rec.closest.size(), 1u);
  ASSERT_EQ(rec.shadow.size(), 1u);
  const RTCRay &ra = rec.closest[0], &rb = rec.shadow[0];
  EXPECT_EQ(Vec3(ra.org_x, ra.org_y, ra.org_z), a.o);
  EXPECT_EQ(Vec3(ra.dir_x, ra.dir_y, ra.dir_z), a.d);
  EXPECT_EQ(ra.tfar, 3.f);
  // Embree's time: the ray's time as a fraction of the TransformTimes, 0 where nothing moves.
  EXPECT_EQ(ra.time, 0.f);
  EXPECT_EQ(Vec3(rb.org_x, rb.org_y, rb.org_z), b.o);
  EXPECT_EQ(Vec3(rb.dir_x, rb.dir_y, rb.dir_z), b.d);
  EXPECT_EQ(rb.tfar, kInfinity);
  // Replayed through Embree alone, the recorded closest-hit ray finds the plane at z = 2
  // (t = 1 for |d| = 2), as the scene did.
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRayHit rh;
  rh.ray = ra;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene->embree_scene(), &ctx, &rh);
  ASSERT_NE(rh.hit.geomID, RTC_INVALID_GEOMETRY_ID);
  EXPECT_NEAR(rh.ray.tfar, 1.f, 1e-6f);
}

TEST(Scene, HitCarriesMaterialAndEmitterOfItsPrimitive) {
  NullMaterial mat;
  RecordingLight light(false);
  auto scene = plane_scene(&mat, &light);
  SurfaceInteraction si;
  ASSERT_TRUE(scene->intersect(Ray{Vec3(1, 1, 0), Vec3(0, 0, 1)}, &si));
  EXPECT_EQ(si.material, &mat);
  EXPECT_EQ(si.area_light, &light);
}

TEST(Scene, ClosestOfSeveralShapes) {
  NullMaterial near_mat, far_mat;
  Scene scene;
  scene.add_primitive(Primitive{make_sphere(translate(Vec3(0, 0, 10))), &far_mat, nullptr});
  scene.add_primitive(Primitive{make_sphere(translate(Vec3(0, 0, 5))), &near_mat, nullptr});
  scene.commit();
  SurfaceInteraction si;
  ASSERT_TRUE(scene.intersect(Ray{Vec3(0), Vec3(0, 0, 1)}, &si));
  EXPECT_EQ(si.material, &near_mat);
  EXPECT_NEAR(si.t, 4.6f, 1e-5f);  // radius 0.4
}

TEST(Scene, LightsPreprocessedWithSceneBoundsAndClassified) {
  Scene scene;
  auto area = std::make_unique<RecordingLight>(false);
  auto sky = std::make_unique<RecordingLight>(true);
  RecordingLight *a = area.get(), *s = sky.get();
  scene.add_light(std::move(area));
  scene.add_light(std::move(sky));
  scene.add_primitive(Primitive{make_sphere(translate(Vec3(1, 2, 3))), nullptr, a});
  scene.commit();
  EXPECT_EQ(scene.lights().size(), 2u);
  ASSERT_EQ(scene.infinite_lights().size(), 1u);
  EXPECT_EQ(scene.infinite_lights()[0], s);
  EXPECT_EQ(a->calls, 1);
  EXPECT_EQ(s->calls, 1);
  EXPECT_NEAR(s->bounds.lo.x, 0.6f, 1e-5f);
  EXPECT_NEAR(s->bounds.hi.z, 3.3f, 1e-5f);  // zmax 0.3
}

TEST(Scene, EmptySceneIsUsable) {
  Scene scene;
  auto sky = std::make_unique<RecordingLight>(true);
  RecordingLight* s = sky.get();
  scene.add_light(std::move(sky));
  scene.commit();
  SurfaceInteraction si;
  EXPECT_FALSE(scene.intersect(Ray{Vec3(0), Vec3(0, 0, 1)}, &si));
  EXPECT_FALSE(scene.occluded(Ray{Vec3(0), Vec3(0, 0, 1)}));
  EXPECT_EQ(scene.primitive_count(), 0u);
  // A finite extent (the origin), never NaN or infinite.
  EXPECT_EQ(s->bounds.lo, Vec3(0));
  EXPECT_EQ(s->bounds.hi, Vec3(0));
  EXPECT_EQ(scene.bounds().radius(), 0.f);
}

// A shape whose attach() misuses Embree: a user-geometry call on a triangle geometry.
class BrokenShape : public Shape {
 public:
  unsigned attach(RTCDevice device, RTCScene scene) const override {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryUserPrimitiveCount(g, 1);
    rtcCommitGeometry(g);  // no vertex buffer either
    unsigned id = rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    return id;
  }
  SurfaceInteraction interaction(const Ray&, float, unsigned, Vec2, Vec3) const override { return {}; }
  float area() const override { return 1.f; }
  ShapeSample sample_area(Vec2) const override { return {}; }
  Bounds3 bounds() const override { return {}; }
};

TEST(Scene, EmbreeErrorsBecomeSceneErrors) {
  Scene scene;
  try {
    scene.add_primitive(Primitive{std::make_unique<BrokenShape>(), nullptr, nullptr});
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("Embree error"), std::string::npos) << e.what();
  }
}

// Rays spawned with offset_ray_origin (core/ray.h) from hits on a sphere and on a plane,
// at scene scales 1e-4 .. 1e5 and placed near and far (1e4 radii) from the origin (float
// spacing grows with distance), never hit the point they leave: rays leaving a convex
// sphere, or either side of a lone plane, must find nothing; rays into the sphere must
// reach its far side (a self-hit lands at ~0 distance, the far side at the chord length
// 2 r cos(angle to -n)). The old fixed epsilon (1e-4 * max(1, |p|) * 0.05 + 1e-6) failed
// this at scale 1e-4 (the offset is 1e-2 radii) and 1e5 far from the origin.
TEST(Scene, SpawnedRaysDoNotSelfIntersect) {
  for (float s : {1e-4f, 1e-2f, 1.f, 1e2f, 1e5f})
    for (float distance : {0.f, 100.f, 1e4f}) {
      Transform t = translate(s * Vec3(distance, -distance, 0.5f * distance)) * scale(Vec3(s));
      Scene sphere_scene, plane_scene;
      ParameterList sp;
      sp.add(param("float", "radius", {1.0}));
      sphere_scene.add_primitive(
          Primitive{std::move(create_sphere_shapes(ShapeContext{sp, t, false, ""})[0]), nullptr, nullptr});
      sphere_scene.commit();
      ParameterList pp;
      pp.add(param("point3", "P", {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}));
      pp.add(param("integer", "indices", {0, 1, 2, 0, 2, 3}));
      Transform tilt = t * rotate(20.f, Vec3(1, 1, 0));
      plane_scene.add_primitive(
          Primitive{std::move(create_trianglemesh_shapes(ShapeContext{pp, tilt, false, ""})[0]), nullptr, nullptr});
      plane_scene.commit();

      Vec3 centre = t.point(Vec3(0));
      // Below this chord (in radii) a grazing inward ray is too close to tangent to judge:
      // the hit point itself is only known to float spacing at |p| ~ distance radii.
      float min_chord = 4.f * (2e-5f * std::max(1.f, distance) + 1e-3f);
      std::mt19937 rng(17);
      std::uniform_real_distribution<float> U(0.f, 1.f);
      int bad = 0, checked = 0, plane_hits = 0;
      for (int i = 0; i < 2000; ++i) {
        Vec3 dir = sample_uniform_sphere(Vec2(U(rng), U(rng)));
        Vec3 out_local = sample_uniform_hemisphere(Vec2(U(rng), U(rng)));
        SurfaceInteraction si, next;
        if (sphere_scene.intersect(Ray{centre - 10.f * s * dir, dir}, &si)) {
          Vec3 out = Frame(si.n).to_world(out_local);
          if (sphere_scene.intersect(spawn_ray(si, out), &next)) ++bad;
          float chord = 2.f * out_local.z;
          if (chord > min_chord) {
            ++checked;
            if (!sphere_scene.intersect(spawn_ray(si, -out), &next) || glm::distance(next.p, si.p) < 0.5f * chord * s)
              ++bad;
          }
        }
        Vec3 jitter = 0.5f * s * Vec3(U(rng) - 0.5f, U(rng) - 0.5f, 0);
        if (plane_scene.intersect(Ray{tilt.point(Vec3(0)) - 10.f * s * dir + jitter, dir}, &si)) {
          ++plane_hits;
          Vec3 out = Frame(si.n).to_world(out_local);
          if (plane_scene.intersect(spawn_ray(si, out), &next)) ++bad;
          if (plane_scene.intersect(spawn_ray(si, -out), &next)) ++bad;
        }
      }
      EXPECT_GT(checked, 1000);
      EXPECT_GT(plane_hits, 1000);
      EXPECT_EQ(bad, 0) << "at scale " << s << ", distance " << distance << " radii";
    }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
