// MakeNamedMedium "nanovdb": .nvdb files written here with NanoVDB's own GridBuilder (Debian's
// libnanovdb-dev) are read back; trilinear lookups reproduce a linear density exactly inside
// the active voxels; the 64^3 majorant grid bounds every density sample (random points); a
// constant-density volume passes exp(-sigma_a d) to a narrow view (the render path through the
// DDA); a temperature grid emits the normalised blackbody times Lescale; a missing, truncated
// or grid-less file and a negative density are errors naming file, line and parameter.
#include "media/nanovdb_medium.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>
#include <nanovdb/util/GridBuilder.h>
#include <nanovdb/util/IO.h>

#include <cmath>
#include <fstream>
#include <random>

#include "../support/render_text.h"
#include "../support/temp_files.h"
#include "core/error.h"
#include "media/grid_medium.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

using Handle = nanovdb::GridHandle<nanovdb::HostBuffer>;

// A float fog volume named `name`: value f(i, j, k) at index (i, j, k) in [0, n)^3, voxel 0.1.
template <typename F>
Handle make_grid(const std::string& name, int n, F f) {
  nanovdb::GridBuilder<float> builder(0.f, nanovdb::GridClass::FogVolume);
  auto acc = builder.getAccessor();
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) acc.setValue(nanovdb::Coord(i, j, k), f(i, j, k));
  return builder.getHandle<>(0.1, nanovdb::Vec3d(0.0), name);
}

std::unique_ptr<Medium> load(const test::TempDir& dir, const std::string& params) {
  const std::string text = "WorldBegin\nMakeNamedMedium \"v\" \"string type\" \"nanovdb\" " + params;
  SceneDescription desc = parse_scene_string(text, "n.pbrt", dir.path().string());
  const TransformedEntity& e = desc.media.at("v");
  return create_nanovdb_medium(MediumContext{e.params, e.world_from_object, dir.path().string()});
}

TEST(NanoVDBMedium, TrilinearLookupsReproduceALinearDensity) {
  test::TempDir dir("nvdb");
  nanovdb::io::writeGrid(dir.file("lin.nvdb"), make_grid("density", 20, [](int i, int j, int k) {
                           return 0.5f + 0.1f * i + 0.05f * j + 0.02f * k;
                         }));
  const auto m = load(dir, "\"string filename\" \"lin.nvdb\"");
  const auto* v = dynamic_cast<const NanoVDBMedium*>(m.get());
  ASSERT_NE(v, nullptr);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.f, 1.9f);  // index 0..19: world 0..1.9
  for (int n = 0; n < 500; ++n) {
    const Vec3 p(u(rng), u(rng), u(rng));
    EXPECT_NEAR(v->density_in_medium_space(p), 0.5f + p.x + 0.5f * p.y + 0.2f * p.z, 1e-4f);
  }
}

TEST(NanoVDBMedium, MajorantGridBoundsEveryDensitySample) {
  test::TempDir dir("nvdb");
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  nanovdb::io::writeGrid(dir.file("spiky.nvdb"),
                         make_grid("density", 24, [&](int, int, int) { return u(rng) < 0.7f ? 0.f : 5.f * u(rng); }));
  const auto m = load(dir, "\"string filename\" \"spiky.nvdb\"");
  const auto* v = dynamic_cast<const NanoVDBMedium*>(m.get());
  const Bounds3 b = v->bounds();
  const MajorantGrid& g = v->majorant_grid();
  for (int n = 0; n < 20000; ++n) {
    const Vec3 f(u(rng), u(rng), u(rng));
    const Vec3 p = b.lo + f * (b.hi - b.lo);
    const int x = std::min(int(f.x * g.res), g.res - 1), y = std::min(int(f.y * g.res), g.res - 1),
              z = std::min(int(f.z * g.res), g.res - 1);
    EXPECT_LE(v->density_in_medium_space(p), g.lookup(x, y, z) + 1e-6f) << p.x << " " << p.y << " " << p.z;
  }
}

TEST(NanoVDBMedium, TemperatureEmitsTheNormalisedBlackbodyTimesLescale) {
  test::TempDir dir("nvdb");
  std::vector<Handle> grids;
  grids.push_back(make_grid("density", 8, [](int, int, int) { return 1.f; }));
  grids.push_back(make_grid("temperature", 8, [](int, int, int) { return 16.f; }));
  nanovdb::io::writeGrids(dir.file("fire.nvdb"), grids);
  const auto m = load(dir,
                      "\"string filename\" \"fire.nvdb\" \"float temperaturecutoff\" 1 "
                      "\"float temperaturescale\" 100 \"float Lescale\" 2");
  // The explosion scene's spelling, "LeScale", is the same parameter.
  const auto older = load(dir,
                          "\"string filename\" \"fire.nvdb\" \"float temperaturecutoff\" 1 "
                          "\"float temperaturescale\" 100 \"float LeScale\" 2");
  EXPECT_TRUE(m->emissive());
  const SampledWavelengths lambda = SampledWavelengths::sample_uniform(0.4f);
  const MediumProperties mp = m->properties(Vec3(0.35f), lambda);  // inside: T = 1500 K
  const MediumProperties mp_older = older->properties(Vec3(0.35f), lambda);
  for (int i = 0; i < kSpectrumSamples; ++i) {
    EXPECT_NEAR(mp.Le[i], 2.f * cie_y_integral() * normalized_blackbody(lambda[i], 1500.f), 1e-3f * mp.Le[i]);
    EXPECT_EQ(mp_older.Le[i], mp.Le[i]);
  }
}

// Density 1 in [0, 3.9]^3 (40^3 voxels of 0.1), centred on the origin by the transform at
// MakeNamedMedium; a sphere of radius 0.5 inside it; sigma_a 0.8 and no scattering: a narrow
// view passes exp(-0.8) of the sky.
TEST(NanoVDBMedium, ConstantVolumePassesBeerLambert) {
  test::TempDir dir("nvdb");
  nanovdb::io::writeGrid(dir.file("block.nvdb"), make_grid("density", 40, [](int, int, int) { return 1.f; }));
  auto render = [&](bool with_medium, int spp) {
    const std::string text = fmt::format(R"(LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" 0.2
Film "rgb" "integer xresolution" 16 "integer yresolution" 16
Sampler "independent" "integer pixelsamples" {}
PixelFilter "box"
Integrator "volpath" "integer maxdepth" 5
WorldBegin
LightSource "infinite" "rgb L" [1 1 1]
AttributeBegin
  Translate -1.95 -1.95 -1.95
  MakeNamedMedium "v" "string type" "nanovdb" "string filename" "block.nvdb" "rgb sigma_a" [0.8 0.8 0.8]
    "rgb sigma_s" [0 0 0]
AttributeEnd
{})",
                                         spp,
                                         with_medium ? "MediumInterface \"v\" \"\"\nMaterial \"interface\"\n"
                                                       "Shape \"sphere\" \"float radius\" 0.5\n"
                                                     : "");
    RenderSetup s = build_render_setup(parse_scene_string(text, "n.pbrt", dir.path().string()), {});
    RenderCounters counters;
    s.integrator->render(*s.camera, *s.sampler, *s.film, RenderOptions{}, counters);
    return test::channel_mean_and_error(s.film->image(), 1);
  };
  const auto open = render(false, 4), absorbed = render(true, 64);
  EXPECT_NEAR(absorbed.mean, open.mean * std::exp(-0.8), 5 * absorbed.std_error + 1e-3 * open.mean);
}

TEST(NanoVDBMedium, BadInputIsAnErrorNamingFileLineAndParameter) {
  test::TempDir dir("nvdb");
  nanovdb::io::writeGrid(dir.file("ok.nvdb"), make_grid("density", 4, [](int, int, int) { return 1.f; }));
  nanovdb::io::writeGrid(dir.file("other.nvdb"), make_grid("smoke", 4, [](int, int, int) { return 1.f; }));
  nanovdb::io::writeGrid(dir.file("negative.nvdb"), make_grid("density", 4, [](int i, int, int) { return i - 1.f; }));
  {
    const std::string bytes = test::read_text(dir.file("ok.nvdb"));
    std::ofstream(dir.file("truncated.nvdb"), std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    std::ofstream(dir.file("garbage.nvdb"), std::ios::binary) << "not a nanovdb file at all";
  }
  auto error = [&](const std::string& params) -> std::string {
    try {
      load(dir, params);
    } catch (const SceneError& e) {
      return e.what();
    }
    return "";
  };
  for (auto [params, what] : {std::pair{"", "filename"}, std::pair{"\"string filename\" \"missing.nvdb\"", "filename"},
                              std::pair{"\"string filename\" \"truncated.nvdb\"", "filename"},
                              std::pair{"\"string filename\" \"garbage.nvdb\"", "filename"},
                              std::pair{"\"string filename\" \"other.nvdb\"", "gridname"},
                              std::pair{"\"string filename\" \"negative.nvdb\"", "negative"},
                              std::pair{"\"string filename\" \"ok.nvdb\" \"float g\" 2", "\"g\""}}) {
    const std::string e = error(params);
    EXPECT_NE(e.find("n.pbrt:2"), std::string::npos) << params << ": " << e;
    EXPECT_NE(e.find(what), std::string::npos) << params << ": " << e;
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
