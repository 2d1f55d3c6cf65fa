// Adaptive sampling: the error estimate against the textbook standard error of a mean, the
// pass schedule, pooling over neighbours, and renders that must be reproducible (threads,
// stop and resume through the state file), never leave a pixel without samples, and spend
// their samples where the image is noisy.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <random>
#include <thread>

#include "../support/lit_sphere_world.h"
#include "../support/unity_id.h"
#include "render/adaptive_sampling.h"
#include "render/film.h"
#include "render/render_state.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

#include "../support/unit_box_filter.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// A grey sample of luminance y: linear sRGB (y, y, y) has luminance y (the weights sum to 1).
RGB grey(double y) { return RGB(float(y)); }

Film film_of(IVec2 size) { return Film(size, PixelBounds{IVec2(0), size}, std::make_unique<UnitBox>()); }

TileProgress counts(const Film& f, int n) {
  TileProgress t = TileProgress::start(f.bounds());
  t.pixel_done.assign(f.bounds().area(), n);
  t.pixel_target = t.pixel_done;
  return t;
}

// Pixel 0 takes 0, 2, 0, 2, ... (mean 1, sample variance n / (n - 1)), pixel 1 the constant 1:
// the standard error of pixel 0's mean is sqrt(1 / (n - 1)), relative to sqrt(1 + floor^2) with
// floor = 0.1 x the image mean 1. Weights of 0.5 (a constant filter weight) change nothing.
TEST(AdaptiveSampling, ErrorIsTheStandardErrorOfTheMeanRelativeToIt) {
  for (float w : {1.f, 0.5f}) {
    Film f = film_of(IVec2(2, 1));
    const int n = 16;
    for (int i = 0; i < n; ++i) {
      f.add_sample(IVec2(0, 0), grey(2.0 * (i % 2)), w);
      f.add_sample(IVec2(1, 0), grey(1.0), w);
    }
    const std::vector<double> e = pixel_errors(f, counts(f, n));
    EXPECT_NEAR(e[0], std::sqrt(1.0 / (n - 1) / (1.0 + 0.01)), 1e-6) << "weight " << w;
    EXPECT_NEAR(e[1], 0.0, 1e-6) << "weight " << w;
  }
}

// Gaussian samples of known sigma: the estimate agrees with sigma / sqrt(n) / mean within the
// sampling error of a variance estimate (relative sd sqrt(2 / (n - 1)) = 4.5 % at n = 1000; 5 sd).
TEST(AdaptiveSampling, ErrorOfNoisySamplesMatchesTheirSigma) {
  Film f = film_of(IVec2(1, 1));
  std::mt19937 rng(3);
  std::normal_distribution<double> normal(4.0, 0.8);
  const int n = 1000;
  for (int i = 0; i < n; ++i) f.add_sample(IVec2(0, 0), grey(normal(rng)), 1.f);
  const double expected = 0.8 / std::sqrt(double(n)) / std::sqrt(16.0 + 0.16);
  EXPECT_NEAR(pixel_errors(f, counts(f, n))[0] / expected, 1.0, 5 * std::sqrt(2.0 / (n - 1)));
}

TEST(AdaptiveSampling, APixelWithFewerThanTwoSamplesIsNeverConverged) {
  Film f = film_of(IVec2(1, 1));
  f.add_sample(IVec2(0, 0), grey(1.0), 1.f);
  EXPECT_TRUE(std::isinf(pixel_errors(f, counts(f, 1))[0]));
}

TEST(AdaptiveSampling, PassesDoubleAndStopAtTheCap) {
  AdaptiveOptions o;
  o.min_spp = 16;
  o.max_spp = 300;
  std::vector<int> ends = {16};
  while (ends.back() < o.max_spp) ends.push_back(next_pass_end(ends.back(), o));
  EXPECT_EQ(ends, (std::vector<int>{16, 32, 64, 128, 256, 300}));
}

// Pixel 0 takes 0.5, 1.5, ... (sample sd 0.5 sqrt(n / (n - 1))), pixel 6 takes 0, 2, ... (twice
// that), the rest 1: sigma relative to sqrt(1 + 0.1^2) (the image mean is 1). Pooled (the larger
// of its own and its neighbourhood's mean), pixels 0, 1, 5, 6 have s0, s0 / 3, s6 / 3, s6 (a 7x1
// film: neighbourhoods of 2 or 3); k = mean(pooled) / E^2; each wants k sigma rounded to the
// nearest power of two, at least min_spp.
TEST(AdaptiveSampling, PixelsWantSamplesInProportionToTheirSigma) {
  Film f = film_of(IVec2(7, 1));
  const int n = 16;
  for (int i = 0; i < n; ++i)
    for (int x = 0; x < 7; ++x)
      f.add_sample(IVec2(x, 0), grey(x == 0 ? 0.5 + (i % 2) : x == 6 ? 2.0 * (i % 2) : 1.0), 1.f);
  AdaptiveOptions o;
  o.target_error = 0.05;
  o.min_spp = 4;
  o.max_spp = 1000;
  const double s0 = 0.5 * std::sqrt(n / (n - 1.0)) / std::sqrt(1.01), s6 = 2 * s0;
  const double k = (s0 + s0 / 3 + s6 / 3 + s6) / 7 / (0.05 * 0.05);
  auto want = [&](double sigma) { return std::max(4, int(std::exp2(std::round(std::log2(k * sigma))))); };
  const std::vector<int> expected = {want(s0), want(s0 / 3), 4, 4, 4, want(s6 / 3), want(s6)};
  EXPECT_EQ(wanted_samples(f, o, counts(f, n)), expected);
  EXPECT_EQ(expected, (std::vector<int>{64, 16, 4, 4, 4, 32, 128})) << "the case this test means to make";
  // The next pass takes them towards it, by at most as many samples again (16 + 16).
  TileProgress t = counts(f, n);
  EXPECT_EQ(plan_next_pass(f, o, t), 3u);
  EXPECT_EQ(t.pixel_target, (std::vector<int>{32, n, n, n, n, 32, 32}));
}

// A 5x5 film, constant everywhere but a noisy centre: the centre and its eight neighbours
// (whose own samples all agree) take the next pass; the rest stop. Nobody goes beyond the cap.
TEST(AdaptiveSampling, APixelBesideANoisyOneGoesOn) {
  Film f = film_of(IVec2(5, 5));
  const int n = 16;
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 5; ++x)
      for (int i = 0; i < n; ++i) f.add_sample(IVec2(x, y), grey(x == 2 && y == 2 ? 2.0 * (i % 2) : 1.0), 1.f);
  AdaptiveOptions o;
  o.target_error = 0.01;
  o.min_spp = n;
  o.max_spp = 64;
  TileProgress t = counts(f, n);
  EXPECT_EQ(plan_next_pass(f, o, t), 9u);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 5; ++x)
      EXPECT_EQ(t.pixel_target[size_t(y * 5 + x)], std::abs(x - 2) <= 1 && std::abs(y - 2) <= 1 ? 32 : n) << x << y;
  t.pixel_done.assign(25, 64);
  t.pixel_target = t.pixel_done;
  EXPECT_EQ(plan_next_pass(f, o, t), 0u) << "capped pixels stop";
}

// A lit sphere and floor over a black background (40x24, 3x2 tiles, the last ones partial).
const char* kScene = R"(LookAt 0 0 -4  0 0 0  0 1 0
Camera "perspective" "float fov" 40
Film "rgb" "integer xresolution" 40 "integer yresolution" 24 "string filename" "out.exr"
PixelFilter "gaussian"
Sampler "zsobol" "integer pixelsamples" 128
Integrator "path" "integer maxdepth" 4
)";

RenderSetup setup_scene() {
  set_warnings_enabled(false);
  return build_render_setup(parse_scene_string(kScene + test::lit_sphere_world(2), "adaptive.pbrt", "/"), {});
}

AdaptiveOptions options() {
  AdaptiveOptions o;
  o.target_error = 0.02;
  o.min_spp = 8;
  o.max_spp = 128;
  return o;
}

struct Rendered {
  std::vector<double> acc;
  TileProgress tiles;
};

Rendered render(int threads, const std::atomic<bool>* stop = nullptr, TileProgress tiles = {},
                const std::vector<double>* restore = nullptr) {
  RenderSetup s = setup_scene();
  if (restore) s.film->restore(*restore, 0);
  const AdaptiveOptions o = options();
  RenderOptions r;
  r.threads = threads;
  r.progress = false;
  r.adaptive = &o;
  r.tiles = &tiles;
  r.stop = stop;
  RenderCounters counters;
  s.integrator->render(*s.camera, *s.sampler, *s.film, r, counters);
  return {s.film->accumulators(), tiles};
}

bool bits_equal(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(AdaptiveRender, SpendsSamplesWhereTheImageIsNoisyAndNoneGoWithout) {
  const Rendered r = render(2);
  ASSERT_TRUE(r.tiles.complete(128));
  const int w = 40;
  // The top corners see only the black background: every sample is 0, so they stop at once.
  EXPECT_EQ(r.tiles.pixel_done[0], 8);
  EXPECT_EQ(r.tiles.pixel_done[w - 1], 8);
  // The lit sphere's centre (one bounce off the floor is noisy) goes on.
  EXPECT_GT(r.tiles.pixel_done[size_t(12 * w + 20)], 8);
  for (int n : r.tiles.pixel_done) EXPECT_GE(n, 8);
}

TEST(AdaptiveRender, SameImageForAnyThreadCount) {
  const Rendered one = render(1), two = render(2);
  EXPECT_TRUE(bits_equal(one.acc, two.acc));
  EXPECT_EQ(one.tiles.pixel_done, two.tiles.pixel_done);
}

// Stopped by another thread in the middle of the render (as a signal would), saved through the
// state file and resumed with another thread count: the same bits as an uninterrupted render.
TEST(AdaptiveRender, StoppedAndResumedThroughTheStateFileIsBitIdentical) {
  const Rendered ref = render(1);
  std::atomic<bool> stop{false};
  RenderSetup probe = setup_scene();
  std::thread stopper;
  Rendered part;
  {
    // Stop once a few tiles of the second pass exist: poll the sample counter from outside.
    RenderSetup s = setup_scene();
    const AdaptiveOptions o = options();
    TileProgress tiles;
    RenderOptions r;
    r.threads = 1;
    r.adaptive = &o;
    r.tiles = &tiles;
    r.stop = &stop;
    RenderCounters counters;
    stopper = std::thread([&] {
      while (counters.samples.load() < 40u * 24u * 8u + 1000u) std::this_thread::yield();
      stop = true;
    });
    s.integrator->render(*s.camera, *s.sampler, *s.film, r, counters);
    stopper.join();
    part = {s.film->accumulators(), tiles};
  }
  ASSERT_FALSE(part.tiles.complete(128));
  RenderState st;
  st.resolution = probe.film->resolution();
  st.bounds = probe.film->bounds();
  st.samples_per_pixel = 128;
  st.tiles = part.tiles;
  st.accumulators = part.acc;
  const std::string path = ::testing::TempDir() + "adaptive_sampling_test.exr.state";
  write_render_state(path, st);
  RenderState back = read_render_state(path);
  EXPECT_EQ(back.tiles.pixel_done, part.tiles.pixel_done);
  EXPECT_EQ(back.tiles.pixel_target, part.tiles.pixel_target);
  const Rendered resumed = render(2, nullptr, back.tiles, &back.accumulators);
  EXPECT_TRUE(bits_equal(resumed.acc, ref.acc));
  EXPECT_EQ(resumed.tiles.pixel_done, ref.tiles.pixel_done);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
