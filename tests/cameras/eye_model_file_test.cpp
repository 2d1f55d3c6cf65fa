// An eye model is one data file: a model written to a temporary file and registered at run
// time is built, analysed and rendered like the embedded ones, and a malformed model file is
// an error naming the file and the field.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "../support/unity_id.h"
#include "optics/embedded_data.h"
#include "optics/eye_models.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

namespace fs = std::filesystem;

// Navarro's data file with another name and a steeper anterior cornea (7.5 mm for 7.72 mm).
std::string steep_cornea_model(const std::string& name) {
  nlohmann::json j = nlohmann::json::parse(embedded::files().at("navarro.json"));
  j["model"] = name;
  j["surfaces"][0]["radius_mm"] = 7.5;
  return j.dump(2);
}

fs::path write_temp(const std::string& file_name, const std::string& text) {
  const fs::path path = fs::temp_directory_path() / file_name;
  std::ofstream(path) << text;
  return path;
}

Image render_with(const std::string& camera) {
  SceneDescription desc = parse_scene_file(std::string(EYETRACE_SOURCE_DIR) + "/scenes/peripheral.pbrt");
  RenderOverrides o;
  o.camera = parse_directive_text(camera, "Camera", "<test>");
  o.resolution = IVec2(24, 16);
  o.spp = 4;
  o.seed = 1;
  RenderSetup s = build_render_setup(desc, o);
  RenderCounters counters;
  s.integrator->render(*s.camera, *s.sampler, *s.film, RenderOptions{}, counters);
  return s.film->image();
}

TEST(EyeModelFile, RegisteredModelIsBuiltAnalysedAndRendered) {
  const fs::path path = write_temp("eyetrace-steep-cornea.json", steep_cornea_model("steep-cornea"));
  optics::register_eye_model_file(path.string());
  fs::remove(path);

  // The file's optics equal Navarro's prescription with the same change made in code.
  optics::EyeOptions o;
  o.model = "navarro";
  optics::Prescription expected = optics::make_eye(o);
  expected.surfaces[0].profile = optics::SurfaceProfile::from_radius(7.5, expected.surfaces[0].profile.conic);
  o.model = "steep-cornea";
  const optics::Prescription loaded = optics::make_eye(o);
  EXPECT_NEAR(optics::refraction_D(loaded), optics::refraction_D(expected), 1e-12);
  // A thin cornea in air: its power rises by (1.376 - 1)(1/7.5 - 1/7.72) mm^-1 = 1.43 D, and the
  // eye's refraction falls by about that much (less the effectivity of the 0.55 mm cornea and
  // the aqueous: within 0.2 D).
  const double delta_power = (1.376 - 1.0) * (1.0 / 7.5 - 1.0 / 7.72) * 1000.0;
  o.model = "navarro";
  EXPECT_NEAR(optics::refraction_D(loaded) - optics::refraction_D(optics::make_eye(o)), -delta_power, 0.2);
  // Its accommodation law comes from the file like everything else.
  EXPECT_EQ(optics::max_accommodation_D("steep-cornea"), optics::max_accommodation_D("navarro"));

  const Image steep = render_with(R"(Camera "eye" "string model" "steep-cornea" "float fov" 40)");
  const Image navarro = render_with(R"(Camera "eye" "string model" "navarro" "float fov" 40)");
  double difference = 0.0;
  for (size_t i = 0; i < steep.pixels.size(); ++i) {
    ASSERT_TRUE(std::isfinite(steep.pixels[i]));
    difference += std::abs(steep.pixels[i] - navarro.pixels[i]);
  }
  EXPECT_GT(difference, 0.0) << "the steeper cornea must change the image";
}

TEST(EyeModelFile, MalformedFilesAreErrorsNamingFileAndField) {
  nlohmann::json j = nlohmann::json::parse(steep_cornea_model("bad-law"));
  j["accommodation"]["law"] = "quadratic-guess";
  fs::path path = write_temp("eyetrace-bad-law.json", j.dump());
  try {
    optics::register_eye_model_file(path.string());
    ADD_FAILURE() << "an unknown accommodation law must be refused";
  } catch (const optics::OpticsError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(path.string()), std::string::npos) << m;
    EXPECT_NE(m.find("accommodation: unknown accommodation law 'quadratic-guess'"), std::string::npos) << m;
  }
  j.erase("accommodation");
  std::ofstream(path) << j.dump();
  EXPECT_THROW(optics::register_eye_model_file(path.string()), optics::OpticsError);
  fs::remove(path);
  // A model that exists already cannot be defined twice.
  path = write_temp("eyetrace-second-navarro.json", embedded::files().at("navarro.json"));
  EXPECT_THROW(optics::register_eye_model_file(path.string()), optics::OpticsError);
  fs::remove(path);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
