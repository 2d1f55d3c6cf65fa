// The "conductor" material: complex Fresnel per channel, pbrt-v4's parameter forms.
#include <gtest/gtest.h>

#include "core/arena.h"
#include "materials/conductor_material.h"
#include "scene/spectrum_param.h"
#include "scene/texture_store.h"

namespace eyetrace {
namespace {

SurfaceInteraction hit() {
  SurfaceInteraction si;
  si.n = si.ns = Vec3(0.f, 0.f, 1.f);
  return si;
}

Param param(const std::string& type, const std::string& name, std::vector<double> numbers,
            std::vector<std::string> strings = {}) {
  Param p;
  p.type = type;
  p.name = name;
  p.loc = SourceLoc{"metal.pbrt", 9, 1};
  p.numbers = std::move(numbers);
  p.strings = std::move(strings);
  return p;
}

// Reflectance of a smooth conductor seen along the normal: the specular sample's weight.
RGB normal_reflectance(const ParameterList& p) {
  TextureStore store;
  auto m = create_conductor_material(MaterialContext{p, store, ""});
  ScratchBuffer arena;
  const BSDF* b = m->bsdf(hit(), arena);
  auto s = b->sample_f(Vec3(0.f, 0.f, 1.f), 0.5f, Vec2(0.5f));
  EXPECT_TRUE(s && s->is_specular());
  return s ? s->f * std::abs(s->wi.z) / s->pdf : RGB(-1.f);
}

RGB expected_f0(RGB n, RGB k) { return ((n - 1.f) * (n - 1.f) + k * k) / ((n + 1.f) * (n + 1.f) + k * k); }

TEST(ConductorMaterial, NormalIncidenceReflectance) {
  ParameterList p;
  p.add(param("rgb", "eta", {0.2, 0.9, 1.1}));
  p.add(param("rgb", "k", {3.9, 2.4, 2.1}));
  RGB r = normal_reflectance(p), e = expected_f0(RGB(0.2f, 0.9f, 1.1f), RGB(3.9f, 2.4f, 2.1f));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(r[c], e[c], 1e-5f);
}

TEST(ConductorMaterial, DefaultsToCopper) {
  ParameterList p;
  Param eta = param("spectrum", "eta", {}, {"metal-Cu-eta"}), k = param("spectrum", "k", {}, {"metal-Cu-k"});
  RGB r = normal_reflectance(p), e = expected_f0(spectrum_param_to_rgb(eta), spectrum_param_to_rgb(k));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(r[c], e[c], 1e-5f);
  EXPECT_GT(r.r, r.g);
  EXPECT_GT(r.g, r.b);
}

TEST(ConductorMaterial, ReflectanceParameterGivesThatNormalReflectance) {
  ParameterList p;
  p.add(param("rgb", "reflectance", {0.9, 0.5, 0.1}));
  RGB r = normal_reflectance(p);
  EXPECT_NEAR(r.r, 0.9f, 1e-4f);
  EXPECT_NEAR(r.g, 0.5f, 1e-4f);
  EXPECT_NEAR(r.b, 0.1f, 1e-4f);
}

TEST(ConductorMaterial, ReflectanceAndEtaTogetherIsAnError) {
  ParameterList p;
  p.add(param("rgb", "reflectance", {0.9, 0.5, 0.1}));
  p.add(param("spectrum", "eta", {}, {"metal-Au-eta"}));
  TextureStore store;
  try {
    create_conductor_material(MaterialContext{p, store, ""});
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("metal.pbrt:9:1"), std::string::npos) << e.what();
  }
}

TEST(ConductorMaterial, GrazingReflectanceApproachesOne) {
  ParameterList p;
  TextureStore store;
  auto m = create_conductor_material(MaterialContext{p, store, ""});
  ScratchBuffer arena;
  const BSDF* b = m->bsdf(hit(), arena);
  Vec3 wo(std::sin(1.56f), 0.f, std::cos(1.56f));
  auto s = b->sample_f(wo, 0.5f, Vec2(0.5f));
  ASSERT_TRUE(s);
  RGB r = s->f * std::abs(s->wi.z) / s->pdf;
  for (int c = 0; c < 3; ++c) EXPECT_GT(r[c], 0.95f);
}

}  // namespace
}  // namespace eyetrace
