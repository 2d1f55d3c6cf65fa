// The "diffuse" material: Lambertian f = R / pi, cosine sampling pdf = cos / pi, parameters
// read the pbrt-v4 way, and the light-leak guard of the shading frame.
#include <gtest/gtest.h>

#include <unistd.h>
#include "../support/spectral.h"
#include "../support/unity_id.h"

#include <filesystem>

#include "core/arena.h"
#include "materials/diffuse_material.h"
#include "materials/interface_material.h"
#include "render/image_io.h"
#include "scene/texture_store.h"
#include "textures/constant_texture.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

SampledWavelengths g_lambda = test::wavelengths();

Param rgb_param(const std::string& name, RGB v) {
  Param p;
  p.type = "rgb";
  p.name = name;
  p.numbers = {v.r, v.g, v.b};
  return p;
}

SurfaceInteraction hit(Vec3 ns = Vec3(0.f, 0.f, 1.f)) {
  SurfaceInteraction si;
  si.n = Vec3(0.f, 0.f, 1.f);
  si.ns = glm::normalize(ns);
  si.dpdu = Vec3(1.f, 0.f, 0.f);
  si.dpdv = Vec3(0.f, 1.f, 0.f);
  return si;
}

TEST(DiffuseMaterial, LambertianValueAndPdf) {
  ParameterList params;
  params.add(rgb_param("reflectance", RGB(0.2f, 0.5f, 0.9f)));
  TextureStore store;
  auto m = create_diffuse_material(MaterialContext{params, store, ""});
  ScratchBuffer arena;
  const BSDF* b = m->bsdf(hit(), g_lambda, arena);
  Vec3 wo = glm::normalize(Vec3(0.3f, -0.2f, 0.9f));
  for (float theta : {0.f, 0.4f, 1.0f, 1.5f}) {
    Vec3 wi(std::sin(theta), 0.f, std::cos(theta));
    SampledSpectrum f = b->f(wo, wi), e = test::albedo(RGB(0.2f, 0.5f, 0.9f), g_lambda) / kPi;
    for (int c = 0; c < kSpectrumSamples; ++c) EXPECT_NEAR(f[c], e[c], 1e-7f);
    EXPECT_NEAR(b->pdf(wo, wi), std::cos(theta) / kPi, 1e-7f);
  }
  EXPECT_TRUE(b->f(wo, Vec3(0.f, 0.6f, -0.8f)).is_black());  // no transmission
  EXPECT_EQ(b->flags(), unsigned(kReflection | kDiffuse));
}

TEST(DiffuseMaterial, SampleWeightIsReflectance) {
  ParameterList params;
  TextureStore store;
  auto m = create_diffuse_material(MaterialContext{params, store, ""});
  ScratchBuffer arena;
  const BSDF* b = m->bsdf(hit(), g_lambda, arena);
  Vec3 wo = glm::normalize(Vec3(0.1f, 0.4f, 0.5f));
  for (float u : {0.1f, 0.37f, 0.8f}) {
    auto s = b->sample_f(wo, 0.5f, Vec2(u, 1.f - u));
    ASSERT_TRUE(s);
    SampledSpectrum w = s->f * std::abs(s->wi.z) / s->pdf;
    for (int c = 0; c < kSpectrumSamples; ++c) EXPECT_NEAR(w[c], 0.5f, 1e-4f);  // pbrt-v4's default reflectance
  }
}

TEST(DiffuseMaterial, TwoSided) {
  ParameterList params;
  TextureStore store;
  auto m = create_diffuse_material(MaterialContext{params, store, ""});
  ScratchBuffer arena;
  const BSDF* b = m->bsdf(hit(), g_lambda, arena);
  Vec3 wo(0.f, 0.f, -1.f), wi = glm::normalize(Vec3(0.5f, 0.f, -1.f));
  EXPECT_NEAR(b->f(wo, wi)[0], 0.5f / kPi, 1e-4f);
  auto s = b->sample_f(wo, 0.5f, Vec2(0.3f, 0.6f));
  ASSERT_TRUE(s);
  EXPECT_LT(s->wi.z, 0.f);
}

TEST(DiffuseMaterial, NamedTextureReflectance) {
  ParameterList params;
  Param p;
  p.type = "texture";
  p.name = "reflectance";
  p.strings = {"red"};
  params.add(p);
  TextureStore store;
  store.add_spectrum("red", std::make_unique<ConstantSpectrumTexture>(RGB(0.7f, 0.f, 0.f)), SourceLoc{});
  auto m = create_diffuse_material(MaterialContext{params, store, ""});
  ScratchBuffer arena;
  const BSDF* b = m->bsdf(hit(), g_lambda, arena);
  SampledSpectrum f = b->f(Vec3(0.f, 0.f, 1.f), Vec3(0.f, 0.f, 1.f)), e = test::albedo(RGB(0.7f, 0.f, 0.f), g_lambda);
  for (int c = 0; c < kSpectrumSamples; ++c) EXPECT_NEAR(f[c], e[c] / kPi, 1e-7f);
}

TEST(LocalBsdf, NoLightLeaksWhereShadingAndGeometryDisagree) {
  // Shading normal tilted 30 degrees: a direction just above the geometric surface can be
  // below the shading hemisphere. Such a pair counts for neither side.
  ParameterList params;
  TextureStore store;
  auto m = create_diffuse_material(MaterialContext{params, store, ""});
  ScratchBuffer arena;
  const BSDF* b = m->bsdf(hit(Vec3(std::sin(0.5f), 0.f, std::cos(0.5f))), g_lambda, arena);
  Vec3 wo(0.f, 0.f, 1.f);
  Vec3 wi_geo_below = glm::normalize(Vec3(1.f, 0.f, -0.1f));  // below n, above ns
  Vec3 wi_ok = glm::normalize(Vec3(0.2f, 0.1f, 1.f));
  EXPECT_TRUE(b->f(wo, wi_geo_below).is_black());
  EXPECT_GT(b->f(wo, wi_ok)[0], 0.f);
  // Sampling never returns a direction on the other geometric side.
  for (int i = 0; i < 64; ++i) {
    auto s = b->sample_f(Vec3(-0.9f, 0.f, 0.436f), 0.5f, Vec2((i + 0.5f) / 64.f, 0.5f));
    if (s) EXPECT_GT(s->wi.z, 0.f);
  }
}

TEST(DiffuseMaterial, NormalMapTiltsTheShadingNormal) {
  // A 1x1 float image c = (0.8, 0.5, 0.9) encodes the tangent-space normal 2c - 1 =
  // (0.6, 0, 0.8): tilted towards +u (dpdu = +x) by acos(0.8).
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("eyetrace_normalmap_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  Image texel;
  texel.width = texel.height = 1;
  texel.pixels = {0.8f, 0.5f, 0.9f};
  write_image((dir / "n.exr").string(), texel);

  ParameterList params;
  Param p;
  p.type = "string";
  p.name = "normalmap";
  p.strings = {"n.exr"};
  params.add(p);
  TextureStore store;
  auto m = create_diffuse_material(MaterialContext{params, store, dir.string()});
  ScratchBuffer arena;
  const BSDF* b = m->bsdf(hit(), g_lambda, arena);
  Vec3 wo(0.f, 0.f, 1.f);
  EXPECT_NEAR(b->pdf(wo, Vec3(0.6f, 0.f, 0.8f)), 1.f / kPi, 1e-5f);
  EXPECT_NEAR(b->pdf(wo, Vec3(0.f, 0.f, 1.f)), 0.8f / kPi, 1e-5f);
  // The integrator multiplies f by the cosine to the hit's own normal (+z); the product is
  // the Lambertian integrand about the mapped normal: 0.5 / pi * cos(wi, mapped).
  Vec3 wi(0.6f, 0.f, 0.8f);
  EXPECT_NEAR(b->f(wo, wi)[0] * wi.z, 0.5f / kPi * 1.f, 1e-5f);
  auto s = b->sample_f(wo, 0.5f, Vec2(0.3f, 0.7f));
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->f[0] * std::abs(s->wi.z) / s->pdf, 0.5f, 1e-4f);

  ParameterList missing;
  p.strings = {"absent.exr"};
  missing.add(p);
  try {
    create_diffuse_material(MaterialContext{missing, store, dir.string()});
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("\"normalmap\""), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("absent.exr"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(InterfaceMaterial, HasNoBsdf) {
  ParameterList params;
  TextureStore store;
  auto m = create_interface_material(MaterialContext{params, store, ""});
  ASSERT_NE(m, nullptr);
  ScratchBuffer arena;
  EXPECT_EQ(m->bsdf(hit(), g_lambda, arena), nullptr);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
