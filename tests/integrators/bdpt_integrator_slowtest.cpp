// bdpt's t = 1 strategies on a caustic (tests/data/pbrt-v4/bdpt-caustic.pbrt at 32 x 32: a point
// light beside a glass sphere over a diffuse floor, seen by a pinhole), against independent
// estimates, on the floor pixels alone (those where the camera sees the floor directly):
// - with the point light replaced by a sphere light of radius 0.2 and the same power, bdpt's
//   floor carries what the path tracer finds (its BSDF-sampled rays hit the light through the
//   glass), within 4 combined standard errors;
// - a sphere light shrunk to radius 0.02 gives the point light's floor (the light's extent moves
//   light by a first-order amount in its radius: +2.8 % at 0.2 in the sppm test, so at 0.02
//   within 0.5 % besides the noise);
// - without t = 1 bdpt misses the point light's caustic, as the path tracer does: its floor is
//   more than 5 % darker (the caustic is about a tenth of the floor's light).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "render/film.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {

const std::string kDataDir = std::string(EYETRACE_SOURCE_DIR) + "/tests/data/pbrt-v4/";

std::string read_scene(const std::string& name) {
  std::ifstream in(kDataDir + name);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::string with_line(const std::string& text, const std::string& prefix, const std::string& line) {
  const size_t at = text.find("\n" + prefix);
  EXPECT_NE(at, std::string::npos) << prefix;
  const size_t end = text.find('\n', at + 1);
  return text.substr(0, at + 1) + line + text.substr(end);
}

Image render(const std::string& text, int spp, uint64_t seed) {
  SceneDescription desc = parse_scene_string(text, "bdpt-slow.pbrt", kDataDir);
  RenderOverrides o;
  o.resolution = IVec2(32, 32);
  o.spp = spp;
  o.seed = seed;
  RenderSetup s = build_render_setup(desc, o);
  RenderCounters counters;
  s.integrator->render(*s.camera, *s.sampler, *s.film, RenderOptions{}, counters);
  EXPECT_EQ(counters.nonfinite_samples.load(), 0u);
  return s.film->image();
}

double masked(const Image& im, const std::vector<bool>& mask) {
  double sum = 0, n = 0;
  for (size_t p = 0; p < mask.size(); ++p) {
    if (!mask[p]) continue;
    for (int c = 0; c < 3; ++c) sum += im.pixels[p * 3 + c] / 3.0;
    n += 1;
  }
  return sum / n;
}

// Two renders that differ only in their seed: the masked mean of their average and its standard
// error, sqrt(sum_p (a1_p - a2_p)^2 / 4) / n ((a1 - a2)^2 / 4 estimates the variance of their
// average in each pixel; pixels taken as independent).
struct MeanAndError {
  double mean = 0, std_error = 0;
};
MeanAndError masked_pair(const Image& a1, const Image& a2, const std::vector<bool>& mask) {
  double var = 0, n = 0;
  for (size_t p = 0; p < mask.size(); ++p) {
    if (!mask[p]) continue;
    double d = 0;
    for (int c = 0; c < 3; ++c) d += (a1.pixels[p * 3 + c] - a2.pixels[p * 3 + c]) / 3.0;
    var += d * d / 4;
    n += 1;
  }
  return {0.5 * (masked(a1, mask) + masked(a2, mask)), std::sqrt(var) / n};
}

TEST(BdptIntegrator, CausticSeenDirectlyCarriesThePowerPathFindsThroughASphereLight) {
  const std::string caustic = read_scene("bdpt-caustic.pbrt");
  const std::string point = "LightSource \"point\" \"point3 from\" [-1.5 2.5 0] \"rgb I\" [10 10 10]";
  // A sphere of radius r and radiance L emits I = pi r^2 L in every direction: the point's power.
  auto sphere = [&](const std::string& text, double r) {
    const double L = 10.0 / (kPiDouble * r * r);
    return replaced(text, point,
                    fmt::format("AttributeBegin\nTranslate -1.5 2.5 0\nAreaLightSource \"diffuse\" \"rgb L\" [{0} {0} "
                                "{0}]\nMaterial \"diffuse\" \"rgb reflectance\" [0 0 0]\nShape \"sphere\" \"float "
                                "radius\" {1}\nAttributeEnd",
                                L, r));
  };
  const std::string path = with_line(caustic, "Integrator", "Integrator \"path\" \"integer maxdepth\" 5");
  // The floor pixels: the floor made an emitter of radiance 1 and the glass black, seen directly.
  std::string floor_text = with_line(caustic, "Integrator", "Integrator \"path\" \"integer maxdepth\" 0");
  floor_text = replaced(floor_text, "Material \"diffuse\" \"rgb reflectance\" [0.7 0.7 0.7]",
                        "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]");
  floor_text = replaced(floor_text, "Material \"dielectric\" \"float eta\" 1.5",
                        "Material \"diffuse\" \"rgb reflectance\" [0 0 0]");
  const Image floor = render(floor_text, 16, 1);
  std::vector<bool> mask(size_t(floor.width) * floor.height);
  for (size_t p = 0; p < mask.size(); ++p) mask[p] = floor.pixels[p * 3 + 1] > 0.999f;

  const MeanAndError path_sphere =
      masked_pair(render(sphere(path, 0.2), 4096, 1), render(sphere(path, 0.2), 4096, 2), mask);
  const MeanAndError bdpt_sphere =
      masked_pair(render(sphere(caustic, 0.2), 256, 1), render(sphere(caustic, 0.2), 256, 2), mask);
  const MeanAndError bdpt_point = masked_pair(render(caustic, 256, 3), render(caustic, 256, 4), mask);
  const MeanAndError bdpt_small =
      masked_pair(render(sphere(caustic, 0.02), 256, 5), render(sphere(caustic, 0.02), 256, 6), mask);
  const std::string without =
      with_line(caustic, "Integrator", "Integrator \"bdpt\" \"integer maxdepth\" 5 \"bool lighttracing\" false");
  const double without_t1 = masked(render(without, 64, 7), mask);
  std::printf(
      "floor means: path sphere 0.2 %.5f +- %.5f, bdpt sphere 0.2 %.5f +- %.5f, bdpt point %.5f +- %.5f, bdpt "
      "sphere 0.02 %.5f +- %.5f, bdpt point without t = 1 %.5f\n",
      path_sphere.mean, path_sphere.std_error, bdpt_sphere.mean, bdpt_sphere.std_error, bdpt_point.mean,
      bdpt_point.std_error, bdpt_small.mean, bdpt_small.std_error, without_t1);
  EXPECT_NEAR(bdpt_sphere.mean, path_sphere.mean, 4 * std::hypot(bdpt_sphere.std_error, path_sphere.std_error));
  EXPECT_NEAR(bdpt_small.mean, bdpt_point.mean,
              4 * std::hypot(bdpt_small.std_error, bdpt_point.std_error) + 0.005 * bdpt_point.mean);
  EXPECT_LT(without_t1, 0.95 * bdpt_point.mean);
}

}  // namespace
}  // namespace eyetrace
