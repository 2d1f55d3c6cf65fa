// Renders scene text through the whole renderer (parser, builder, integrator, film) and returns
// the film's image, and the image means the render-level tests compare with analytic values.
#pragma once
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "render/film.h"
#include "render/image_io.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace::test {

inline Image render_text(const std::string& text, const std::string& name = "test.pbrt") {
  SceneDescription desc = parse_scene_string(text, name, ".");
  RenderSetup s = build_render_setup(desc, {});
  RenderCounters counters;
  s.integrator->render(*s.camera, *s.sampler, *s.film, RenderOptions{}, counters);
  EXPECT_EQ(counters.nonfinite_samples.load(), 0u);
  return s.film->image();
}

// The mean of every value of the image (all channels).
inline double image_mean(const Image& img) {
  double sum = 0;
  for (float v : img.pixels) sum += v;
  return sum / double(img.pixels.size());
}

// The mean of channel c over columns [x0, x1) (x1 < 0: to the right edge).
inline double channel_mean(const Image& img, int c, int x0 = 0, int x1 = -1) {
  if (x1 < 0) x1 = img.width;
  double sum = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = x0; x < x1; ++x) sum += img.at(x, y, c);
  return sum / (double(x1 - x0) * img.height);
}

// Channel c's mean over every pixel and that mean's standard error, from the pixels' spread
// (for tests whose pixels are independent estimates of one value).
struct MeanAndError {
  double mean = 0, std_error = 0;
};
inline MeanAndError channel_mean_and_error(const Image& img, int c) {
  const double n = double(img.width) * img.height;
  double sum = 0, sum2 = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const double v = img.at(x, y, c);
      sum += v;
      sum2 += v * v;
    }
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1))};
}

}  // namespace eyetrace::test
