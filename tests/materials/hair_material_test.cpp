// The "hair" material (pbrt-v4's) through the whole renderer, on a quad whose u runs along
// the fibre and v across it:
//  - a white fibre (sigma_a 0) under a uniform sky returns the sky's radiance: the furnace
//    integral of f |cos| is 1 and a flat quad never meets its own scattered light;
//  - absorbing fibres (the default brown, melanins, a reflectance) return less, darker for more
//    melanin; "color" is pbrt-v4's older name of "reflectance" and renders the same;
//  - bad values are errors naming the file, the line and the parameter.
// The BSDF itself is tested in hair_bxdf_test.cpp and bsdf_properties_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../support/render_text.h"
#include "../support/unity_id.h"
#include "core/error.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

struct Mean {
  double value = 0, std_error = 0;
};

// A unit quad facing the camera, u along y and v along x, in a uniform white sky; line 8 holds
// the material. Each pixel's value is the sky's radiance times the fibre's furnace albedo.
Mean furnace(const std::string& material, int spp = 16, const std::string& textures = "") {
  const Image img = test::render_text(fmt::format(R"(LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" 8
Film "rgb" "integer xresolution" 16 "integer yresolution" 16
Sampler "independent" "integer pixelsamples" {}
Integrator "path" "integer maxdepth" 5
WorldBegin {}
LightSource "infinite" "rgb L" [1 1 1]
Material "hair" {}
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-1 -1 0  -1 1 0  1 1 0  1 -1 0]
  "point2 uv" [0 0  1 0  1 1  0 1]
)",
                                                  spp, textures, material),
                                      "hair.pbrt");
  double sum = 0, sum2 = 0;
  for (size_t i = 0; i < img.pixels.size(); i += 3) {
    const double y = (img.pixels[i] + img.pixels[i + 1] + img.pixels[i + 2]) / 3.0;
    sum += y;
    sum2 += y * y;
  }
  const double n = double(img.pixels.size() / 3);
  return {sum / n, std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)) / n)};
}

TEST(HairMaterial, WhiteFibreInAFurnaceReturnsTheSky) {
  const Mean m = furnace(R"("rgb sigma_a" [0 0 0] "float beta_m" 0.4 "float beta_n" 0.5)");
  EXPECT_NEAR(m.value, 1.0, std::max(4 * m.std_error, 1e-3));
  EXPECT_LT(m.std_error, 0.01);
}

TEST(HairMaterial, AbsorptionDarkensInTheOrderOfMelanin) {
  const double brown = furnace("").value;  // pbrt-v4's default: eumelanin 1.3
  EXPECT_GT(brown, 0.05);
  EXPECT_LT(brown, 0.8);
  EXPECT_NEAR(furnace(R"("float eumelanin" 1.3)").value, brown, 1e-6);  // the same text, made explicit
  EXPECT_GT(furnace(R"("float eumelanin" 0.3)").value, brown);
  EXPECT_LT(furnace(R"("float eumelanin" 8)").value, brown);
  // Pheomelanin alone: eumelanin is then 0, not the default.
  EXPECT_GT(furnace(R"("float pheomelanin" 0.3)").value, furnace(R"("float eumelanin" 0.3)").value);
  // sigma_a wins over the melanins (with a warning), as in pbrt-v4.
  EXPECT_NEAR(furnace(R"("rgb sigma_a" [0 0 0] "float eumelanin" 8)").value, 1.0, 0.02);
}

TEST(HairMaterial, ColorIsReflectancesOlderName) {
  const double r = furnace(R"("rgb reflectance" [0.6 0.4 0.2])").value;
  EXPECT_EQ(furnace(R"("rgb color" [0.6 0.4 0.2])").value, r);
  EXPECT_LT(r, 0.99);  // one fibre's albedo: the colour is what many fibres' scattering makes of it
  EXPECT_GT(furnace(R"("rgb reflectance" [0.9 0.9 0.9])").value, r);
}

// Every parameter may be a texture, as in pbrt-v4: constant textures render as the numbers.
TEST(HairMaterial, ParametersMayBeTextures) {
  const std::string textures = R"(Texture "e" "float" "constant" "float value" 0.8
    Texture "b" "float" "constant" "float value" 0.45
    Texture "s" "spectrum" "constant" "rgb value" [0.2 0.4 0.6])";
  EXPECT_EQ(furnace(R"("texture eumelanin" "e" "texture beta_m" "b")", 16, textures).value,
            furnace(R"("float eumelanin" 0.8 "float beta_m" 0.45)").value);
  EXPECT_EQ(furnace(R"("texture sigma_a" "s" "texture eta" "b")", 16, textures).value,
            furnace(R"("rgb sigma_a" [0.2 0.4 0.6] "float eta" 0.45)").value);
}

std::string error_of(const std::string& material) {
  try {
    furnace(material, 1);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(HairMaterial, BadValuesNameFileLineAndParameter) {
  for (const char* bad : {R"("float beta_m" -0.1)", R"("float beta_n" -1)", R"("float eta" 0)", R"("float eta" -1.5)",
                          R"("float eumelanin" -1)", R"("float pheomelanin" -0.5)"}) {
    const std::string e = error_of(bad);
    const std::string name = std::string(bad).substr(7, std::string(bad).find('"', 7) - 7);
    EXPECT_NE(e.find("hair.pbrt:8:"), std::string::npos) << bad << ": " << e;
    EXPECT_NE(e.find("\"" + name + "\""), std::string::npos) << bad << ": " << e;
  }
  const std::string both = error_of(R"("rgb reflectance" [0.5 0.5 0.5] "rgb color" [0.5 0.5 0.5])");
  EXPECT_NE(both.find("hair.pbrt:8:"), std::string::npos) << both;
  EXPECT_NE(both.find("not both"), std::string::npos) << both;
  // pbrt-v4's hair has no bump map: "displacement" is an unknown parameter there too.
  EXPECT_NE(error_of(R"("float displacement" 0.1)").find("displacement"), std::string::npos);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
