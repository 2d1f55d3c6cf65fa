// The "conductor" material: complex Fresnel per channel, pbrt-v4's parameter forms.
#include <gtest/gtest.h>

#include "../support/spectral.h"
#include "../support/unity_id.h"

#include "core/arena.h"
#include "materials/conductor_material.h"
#include "scene/spectrum_param.h"
#include "scene/texture_store.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

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
// At the test wavelengths (about 494, 559, 635, 398 nm).
SampledSpectrum normal_reflectance(const ParameterList& p) {
  TextureStore store;
  auto m = create_conductor_material(MaterialContext{p, store, ""});
  ScratchBuffer arena;
  SampledWavelengths lambda = test::wavelengths();
  const BSDF* b = m->bsdf(hit(), lambda, arena);
  auto s = b->sample_f(Vec3(0.f, 0.f, 1.f), 0.5f, Vec2(0.5f));
  EXPECT_TRUE(s && s->is_specular());
  return s ? s->f * std::abs(s->wi.z) / s->pdf : SampledSpectrum(-1.f);
}

SampledSpectrum expected_f0(SampledSpectrum n, SampledSpectrum k) {
  SampledSpectrum r;
  for (int c = 0; c < kSpectrumSamples; ++c)
    r[c] = ((n[c] - 1.f) * (n[c] - 1.f) + k[c] * k[c]) / ((n[c] + 1.f) * (n[c] + 1.f) + k[c] * k[c]);
  return r;
}

// A named spectrum at the test wavelengths, straight from its table.
SampledSpectrum named_at(const char* name) {
  SampledSpectrum s;
  for (int c = 0; c < kSpectrumSamples; ++c)
    s[c] = evaluate_named_spectrum(*find_named_spectrum(name), test::wavelengths()[c]);
  return s;
}

TEST(ConductorMaterial, NormalIncidenceReflectance) {
  ParameterList p;
  p.add(param("rgb", "eta", {0.2, 0.9, 1.1}));
  p.add(param("rgb", "k", {3.9, 2.4, 2.1}));
  const SampledWavelengths l = test::wavelengths();
  const auto unbounded = [&](RGB c) { return Spectrum::from_rgb(c, SpectrumType::Unbounded).sample(l); };
  SampledSpectrum r = normal_reflectance(p),
                  e = expected_f0(unbounded(RGB(0.2f, 0.9f, 1.1f)), unbounded(RGB(3.9f, 2.4f, 2.1f)));
  for (int c = 0; c < kSpectrumSamples; ++c) EXPECT_NEAR(r[c], e[c], 1e-5f);
}

TEST(ConductorMaterial, DefaultsToCopper) {
  ParameterList p;
  SampledSpectrum r = normal_reflectance(p), e = expected_f0(named_at("metal-Cu-eta"), named_at("metal-Cu-k"));
  for (int c = 0; c < kSpectrumSamples; ++c) EXPECT_NEAR(r[c], e[c], 1e-5f);
  EXPECT_GT(r[2], r[1]);  // copper reflects red (635 nm) more than green (559 nm)
  EXPECT_GT(r[1], r[3]);  // and green more than violet (398 nm)
}

TEST(ConductorMaterial, ReflectanceParameterGivesThatNormalReflectance) {
  ParameterList p;
  p.add(param("rgb", "reflectance", {0.9, 0.5, 0.1}));
  SampledSpectrum r = normal_reflectance(p), e = test::albedo(RGB(0.9f, 0.5f, 0.1f), test::wavelengths());
  for (int c = 0; c < kSpectrumSamples; ++c) EXPECT_NEAR(r[c], e[c], 1e-4f);
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
  SampledWavelengths lambda = test::wavelengths();
  const BSDF* b = m->bsdf(hit(), lambda, arena);
  Vec3 wo(std::sin(1.56f), 0.f, std::cos(1.56f));
  auto s = b->sample_f(wo, 0.5f, Vec2(0.5f));
  ASSERT_TRUE(s);
  SampledSpectrum r = s->f * std::abs(s->wi.z) / s->pdf;
  for (int c = 0; c < kSpectrumSamples; ++c) EXPECT_GT(r[c], 0.95f);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
