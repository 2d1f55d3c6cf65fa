// Bilinear patch meshes split into triangles: exact for planar patches (position, normal
// and, for parallelograms, pbrt's patch uv), plus validation errors.
#include "shapes/bilinear_mesh.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <functional>

#include "render/scene.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

Param param(const std::string& type, const std::string& name, std::vector<double> numbers) {
  Param p;
  p.type = type;
  p.name = name;
  p.loc = SourceLoc{"blp.pbrt", 8, 3};
  p.numbers = std::move(numbers);
  return p;
}

ParameterList patch_params(std::vector<double> P, std::vector<double> indices = {}) {
  ParameterList pl(SourceLoc{"blp.pbrt", 8, 1});
  pl.add(param("point3", "P", std::move(P)));
  if (!indices.empty()) pl.add(param("integer", "indices", std::move(indices)));
  return pl;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

struct OneShape {
  std::unique_ptr<Scene> scene = std::make_unique<Scene>();
  explicit OneShape(std::unique_ptr<Shape> s) {
    scene->add_primitive(Primitive{std::move(s), nullptr, nullptr});
    scene->commit();
  }
};

TEST(BilinearMesh, ParallelogramPatchIsExact) {
  // p00 = 0, p10 = a = (2, 0, 0), p01 = b = (1, 1, 0), p11 = a + b: p(u, v) = u a + v b.
  ParameterList pl = patch_params({0, 0, 0, 2, 0, 0, 1, 1, 0, 3, 1, 0});
  auto shapes = create_bilinearmesh_shapes(ShapeContext{pl, Transform(), false, ""});
  ASSERT_EQ(shapes.size(), 1u);
  EXPECT_EQ(shapes[0]->primitive_count(), 2u);
  EXPECT_NEAR(shapes[0]->area(), 2.f, 1e-6f);  // |a x b|
  OneShape s(std::move(shapes[0]));
  // Points on both sides of the p10-p01 diagonal.
  for (Vec2 uv : {Vec2(0.2f, 0.3f), Vec2(0.8f, 0.7f)}) {
    Vec3 p = uv.x * Vec3(2, 0, 0) + uv.y * Vec3(1, 1, 0);
    SurfaceInteraction si;
    ASSERT_TRUE(s.scene->intersect(Ray{p + Vec3(0, 0, 1), Vec3(0, 0, -1)}, &si));
    EXPECT_NEAR(si.uv.x, uv.x, 1e-6f);
    EXPECT_NEAR(si.uv.y, uv.y, 1e-6f);
    // pbrt's patch normal cross(dp/du, dp/dv) = a x b = +z (2 in length).
    EXPECT_NEAR(si.n.z, 1.f, 1e-6f);
    EXPECT_NEAR(glm::distance(si.dpdu, Vec3(2, 0, 0)), 0.f, 1e-5f);
    EXPECT_NEAR(glm::distance(si.dpdv, Vec3(1, 1, 0)), 0.f, 1e-5f);
  }
}

TEST(BilinearMesh, SharedVerticesWithUVAndReverseOrientation) {
  // Two unit patches side by side sharing an edge; uv given per vertex as (x/2, y).
  ParameterList pl = patch_params({0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0}, {0, 1, 3, 4, 1, 2, 4, 5});
  pl.add(param("point2", "uv", {0, 0, 0.5, 0, 1, 0, 0, 1, 0.5, 1, 1, 1}));
  auto shapes = create_bilinearmesh_shapes(ShapeContext{pl, Transform(), true, ""});
  EXPECT_EQ(shapes.at(0)->primitive_count(), 4u);
  EXPECT_NEAR(shapes[0]->area(), 2.f, 1e-6f);
  OneShape s(std::move(shapes[0]));
  SurfaceInteraction si;
  ASSERT_TRUE(s.scene->intersect(Ray{Vec3(1.5f, 0.25f, 1), Vec3(0, 0, -1)}, &si));
  EXPECT_NEAR(si.uv.x, 0.75f, 1e-6f);
  EXPECT_NEAR(si.uv.y, 0.25f, 1e-6f);
  EXPECT_NEAR(si.n.z, -1.f, 1e-6f);  // ReverseOrientation
}

TEST(BilinearMesh, ValidationErrorsNameTheParameter) {
  std::vector<double> P5 = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 2, 0};
  auto fails = [](ParameterList pl) {
    return error_of([&] { create_bilinearmesh_shapes(ShapeContext{pl, Transform(), false, ""}); });
  };
  std::string e = fails(patch_params(P5));
  EXPECT_NE(e.find("\"indices\""), std::string::npos) << e;
  EXPECT_NE(e.find("exactly 4 vertices"), std::string::npos) << e;
  e = fails(patch_params(P5, {0, 1, 2}));
  EXPECT_NE(e.find("not a multiple of 4"), std::string::npos) << e;
  e = fails(patch_params(P5, {0, 1, 2, 5}));
  EXPECT_NE(e.find("out of range"), std::string::npos) << e;
  ParameterList bad_n = patch_params(P5, {0, 1, 2, 3});
  bad_n.add(param("normal", "N", {0, 0, 1}));
  e = fails(std::move(bad_n));
  EXPECT_NE(e.find("\"N\""), std::string::npos) << e;
  EXPECT_NE(e.find("blp.pbrt:8:3"), std::string::npos) << e;
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
