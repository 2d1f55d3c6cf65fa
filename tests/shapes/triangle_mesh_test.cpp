// Triangle meshes: hits against hand-computed answers, pbrt's normal orientation rules,
// validation errors, and area sampling checked by chi-square.
#include "shapes/triangle_mesh.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "../support/one_shape.h"
#include "render/scene.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

Param param(const std::string& type, const std::string& name, std::vector<double> numbers) {
  Param p;
  p.type = type;
  p.name = name;
  p.loc = SourceLoc{"mesh.pbrt", 3, 7};
  p.numbers = std::move(numbers);
  return p;
}

ParameterList mesh_params(std::vector<double> P, std::vector<double> indices = {}) {
  ParameterList pl(SourceLoc{"mesh.pbrt", 3, 1});
  pl.add(param("point3", "P", std::move(P)));
  if (!indices.empty()) pl.add(param("integer", "indices", std::move(indices)));
  return pl;
}

std::unique_ptr<Shape> make_mesh(const ParameterList& pl, const Transform& t = Transform(), bool reverse = false) {
  auto shapes = create_trianglemesh_shapes(ShapeContext{pl, t, reverse, ""});
  EXPECT_EQ(shapes.size(), 1u);
  return std::move(shapes.at(0));
}

using test::OneShape;

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

// The unit right triangle p0 = (0,0,0), p1 = (1,0,0), p2 = (0,1,0) lifted to z = 1.
const std::vector<double> kTriangleZ1 = {0, 0, 1, 1, 0, 1, 0, 1, 1};

TEST(TriangleMesh, HitMatchesAnalyticPointDistanceAndNormal) {
  OneShape s(make_mesh(mesh_params(kTriangleZ1)));
  SurfaceInteraction si;
  ASSERT_TRUE(s.scene->intersect(Ray{Vec3(0.2f, 0.3f, -1.f), Vec3(0, 0, 1)}, &si));
  EXPECT_NEAR(si.t, 2.f, 1e-6f);
  EXPECT_NEAR(si.p.x, 0.2f, 1e-6f);
  EXPECT_NEAR(si.p.y, 0.3f, 1e-6f);
  EXPECT_NEAR(si.p.z, 1.f, 1e-6f);
  // pbrt: n along cross(p0 - p2, p1 - p2) = cross((0,-1,0), (1,-1,0)) = +z.
  EXPECT_NEAR(si.n.z, 1.f, 1e-6f);
  EXPECT_EQ(si.ns, si.n);
  EXPECT_NEAR(si.wo.z, -1.f, 1e-6f);
  // Default uv (0,0) (1,0) (1,1) at barycentrics b0 = 0.5, b1 = 0.2, b2 = 0.3: (0.5, 0.3).
  EXPECT_NEAR(si.uv.x, 0.5f, 1e-6f);
  EXPECT_NEAR(si.uv.y, 0.3f, 1e-6f);
}

TEST(TriangleMesh, DirectionNeedNotBeUnit) {
  OneShape s(make_mesh(mesh_params(kTriangleZ1)));
  SurfaceInteraction si;
  ASSERT_TRUE(s.scene->intersect(Ray{Vec3(0.2f, 0.3f, -1.f), Vec3(0, 0, 4)}, &si));
  EXPECT_NEAR(si.t, 0.5f, 1e-6f);  // in units of |d|
  EXPECT_NEAR(si.wo.z, -1.f, 1e-6f);
}

TEST(TriangleMesh, RaysOutsideOrParallelMiss) {
  OneShape s(make_mesh(mesh_params(kTriangleZ1)));
  SurfaceInteraction si;
  EXPECT_FALSE(s.scene->intersect(Ray{Vec3(0.6f, 0.6f, -1.f), Vec3(0, 0, 1)}, &si));  // beyond the hypotenuse
  EXPECT_FALSE(s.scene->intersect(Ray{Vec3(-0.01f, 0.5f, -1.f), Vec3(0, 0, 1)}, &si));
  EXPECT_FALSE(s.scene->intersect(Ray{Vec3(-1.f, 0.2f, 1.f), Vec3(1, 0, 0)}, &si));         // in the plane
  EXPECT_FALSE(s.scene->intersect(Ray{Vec3(0.2f, 0.3f, 2.f), Vec3(0, 0, 1)}, &si));         // pointing away
  EXPECT_FALSE(s.scene->intersect(Ray{Vec3(0.2f, 0.3f, -1.f), Vec3(0, 0, 1), 1.9f}, &si));  // tmax short
}

TEST(TriangleMesh, GivenUVsGiveDerivatives) {
  ParameterList pl = mesh_params(kTriangleZ1);
  // uv = 2 * (x, y): dp/du = (0.5, 0, 0), dp/dv = (0, 0.5, 0).
  pl.add(param("point2", "uv", {0, 0, 2, 0, 0, 2}));
  OneShape s(make_mesh(pl));
  SurfaceInteraction si;
  ASSERT_TRUE(s.scene->intersect(Ray{Vec3(0.25f, 0.125f, 3.f), Vec3(0, 0, -1)}, &si));
  EXPECT_NEAR(si.uv.x, 0.5f, 1e-6f);
  EXPECT_NEAR(si.uv.y, 0.25f, 1e-6f);
  EXPECT_NEAR(glm::distance(si.dpdu, Vec3(0.5f, 0, 0)), 0.f, 1e-6f);
  EXPECT_NEAR(glm::distance(si.dpdv, Vec3(0, 0.5f, 0)), 0.f, 1e-6f);
}

float normal_z(const Transform& t, bool reverse) {
  // cross(p0 - p2, p1 - p2) = cross((-1,-2,0), (1,-2,0)) = (0, 0, 4): object normal +z.
  OneShape s(make_mesh(mesh_params({-1, -1, 0, 1, -1, 0, 0, 1, 0}), t, reverse));
  SurfaceInteraction si;
  EXPECT_TRUE(s.scene->intersect(Ray{Vec3(0.f, 0.f, -1.f), Vec3(0, 0, 1)}, &si));
  return si.n.z;
}

TEST(TriangleMesh, ReverseOrientationXorHandednessFlipsNormal) {
  // Object normal +z. A mirror in x keeps the plane and (as a normal transform) keeps +z:
  // pbrt's world-space cross product flips, and the handedness flag flips it back.
  Transform mirror_x = scale(Vec3(-1, 1, 1));
  EXPECT_NEAR(normal_z(Transform(), false), 1.f, 1e-6f);
  EXPECT_NEAR(normal_z(Transform(), true), -1.f, 1e-6f);
  EXPECT_NEAR(normal_z(mirror_x, false), 1.f, 1e-6f);
  EXPECT_NEAR(normal_z(mirror_x, true), -1.f, 1e-6f);
  // A mirror in z maps the object's +z normal to -z.
  EXPECT_NEAR(normal_z(scale(Vec3(1, 1, -1)), false), -1.f, 1e-6f);
}

TEST(TriangleMesh, ShadingNormalsDecideGeometricSide) {
  ParameterList pl = mesh_params({0, 0, 0, 1, 0, 0, 0, 1, 0});
  // Shading normals tilted, all on the -z side: n follows them (pbrt), ns interpolates.
  pl.add(param("normal", "N", {0, 0, -1, 1, 0, -1, 0, 1, -1}));
  OneShape s(make_mesh(pl));
  SurfaceInteraction si;
  ASSERT_TRUE(s.scene->intersect(Ray{Vec3(0.25f, 0.25f, 1.f), Vec3(0, 0, -1)}, &si));
  EXPECT_NEAR(si.n.z, -1.f, 1e-6f);
  // b = (0.5, 0.25, 0.25): ns ~ (0.25, 0.25, -1) normalised.
  Vec3 expect = glm::normalize(Vec3(0.25f, 0.25f, -1.f));
  EXPECT_NEAR(glm::distance(si.ns, expect), 0.f, 1e-6f);
}

TEST(TriangleMesh, ShadingNormalsFlipWithReverseOrientation) {
  ParameterList pl = mesh_params({0, 0, 0, 1, 0, 0, 0, 1, 0});
  pl.add(param("normal", "N", {0, 0, 1, 0, 0, 1, 0, 0, 1}));
  OneShape s(make_mesh(pl, Transform(), true));
  SurfaceInteraction si;
  ASSERT_TRUE(s.scene->intersect(Ray{Vec3(0.25f, 0.25f, 1.f), Vec3(0, 0, -1)}, &si));
  EXPECT_NEAR(si.ns.z, -1.f, 1e-6f);
  EXPECT_NEAR(si.n.z, -1.f, 1e-6f);
}

TEST(TriangleMesh, TransformAppliedToVertices) {
  Transform t = translate(Vec3(10, 0, 0)) * scale(Vec3(2, 2, 2));
  auto mesh = make_mesh(mesh_params({0, 0, 0, 1, 0, 0, 0, 1, 0}), t);
  EXPECT_NEAR(mesh->area(), 2.f, 1e-6f);  // 0.5 * 2^2
  Bounds3 b = mesh->bounds();
  EXPECT_EQ(b.lo, Vec3(10, 0, 0));
  EXPECT_EQ(b.hi, Vec3(12, 2, 0));
}

TEST(TriangleMesh, ThreeVerticesNeedNoIndices) {
  auto mesh = make_mesh(mesh_params(kTriangleZ1));
  EXPECT_EQ(mesh->primitive_count(), 1u);
  EXPECT_NEAR(mesh->area(), 0.5f, 1e-7f);
}

TEST(TriangleMesh, ValidationErrorsNameTheParameter) {
  auto fails = [](ParameterList pl) { return error_of([&] { make_mesh(pl); }); };
  std::vector<double> P4 = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};

  std::string e = fails(mesh_params(P4));
  EXPECT_NE(e.find("\"indices\""), std::string::npos) << e;
  EXPECT_NE(e.find("exactly 3 vertices"), std::string::npos) << e;
  EXPECT_NE(e.find("mesh.pbrt:3:"), std::string::npos) << e;

  e = fails(mesh_params(P4, {0, 1, 2, 0}));
  EXPECT_NE(e.find("\"indices\""), std::string::npos) << e;
  EXPECT_NE(e.find("not a multiple of 3"), std::string::npos) << e;

  e = fails(mesh_params(P4, {0, 1, 4}));
  EXPECT_NE(e.find("\"indices\""), std::string::npos) << e;
  EXPECT_NE(e.find("out of range"), std::string::npos) << e;

  e = fails(mesh_params(P4, {0, 1, -1}));
  EXPECT_NE(e.find("out of range"), std::string::npos) << e;

  ParameterList no_p(SourceLoc{"mesh.pbrt", 3, 1});
  no_p.add(param("integer", "indices", {0, 1, 2}));
  e = fails(std::move(no_p));
  EXPECT_NE(e.find("\"P\""), std::string::npos) << e;

  ParameterList bad_n = mesh_params(P4, {0, 1, 2});
  bad_n.add(param("normal", "N", {0, 0, 1}));
  e = fails(std::move(bad_n));
  EXPECT_NE(e.find("\"N\""), std::string::npos) << e;
  EXPECT_NE(e.find("1 normals given for 4 vertices"), std::string::npos) << e;

  ParameterList bad_uv = mesh_params(P4, {0, 1, 2});
  bad_uv.add(param("point2", "uv", {0, 0, 1, 1}));
  e = fails(std::move(bad_uv));
  EXPECT_NE(e.find("\"uv\""), std::string::npos) << e;

  // Every triangle degenerate: nothing left to render is an error, not an empty shape.
  e = fails(mesh_params({0, 0, 0, 1, 1, 1, 2, 2, 2}));
  EXPECT_NE(e.find("no triangle of nonzero"), std::string::npos) << e;

  ParameterList bad_faces = mesh_params(P4, {0, 1, 2});
  bad_faces.add(param("integer", "faceIndices", {0, 1}));
  e = fails(std::move(bad_faces));
  EXPECT_NE(e.find("\"faceIndices\""), std::string::npos) << e;
}

TEST(TriangleMesh, DegenerateTrianglesDroppedAndCounted) {
  // Second triangle repeats a vertex: zero area.
  ParameterList pl = mesh_params({0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5}, {0, 1, 2, 3, 3, 1});
  int before = warning_count();
  auto shapes = create_trianglemesh_shapes(ShapeContext{pl, Transform(), false, ""});
  auto* mesh = dynamic_cast<TriangleMesh*>(shapes.at(0).get());
  ASSERT_NE(mesh, nullptr);
  EXPECT_EQ(mesh->primitive_count(), 1u);
  EXPECT_EQ(mesh->dropped_triangles(), 1);
  EXPECT_EQ(warning_count(), before + 1);
  EXPECT_NEAR(mesh->area(), 0.5f, 1e-7f);
}

TEST(TriangleMesh, TangentsAndAlphaAreAcceptedAndMarkedUsed) {
  ParameterList pl = mesh_params(kTriangleZ1);
  pl.add(param("vector3", "S", {1, 0, 0, 1, 0, 0, 1, 0, 0}));
  pl.add(param("float", "alpha", {0.5}));
  make_mesh(pl);
  for (const Param& p : pl.params()) EXPECT_TRUE(p.used) << p.name;
}

// Chi-square statistic of observed counts against expected probabilities.
double chi_square(const std::vector<int>& counts, const std::vector<double>& probs, int n) {
  double chi2 = 0.0;
  for (size_t i = 0; i < counts.size(); ++i) {
    double e = probs[i] * n;
    chi2 += (counts[i] - e) * (counts[i] - e) / e;
  }
  return chi2;
}

TEST(TriangleMesh, AreaSamplingPicksTrianglesByArea) {
  // Four disjoint right triangles with legs 1, sqrt2, sqrt3, 2 at x offsets 0, 10, 20, 30:
  // areas 0.5, 1, 1.5, 2 (probabilities 0.1 0.2 0.3 0.4).
  std::vector<double> P, idx;
  double legs[4] = {1.0, std::sqrt(2.0), std::sqrt(3.0), 2.0};
  for (int k = 0; k < 4; ++k) {
    double x0 = 10.0 * k, l = legs[k];
    P.insert(P.end(), {x0, 0, 0, x0 + l, 0, 0, x0, l, 0});
    idx.insert(idx.end(), {3.0 * k, 3.0 * k + 1, 3.0 * k + 2});
  }
  auto mesh = make_mesh(mesh_params(P, idx));
  EXPECT_NEAR(mesh->area(), 5.f, 1e-5f);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> U(0.f, 1.f);
  const int n = 200000;
  std::vector<int> counts(4, 0);
  for (int i = 0; i < n; ++i) {
    ShapeSample s = mesh->sample_area(Vec2(std::min(U(rng), kOneMinusEpsilon), std::min(U(rng), kOneMinusEpsilon)));
    int k = int(std::floor(s.p.x / 10.f));
    ASSERT_TRUE(k >= 0 && k < 4);
    double lx = s.p.x - 10.0 * k;
    EXPECT_TRUE(lx >= -1e-5 && s.p.y >= -1e-5 && lx + s.p.y <= legs[k] + 1e-5);  // inside triangle k
    EXPECT_FLOAT_EQ(s.pdf_area, 1.f / 5.f);
    EXPECT_NEAR(s.n.z, 1.f, 1e-6f);
    ++counts[k];
  }
  // 3 degrees of freedom; the 0.1% critical value is 16.27 (fixed seed: deterministic).
  EXPECT_LT(chi_square(counts, {0.1, 0.2, 0.3, 0.4}, n), 16.27);
}

TEST(TriangleMesh, AreaSamplingIsUniformWithinATriangle) {
  // The midpoints split the triangle into 4 congruent triangles of equal area; classify
  // samples by which one they fall in.
  auto mesh = make_mesh(mesh_params({0, 0, 0, 2, 0, 0, 0, 2, 0}));
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> U(0.f, 1.f);
  const int n = 100000;
  std::vector<int> counts(4, 0);
  for (int i = 0; i < n; ++i) {
    Vec3 p = mesh->sample_area(Vec2(std::min(U(rng), kOneMinusEpsilon), std::min(U(rng), kOneMinusEpsilon))).p;
    int cell = p.x > 1.f ? 0 : p.y > 1.f ? 1 : (p.x + p.y < 1.f ? 2 : 3);
    ++counts[cell];
  }
  EXPECT_LT(chi_square(counts, {0.25, 0.25, 0.25, 0.25}, n), 16.27);  // 3 dof, alpha 0.001
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
