// TextureStore: constants and named textures behind one lookup, and the errors for
// references that do not resolve.
#include <gtest/gtest.h>

#include "../support/spectral.h"
#include "../support/unity_id.h"

#include "scene/texture_store.h"
#include "textures/constant_texture.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

Param param(const std::string& type, const std::string& name, std::vector<double> v, std::vector<std::string> s = {}) {
  Param p;
  p.type = type;
  p.name = name;
  p.loc = SourceLoc{"store.pbrt", 2, 4};
  p.numbers = std::move(v);
  p.strings = std::move(s);
  return p;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(TextureStore, ConstantsAndDefaults) {
  TextureStore store;
  ParameterList p;
  p.add(param("float", "roughness", {0.25}));
  p.add(param("rgb", "reflectance", {0.1, 0.2, 0.3}));
  p.add(param("spectrum", "k", {0.5}));
  EXPECT_EQ(store.float_param(p, "roughness", 0.f)->evaluate({}), 0.25f);
  EXPECT_EQ(store.float_param(p, "thickness", 0.01f)->evaluate({}), 0.01f);
  EXPECT_EQ(store.float_param_or_null(p, "uroughness"), nullptr);
  const SampledWavelengths l = test::wavelengths();
  EXPECT_TRUE(test::same(store.spectrum_param(p, "reflectance", RGB(0.5f))->evaluate({}, l),
                         test::albedo(RGB(0.1f, 0.2f, 0.3f), l), 0.f));
  EXPECT_TRUE(test::same(store.spectrum_param(p, "k", RGB(0.f))->evaluate({}, l), SampledSpectrum(0.5f), 1e-4f));
  EXPECT_TRUE(test::same(store.spectrum_param(p, "albedo", RGB(0.7f))->evaluate({}, l), SampledSpectrum(0.7f), 1e-4f));
  EXPECT_EQ(store.spectrum_param_or_null(p, "eta"), nullptr);
  for (const auto& q : p.params()) EXPECT_TRUE(q.used) << q.name;
}

TEST(TextureStore, NamedTextures) {
  TextureStore store;
  store.add_float("bumps", std::make_unique<ConstantFloatTexture>(0.3f), SourceLoc{});
  store.add_spectrum("paint", std::make_unique<ConstantSpectrumTexture>(RGB(0.9f, 0.1f, 0.1f)), SourceLoc{});
  ParameterList p;
  p.add(param("texture", "roughness", {}, {"bumps"}));
  p.add(param("texture", "reflectance", {}, {"paint"}));
  p.add(param("texture", "albedo", {}, {"bumps"}));
  EXPECT_EQ(store.float_param(p, "roughness", 0.f), store.named_float("bumps"));
  EXPECT_EQ(store.spectrum_param(p, "reflectance", RGB(0.f)), store.named_spectrum("paint"));
  // A float texture where a spectrum is wanted: grey.
  EXPECT_TRUE(test::same(store.spectrum_param(p, "albedo", RGB(0.f))->evaluate({}, test::wavelengths()),
                         SampledSpectrum(0.3f), 0.f));
  EXPECT_EQ(store.named_float("nothing"), nullptr);
}

TEST(TextureStore, UnknownTextureSuggestsAName) {
  TextureStore store;
  store.add_float("bumps", std::make_unique<ConstantFloatTexture>(0.3f), SourceLoc{});
  ParameterList p;
  p.add(param("texture", "roughness", {}, {"bumsp"}));
  std::string e = error_of([&] { store.float_param(p, "roughness", 0.f); });
  EXPECT_NE(e.find("store.pbrt:2:4"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean \"bumps\""), std::string::npos) << e;
}

TEST(TextureStore, SpectrumTextureIsNotAFloat) {
  TextureStore store;
  store.add_spectrum("paint", std::make_unique<ConstantSpectrumTexture>(RGB(1.f)), SourceLoc{});
  ParameterList p;
  p.add(param("texture", "roughness", {}, {"paint"}));
  EXPECT_NE(error_of([&] { store.float_param(p, "roughness", 0.f); }).find("spectrum texture"), std::string::npos);
}

TEST(TextureStore, RedefinitionIsAnError) {
  TextureStore store;
  store.add_float("a", std::make_unique<ConstantFloatTexture>(1.f), SourceLoc{});
  EXPECT_THROW(store.add_float("a", std::make_unique<ConstantFloatTexture>(2.f), SourceLoc{"s.pbrt", 7, 1}),
               SceneError);
}

TEST(TextureStore, WrongParameterTypeIsAnError) {
  TextureStore store;
  ParameterList p;
  p.add(param("rgb", "roughness", {1, 1, 1}));
  EXPECT_THROW(store.float_param(p, "roughness", 0.f), SceneError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
