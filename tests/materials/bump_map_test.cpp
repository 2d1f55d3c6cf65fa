// Bump mapping ("texture displacement", pbrt-v4's BumpMap): on a plane displaced by d = a u the
// shading normal is the displaced surface's, ~ dp'/du x dp'/dv = (dpdu + a ns) x dpdv, an
// analytic answer; through the renderer a diffuse plane under a distant light shines with the
// cosine to that normal, on the side pbrt-v4's triangle normal gives.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/render_text.h"
#include "../support/unity_id.h"
#include "core/transform.h"
#include "materials/bump_map.h"
#include "scene/texture_store.h"
#include "textures/bilerp_texture.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

Param number(const std::string& name, double v) {
  Param p;
  p.type = "float";
  p.name = name;
  p.numbers = {v};
  return p;
}

// d = a u + b v as a bilerp texture (v00 = 0, v10 = a, v01 = b, v11 = a + b).
std::unique_ptr<FloatTexture> ramp(float a, float b) {
  ParameterList params;
  params.add(number("v00", 0));
  params.add(number("v10", a));
  params.add(number("v01", b));
  params.add(number("v11", a + b));
  static TextureStore store;
  return create_bilerp_float_texture(TextureContext{params, Transform(), store, ""});
}

SurfaceInteraction plane(Vec3 n) {
  SurfaceInteraction si;
  si.n = si.ns = n;
  si.dpdu = Vec3(2.f, 0.f, 0.f);  // u spans 2 units of x, v 2 units of y
  si.dpdv = Vec3(0.f, 2.f, 0.f);
  si.uv = Vec2(0.4f, 0.6f);
  return si;
}

void expect_near(Vec3 got, Vec3 want, float tol) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], tol) << "component " << i;
}

TEST(BumpMap, APlaneDisplacedLinearlyTiltsItsNormalByTheSlope) {
  for (float a : {0.5f, 2.f, -3.f}) {
    // z' = a u = (a / 2) x: the normal ~ (-a/2, 0, 1).
    const SurfaceInteraction si = apply_bump_map(ramp(a, 0).get(), plane(Vec3(0, 0, 1)));
    expect_near(si.ns, glm::normalize(Vec3(-a / 2, 0, 1)), 2e-4f);
    // Along v likewise: z' = (b / 2) y.
    const SurfaceInteraction sv = apply_bump_map(ramp(0, a).get(), plane(Vec3(0, 0, 1)));
    expect_near(sv.ns, glm::normalize(Vec3(0, -a / 2, 1)), 2e-4f);
  }
  // On a surface whose normal is -z the displacement is along -z: z' = -(a / 2) x, whose normal
  // on the -z side is ~ (-a/2, 0, -1).
  const SurfaceInteraction back = apply_bump_map(ramp(2.f, 0).get(), plane(Vec3(0, 0, -1)));
  expect_near(back.ns, glm::normalize(Vec3(-1, 0, -1)), 2e-4f);
}

TEST(BumpMap, NoTextureOrAConstantOneLeavesTheNormal) {
  const SurfaceInteraction si = plane(Vec3(0, 0, 1));
  expect_near(apply_bump_map(nullptr, si).ns, si.ns, 0.f);
  expect_near(apply_bump_map(ramp(0, 0).get(), si).ns, si.ns, 1e-6f);
}

class NanTexture final : public FloatTexture {
 public:
  float evaluate(const TextureEvalContext&) const override { return std::nanf(""); }
};

TEST(BumpMap, ANonFiniteDisplacementKeepsTheHitsNormal) {
  NanTexture nan;
  const SurfaceInteraction si = apply_bump_map(&nan, plane(Vec3(0, 0, 1)));
  expect_near(si.ns, Vec3(0, 0, 1), 0.f);
  expect_near(si.dpdu, Vec3(2, 0, 0), 0.f);
}

// The mean of the image of a diffuse square (z = 0, seen from +z) lit by a distant light from
// direction `from`, with or without the displacement d = 2 u (normal (-1, 0, 1) / sqrt 2 on the
// +z side, which pbrt-v4 gives this winding: n = normalize((p0 - p2) x (p1 - p2)) = +z).
double lit_plane(Vec3 from, bool bumped) {
  const std::string text = fmt::format(R"(
    LookAt 0 0 5  0 0 0  0 1 0
    Camera "perspective" "float fov" 8
    Film "rgb" "integer xresolution" 8 "integer yresolution" 8
    Sampler "independent" "integer pixelsamples" 4
    Integrator "path" "integer maxdepth" 1
    WorldBegin
    LightSource "distant" "point3 from" [{} {} {}] "point3 to" [0 0 0] "rgb L" [1 1 1]
    Texture "bump" "float" "bilerp" "float v10" 2 "float v01" 0 "float v11" 2
    Material "diffuse" "rgb reflectance" [0.5 0.5 0.5] {}
    Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]
      "point3 P" [-1 -1 0  1 -1 0  1 1 0  -1 1 0] "point2 uv" [0 0  1 0  1 1  0 1]
  )",
                                       from.x, from.y, from.z, bumped ? "\"texture displacement\" \"bump\"" : "");
  return test::image_mean(test::render_text(text, "bump.pbrt"));
}

TEST(BumpMap, ADiffusePlaneShinesWithTheCosineToTheBumpedNormal) {
  const Vec3 left(-1, 0, 1), right(1, 0, 1);
  // Flat: cos 45 degrees from either side. Bumped: the light from the left is along the bumped
  // normal (cos 1), the one from the right grazes it (cos 0).
  const double flat = lit_plane(left, false);
  ASSERT_GT(flat, 0.0);
  EXPECT_NEAR(lit_plane(right, false) / flat, 1.0, 1e-5);
  EXPECT_NEAR(lit_plane(left, true) / flat, std::sqrt(2.0), 1e-4);
  EXPECT_NEAR(lit_plane(right, true) / flat, 0.0, 1e-4);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
