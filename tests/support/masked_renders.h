// Shared by the slow tests that compare an integrator's 32 x 32 renders of the pbrt-v4 test scenes
// (tests/data/pbrt-v4) with independent estimates on a subset of the pixels: reading and editing
// the scene text, rendering it, and the mean (and its standard error) over a pixel mask.
#pragma once
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/math.h"
#include "render/film.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace::test {

inline const std::string kPbrtV4DataDir = std::string(EYETRACE_SOURCE_DIR) + "/tests/data/pbrt-v4/";

inline std::string read_pbrt_v4_scene(const std::string& name) {
  std::ifstream in(kPbrtV4DataDir + name);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// `text` with the first occurrence of `from` replaced by `to` (which must be there).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// The line of `text` starting with `prefix`, replaced by `line`.
inline std::string with_line(const std::string& text, const std::string& prefix, const std::string& line) {
  const size_t at = text.find("\n" + prefix);
  EXPECT_NE(at, std::string::npos) << prefix;
  const size_t end = text.find('\n', at + 1);
  return text.substr(0, at + 1) + line + text.substr(end);
}

// The scene text rendered at 32 x 32 with `spp` samples and `seed` (relative files resolve in
// tests/data/pbrt-v4); no sample may be non-finite.
inline Image render_32(const std::string& text, int spp, uint64_t seed) {
  SceneDescription desc = parse_scene_string(text, "masked-render.pbrt", kPbrtV4DataDir);
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

// The mean over the pixels where mask is set (all channels).
inline double masked(const Image& im, const std::vector<bool>& mask) {
  double sum = 0, n = 0;
  for (size_t p = 0; p < mask.size(); ++p) {
    if (!mask[p]) continue;
    for (int c = 0; c < 3; ++c) sum += im.pixels[p * 3 + c] / 3.0;
    n += 1;
  }
  return sum / n;
}

// Two renders that differ only in their seed (independent pixels): the masked mean of their
// average and its standard error, sqrt(sum_p (a1_p - a2_p)^2 / 4) / n, since (a1 - a2)^2 / 4
// estimates the variance of (a1 + a2) / 2 in each pixel.
struct MeanAndError {
  double mean = 0, std_error = 0;
};
inline MeanAndError masked_pair(const Image& a1, const Image& a2, const std::vector<bool>& mask) {
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

// The caustic scenes (bdpt-caustic.pbrt, sppm-caustic.pbrt: a point light beside a glass sphere over
// a diffuse floor) with the point light replaced by a sphere light of radius r and the same power:
// a sphere of radiance L emits I = pi r^2 L in every direction.
inline std::string caustic_with_sphere_light(const std::string& caustic, double r) {
  const double L = 10.0 / (kPiDouble * r * r);
  return replaced(caustic, "LightSource \"point\" \"point3 from\" [-1.5 2.5 0] \"rgb I\" [10 10 10]",
                  fmt::format("AttributeBegin\nTranslate -1.5 2.5 0\nAreaLightSource \"diffuse\" \"rgb L\" [{0} {0} "
                              "{0}]\nMaterial \"diffuse\" \"rgb reflectance\" [0 0 0]\nShape \"sphere\" \"float "
                              "radius\" {1}\nAttributeEnd",
                              L, r));
}

// The caustic scene's pixels that see the floor directly: the floor made an emitter of radiance 1
// and the glass black, rendered without bounces.
inline std::vector<bool> caustic_floor_pixels(const std::string& caustic) {
  std::string text = with_line(caustic, "Integrator", "Integrator \"path\" \"integer maxdepth\" 0");
  text = replaced(text, "Material \"diffuse\" \"rgb reflectance\" [0.7 0.7 0.7]",
                  "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]");
  text =
      replaced(text, "Material \"dielectric\" \"float eta\" 1.5", "Material \"diffuse\" \"rgb reflectance\" [0 0 0]");
  const Image floor = render_32(text, 16, 1);
  std::vector<bool> mask(size_t(floor.width) * floor.height);
  for (size_t p = 0; p < mask.size(); ++p) mask[p] = floor.pixels[p * 3 + 1] > 0.999f;
  return mask;
}

}  // namespace eyetrace::test
