// Scene pieces and a renderer shared by the volumetric path tracer's tests
// (tests/integrators/volpath_test.cpp, volpath_grid_test.cpp): statistical tests at 5 standard
// errors whose pixels are independent samples of one expected value ("independent" sampler, box
// filter).
#pragma once
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "render_text.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace::test {

struct VolpathStats {
  std::vector<double> mean, se;  // per channel: image mean and its standard error
};

// Renders the scene text and checks that no sample or pixel is NaN or infinite.
inline VolpathStats render_volpath_stats(const std::string& text, const std::string& filename) {
  RenderSetup s = build_render_setup(parse_scene_string(text, filename, "."), {});
  RenderCounters counters;
  RenderOptions opts;
  s.integrator->render(*s.camera, *s.sampler, *s.film, opts, counters);
  EXPECT_EQ(counters.nonfinite_samples.load(), 0u);
  const Image img = s.film->image();
  for (float v : img.pixels) EXPECT_TRUE(std::isfinite(v));
  VolpathStats st;
  for (int c = 0; c < img.channels; ++c) {
    const MeanAndError e = channel_mean_and_error(img, c);
    st.mean.push_back(e.mean);
    st.se.push_back(e.std_error);
  }
  return st;
}

// A camera 5 units from the origin with a field of view of 0.2 degrees: every ray crosses a
// sphere of radius 0.5 at the origin within 0.01 % of its diameter.
inline std::string narrow_view(const std::string& film, int spp) {
  return fmt::format(R"(LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" 0.2
{}
Sampler "independent" "integer pixelsamples" {}
PixelFilter "box"
Integrator "volpath" "integer maxdepth" 5
)",
                     film, spp);
}

inline const std::string kSpectralFilm =
    "Film \"spectral\" \"integer xresolution\" 16 \"integer yresolution\" 16 \"integer nbuckets\" 3 "
    "\"float lambdamin\" 400 \"float lambdamax\" 700";
// 0.5 over 400-500 nm, 1.5 over 500-600 nm, 3 over 600-700 nm: one value per film bucket.
inline const std::string kStepSpectrum = "[400 0.5 499.99 0.5 500.01 1.5 599.99 1.5 600.01 3 700 3]";
inline constexpr double kStep[3] = {0.5, 1.5, 3.0};

// A sphere that only bounds media: `inside` within, `outside` around it.
inline std::string ball(const std::string& inside, const std::string& outside, float radius) {
  return fmt::format(
      "AttributeBegin\n MediumInterface \"{}\" \"{}\"\n Material \"interface\"\n Shape \"sphere\" \"float radius\" "
      "{}\nAttributeEnd\n",
      inside, outside, radius);
}

}  // namespace eyetrace::test
