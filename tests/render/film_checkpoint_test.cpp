// Rendering in passes, stopping and resuming: the film's per-pixel double sums must see the
// same additions in the same order whatever the pass sizes, the thread count, or where a
// render was stopped and restored. Every variant is compared bit for bit with a one-pass,
// one-thread, uninterrupted render: a sample added twice, skipped, or summed in another
// order changes the last bits of some pixel's sum.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <fstream>
#include <iterator>
#include <thread>

#include "../support/unity_id.h"
#include "core/fnv1a.h"
#include "render/film.h"
#include "render/render_state.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

#include "../support/lit_sphere_world.h"
#include "../support/sample_count.h"
#include "../support/unit_box_filter.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// 40x24 pixels: 3x2 tiles, the right and bottom ones partial. "{}": the camera, film and
// filter (the spectral film's buckets must resume as exactly as R, G, B, and the dispersive
// eye's splats, which cross pixels within a tile, as exactly as the pixels' own sums).
const char* kScene = R"(LookAt 0 0 -4  0 0 0  0 1 0
{}
Sampler "zsobol" "integer pixelsamples" 16
Integrator "path" "integer maxdepth" 4
)";

std::string view(const char* camera, const char* film, const char* filter) {
  return fmt::format(
      "Camera {}\nFilm {} \"integer xresolution\" 40 \"integer yresolution\" 24 \"string filename\" "
      "\"out.exr\"\nPixelFilter {}",
      camera, film, filter);
}
const std::string kRgb = view("\"perspective\" \"float fov\" 40", "\"rgb\"", "\"gaussian\"");
const std::string kSpectral =
    view("\"perspective\" \"float fov\" 40",
         "\"spectral\" \"integer nbuckets\" 7 \"float lambdamin\" 380 \"float lambdamax\" 720", "\"gaussian\"");
// The box filter's spectral MIS splats (`mis`; its default is a path per wavelength, below).
const std::string kSplattingEyeSpectral =
    view("\"navarro\" \"float fov\" 40 \"float pupildiameter\" 6 \"string dispersionsampling\" \"mis\"",
         "\"spectral\" \"integer nbuckets\" 5", "\"box\"");
const std::string kSplattingEye =
    view("\"navarro\" \"float fov\" 40 \"float pupildiameter\" 6 \"string dispersionsampling\" \"mis\"", "\"rgb\"",
         "\"box\"");
// Each wavelength its own camera ray and path, four per sample (the box filter's default).
const std::string kWavelengthPathsEye =
    view("\"navarro\" \"float fov\" 40 \"float pupildiameter\" 6", "\"spectral\" \"integer nbuckets\" 5", "\"box\"");
// With a smooth filter every wavelength splats with the filter's weights (core/wavelength_splat.h).
const std::string kSmoothSplattingEye = view("\"navarro\" \"float fov\" 40 \"float pupildiameter\" 6",
                                             "\"spectral\" \"integer nbuckets\" 5", "\"gaussian\"");

RenderSetup setup_scene(const std::string& v = kRgb) {
  set_warnings_enabled(false);
  return build_render_setup(
      parse_scene_string(fmt::format(fmt::runtime(kScene), v) + test::lit_sphere_world(5), "checkpoint.pbrt", "/"), {});
}

std::vector<double> render(RenderSetup& s, RenderOptions opts) {
  RenderCounters counters;
  opts.progress = false;
  s.integrator->render(*s.camera, *s.sampler, *s.film, opts, counters);
  return s.film->accumulators();
}

bool bits_equal(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

std::vector<double> reference(const std::string& film = kRgb) {
  RenderSetup s = setup_scene(film);
  RenderOptions o;
  o.threads = 1;
  o.pass_samples = 16;
  return render(s, o);
}

TEST(FilmCheckpoint, AccumulatorsRestoreExactly) {
  PixelBounds b{IVec2(0), IVec2(3, 2)};
  Film whole(IVec2(3, 2), b, std::make_unique<UnitBox>());
  Film first(IVec2(3, 2), b, std::make_unique<UnitBox>());
  auto sample = [](int i) { return RGB(0.1f * i, 1.f / (i + 1), 3.3f + i); };
  for (int i = 0; i < 10; ++i) whole.add_sample(IVec2(i % 3, i % 2), sample(i), 0.25f + 0.1f * i);
  for (int i = 0; i < 5; ++i) first.add_sample(IVec2(i % 3, i % 2), sample(i), 0.25f + 0.1f * i);
  first.add_sample(IVec2(0, 0), RGB(std::nanf(""), 0.f, 0.f), 1.f);
  Film resumed(IVec2(3, 2), b, std::make_unique<UnitBox>());
  resumed.restore(first.accumulators(), first.nonfinite_samples());
  for (int i = 5; i < 10; ++i) resumed.add_sample(IVec2(i % 3, i % 2), sample(i), 0.25f + 0.1f * i);
  EXPECT_TRUE(bits_equal(resumed.accumulators(), whole.accumulators()));
  EXPECT_EQ(resumed.nonfinite_samples(), 1u);
  EXPECT_THROW(resumed.restore(std::vector<double>(7), 0), std::invalid_argument);
}

class FilmCheckpointOf : public ::testing::TestWithParam<std::string> {};
std::string view_name(const ::testing::TestParamInfo<std::string>& info) {
  static const char* const kNames[] = {"rgb",
                                       "spectral",
                                       "splatting_eye",
                                       "splatting_eye_spectral",
                                       "smooth_splatting_eye_spectral",
                                       "wavelength_paths_eye_spectral"};
  return kNames[info.index];
}
INSTANTIATE_TEST_SUITE_P(Films, FilmCheckpointOf,
                         ::testing::Values(kRgb, kSpectral, kSplattingEye, kSplattingEyeSpectral, kSmoothSplattingEye,
                                           kWavelengthPathsEye),
                         view_name);

// The eye case is only a test of splats if it splats: a dispersive eye with a box filter sends
// some wavelengths to neighbouring pixels (accumulators 4-6 of a pixel).
TEST(FilmCheckpoint, SplattingEyeSplats) {
  const std::vector<double> acc = reference(kSplattingEye);
  size_t splatted = 0;
  for (size_t p = 0; p < acc.size(); p += Film::kAccumulatorsPerPixel) splatted += acc[p + 4] != 0.0;
  EXPECT_GT(splatted, acc.size() / Film::kAccumulatorsPerPixel / 4);  // half the view is black sky
}

// With a Gaussian filter the dispersive eye puts every wavelength into the splat sums (4-6), the
// pixels' own sums (0-2) stay 0, and most lit pixels receive splats.
TEST(FilmCheckpoint, SmoothSplattingEyeSplatsEverything) {
  const std::vector<double> acc = reference(kSmoothSplattingEye);
  const size_t per_pixel = Film::kAccumulatorsPerPixel + Film::kBucketAccumulators * 5;
  size_t splatted = 0;
  for (size_t p = 0; p < acc.size(); p += per_pixel) {
    EXPECT_EQ(acc[p], 0.0);
    splatted += acc[p + 4] != 0.0;
  }
  EXPECT_GT(splatted, acc.size() / per_pixel / 4);  // half the view is black sky
}

// Pass sizes 1 and 5 only in the optimised build (the sanitizer pass looks for memory errors,
// which 0 and 3 already take through both pass paths and both thread counts).
TEST_P(FilmCheckpointOf, ImageDoesNotDependOnPassSizesOrThreads) {
  std::vector<double> ref = reference(GetParam());
  const std::vector<int> passes = test::kSampleDivisor == 1 ? std::vector<int>{0, 1, 3, 5} : std::vector<int>{0, 3};
  for (int pass : passes) {
    for (int threads : {1, 2}) {
      RenderSetup s = setup_scene(GetParam());
      RenderOptions o;
      o.threads = threads;
      o.pass_samples = pass;
      EXPECT_TRUE(bits_equal(render(s, o), ref)) << "pass " << pass << ", threads " << threads;
    }
  }
}

// Stopped after whole passes, saved through the state file, restored into a new film.
TEST_P(FilmCheckpointOf, StoppedBetweenPassesAndResumedThroughStateFileIsBitIdentical) {
  std::vector<double> ref = reference(GetParam());
  RenderSetup s = setup_scene(GetParam());
  std::atomic<bool> stop{false};
  TileProgress tiles;
  RenderOptions o;
  o.threads = 2;
  o.pass_samples = 3;
  o.tiles = &tiles;
  o.stop = &stop;
  int passes = 0;
  o.on_pass = [&](const TileProgress&) { stop = ++passes == 2; };
  render(s, o);
  EXPECT_EQ(tiles.min_done(), 6);
  EXPECT_EQ(tiles.max_done(), 6);

  RenderState st;
  st.fingerprint = 42;
  st.resolution = s.film->resolution();
  st.bounds = s.film->bounds();
  st.samples_per_pixel = 16;
  st.tiles = tiles;
  st.spectral_buckets = s.film->buckets().count;
  st.accumulators = s.film->accumulators();
  std::string path = ::testing::TempDir() + "film_checkpoint_test.exr.state";
  write_render_state(path, st);
  RenderState back = read_render_state(path);
  EXPECT_EQ(back.fingerprint, 42u);
  EXPECT_EQ(back.tiles.done, tiles.done);
  EXPECT_EQ(back.spectral_buckets, s.film->buckets().count);
  EXPECT_EQ(back.accumulators.size(), 40u * 24u *
                                          (unsigned(Film::kAccumulatorsPerPixel) +
                                           unsigned(Film::kBucketAccumulators) * unsigned(back.spectral_buckets)));

  RenderSetup resumed = setup_scene(GetParam());
  resumed.film->restore(back.accumulators, back.nonfinite_samples);
  RenderOptions r;
  r.threads = 1;
  r.tiles = &back.tiles;
  EXPECT_TRUE(bits_equal(render(resumed, r), ref));
  EXPECT_EQ(back.tiles.min_done(), 16);
}

// Stopped between tiles in the middle of a pass (by another thread, as a signal handler
// would): tiles may then hold different counts, and resuming must still be exact.
TEST_P(FilmCheckpointOf, StoppedMidPassAndResumedIsBitIdentical) {
  std::vector<double> ref = reference(GetParam());
  // A thread stops the render once it has samples; on a loaded machine that thread may not run
  // before the tiny render is done, so the attempt is repeated (a stop that never works fails).
  std::unique_ptr<RenderSetup> s;
  TileProgress tiles;
  for (int attempt = 0; attempt < 20; ++attempt) {
    s.reset();  // the old scene goes before its textures (RenderSetup's order)
    s = std::make_unique<RenderSetup>(setup_scene(GetParam()));
    tiles = TileProgress();
    std::atomic<bool> stop{false};
    RenderCounters counters;
    RenderOptions o;
    o.threads = 1;
    o.pass_samples = 16;
    o.tiles = &tiles;
    o.stop = &stop;
    std::thread stopper([&] {
      while (counters.samples.load() == 0) std::this_thread::yield();
      stop = true;
    });
    s->integrator->render(*s->camera, *s->sampler, *s->film, o, counters);
    stopper.join();
    if (tiles.min_done() < 16) break;
  }
  ASSERT_LT(tiles.min_done(), 16);

  TileProgress resumed_tiles = tiles;
  RenderSetup resumed = setup_scene(GetParam());
  resumed.film->restore(s->film->accumulators(), 0);
  RenderOptions r;
  r.threads = 2;
  r.pass_samples = 7;
  r.tiles = &resumed_tiles;
  EXPECT_TRUE(bits_equal(render(resumed, r), ref));
}

TEST(FilmCheckpoint, DamagedStateFilesAreRefused) {
  RenderState st;
  st.resolution = IVec2(20, 20);
  st.bounds = PixelBounds{IVec2(0), IVec2(20)};
  st.samples_per_pixel = 4;
  st.tiles = TileProgress::start(st.bounds);
  st.accumulators.assign(20 * 20 * Film::kAccumulatorsPerPixel, 0.5);
  std::string path = ::testing::TempDir() + "film_checkpoint_damaged.state";
  write_render_state(path, st);
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  auto error_for = [&](const std::string& content) {
    std::ofstream(path, std::ios::binary) << content;
    try {
      read_render_state(path);
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error_for(bytes.substr(0, bytes.size() / 2)).find("checksum does not match"), std::string::npos);
  std::string flipped = bytes;
  flipped[100] ^= 1;
  EXPECT_NE(error_for(flipped).find("checksum does not match"), std::string::npos);
  EXPECT_NE(error_for("P3\n").find("not an eyetrace render state"), std::string::npos);
  EXPECT_EQ(error_for(bytes), "");
  EXPECT_NE(error_for("").find("not an eyetrace render state"), std::string::npos);
}

// A spectral state: its bucket count is stored, and accumulators that disagree with it, or a
// count outside what a film can have, are refused (a state of format version 1 too).
TEST(FilmCheckpoint, SpectralStateRoundTripsAndInconsistentOnesAreRefused) {
  RenderState st;
  st.resolution = IVec2(20, 20);
  st.bounds = PixelBounds{IVec2(0), IVec2(20)};
  st.samples_per_pixel = 4;
  st.tiles = TileProgress::start(st.bounds);
  st.spectral_buckets = 16;
  st.accumulators.assign(20 * 20 * (Film::kAccumulatorsPerPixel + Film::kBucketAccumulators * 16), 0.25);
  const std::string path = ::testing::TempDir() + "film_checkpoint_spectral.state";
  write_render_state(path, st);
  RenderState back = read_render_state(path);
  EXPECT_EQ(back.spectral_buckets, 16);
  EXPECT_EQ(back.accumulators, st.accumulators);
  auto error_for = [&](const RenderState& s) {
    write_render_state(path, s);
    try {
      read_render_state(path);
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  RenderState rgb_sized = st;
  rgb_sized.accumulators.resize(20 * 20 * Film::kAccumulatorsPerPixel);
  EXPECT_NE(error_for(rgb_sized).find("its film and tile sizes disagree"), std::string::npos);
  RenderState too_many = st;
  too_many.spectral_buckets = 100000;
  EXPECT_NE(error_for(too_many).find("spectral bucket count 100000 is outside [0, 512]"), std::string::npos);
  // Version 1, 2 and 3 files (before spectral films; before splat sums; before squared
  // luminances and adaptive counts) are refused by version,
  // not misread.
  for (uint32_t old_version : {1u, 2u, 3u, 4u}) {
    write_render_state(path, st);
    std::string bytes;
    {
      std::ifstream in(path, std::ios::binary);
      bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const size_t version_at = std::string_view("EYETRACE-RENDER-STATE\n").size() + 4;
    std::memcpy(&bytes[version_at], &old_version, 4);
    const uint64_t sum = fnv1a(std::string_view(bytes).substr(0, bytes.size() - 8));
    std::memcpy(&bytes[bytes.size() - 8], &sum, 8);
    std::ofstream(path, std::ios::binary) << bytes;
    try {
      read_render_state(path);
      ADD_FAILURE() << "a version " << old_version << " state was read";
    } catch (const SceneError& e) {
      EXPECT_NE(
          std::string(e.what()).find(fmt::format("format version {}, this eyetrace reads version 5", old_version)),
          std::string::npos)
          << e.what();
    }
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
