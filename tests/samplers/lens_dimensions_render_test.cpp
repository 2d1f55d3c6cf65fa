// Joint lens dimensions change which samples a pixel gets, not what it converges to: the
// figure scene through the Navarro eye, rendered with joint and with padded (pbrt-v4) lens
// dimensions, agrees within the sampling noise that each mode's own seed-to-seed scatter
// measures. The same statistic separates an image that really differs (1 D accommodation),
// so the test can fail.
#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

Image render(const std::string& lens_dimensions, uint64_t seed, double accommodation = 0) {
  SceneDescription desc = parse_scene_file(std::string(EYETRACE_SOURCE_DIR) + "/scenes/peripheral.pbrt");
  desc.sampler = parse_directive_text(
      "Sampler \"zsobol\" \"integer pixelsamples\" 64 \"string lensdimensions\" \"" + lens_dimensions + "\"", "Sampler",
      "test");
  RenderOverrides o;
  // The centre of a 480x320 view (96x64 pixels): fine enough that 1 D of defocus shows.
  o.resolution = IVec2(480, 320);
  o.crop = Vec4(0.4f, 0.6f, 0.4f, 0.6f);
  o.seed = seed;
  o.camera = parse_directive_text(
      "Camera \"navarro\" \"float pupildiameter\" 5 \"float fov\" 50 \"float wavelength\" 589.3 "
      "\"float accommodation\" " +
          std::to_string(accommodation),
      "Camera", "test");
  RenderSetup s = build_render_setup(desc, o);
  RenderCounters counters;
  RenderOptions opts;
  opts.threads = 2;
  s.integrator->render(*s.camera, *s.sampler, *s.film, opts, counters);
  return s.film->image();
}

// Mean squared difference per pixel channel between two images.
double msd(const Image& a, const Image& b) {
  double sum = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) sum += double(a.pixels[i] - b.pixels[i]) * (a.pixels[i] - b.pixels[i]);
  return sum / double(a.pixels.size());
}

Image mean(const Image& a, const Image& b) {
  Image m = a;
  for (size_t i = 0; i < m.pixels.size(); ++i) m.pixels[i] = 0.5f * (a.pixels[i] + b.pixels[i]);
  return m;
}

TEST(LensDimensions, JointAndPaddedConvergeToTheSameImage) {
  const Image j1 = render("joint", 1), j2 = render("joint", 2);
  const Image p1 = render("padded", 1), p2 = render("padded", 2);
  // Each mode's mean of two seeds has noise variance msd(x1, x2) / 4 per pixel channel; the
  // difference of the two means has the sum. Unbiased modes give a ratio near 1 (the pixels'
  // noise is not independent under one scrambling seed, hence the factor 2 of slack).
  const double noise = msd(j1, j2) / 4 + msd(p1, p2) / 4;
  const double between = msd(mean(j1, j2), mean(p1, p2));
  ASSERT_GT(noise, 0.0);
  EXPECT_LT(between, 2.0 * noise) << "between " << between << " noise " << noise;
  // Power: one dioptre of accommodation is a real change the statistic must see.
  const Image a1 = render("joint", 1, 1.0), a2 = render("joint", 2, 1.0);
  EXPECT_GT(msd(mean(j1, j2), mean(a1, a2)), 5.0 * (msd(j1, j2) / 4 + msd(a1, a2) / 4));
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
