// MakeNamedMedium "uniformgrid": trilinear lookups reproduce a linear density exactly between
// the outermost sample centres (what trilinear interpolation guarantees) and fade to zero at the
// box's faces (samples outside the lattice are zero, as pbrt-v4's SampledGrid); the majorant
// grid bounds every density sample, also along rays through the DDA's segments, which tile the
// ray's range inside the box without gaps (a property test over random points and rays); the
// blackbody is Planck's law normalised to its peak (computed here from the physical constants);
// bad input is an error naming file, line and parameter.
#include "media/grid_medium.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::unique_ptr<Medium> make_grid(const std::string& params, const std::string& transform = "") {
  const std::string text =
      "WorldBegin\n" + transform + "\nMakeNamedMedium \"g\" \"string type\" \"uniformgrid\" " + params;
  SceneDescription desc = parse_scene_string(text, "g.pbrt", ".");
  const TransformedEntity& e = desc.media.at("g");
  return create_grid_medium(MediumContext{e.params, e.world_from_object});
}

std::string floats(const std::vector<float>& v) {
  std::string s = "[";
  for (float x : v) s += fmt::format(" {}", x);
  return s + " ]";
}

// density = 1 + 2x + 3y + 4z sampled at the centres of a 5 x 4 x 6 grid over [0, 1]^3.
std::string linear_grid() {
  std::vector<float> d;
  for (int z = 0; z < 6; ++z)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 5; ++x) d.push_back(1.f + 2.f * (x + 0.5f) / 5 + 3.f * (y + 0.5f) / 4 + 4.f * (z + 0.5f) / 6);
  return "\"integer nx\" 5 \"integer ny\" 4 \"integer nz\" 6 \"float density\" " + floats(d);
}

TEST(GridMedium, TrilinearLookupsReproduceALinearDensityAndFadeAtTheFaces) {
  const auto m = make_grid(linear_grid());
  const auto* g = dynamic_cast<const GridMedium*>(m.get());
  ASSERT_NE(g, nullptr);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  for (int i = 0; i < 1000; ++i) {
    // Between the outermost sample centres: x in [0.1, 0.9], y in [0.125, 0.875], z in [1/12, 11/12].
    const Vec3 p(0.1f + 0.8f * u(rng), 0.125f + 0.75f * u(rng), 1.f / 12 + (10.f / 12) * u(rng));
    EXPECT_NEAR(g->density(p), 1.f + 2.f * p.x + 3.f * p.y + 4.f * p.z, 1e-4f) << p.x << " " << p.y << " " << p.z;
  }
  // On a face, half of the outermost sample (the other half is the zero beyond the lattice).
  const Vec3 face(0.f, 0.5f, 0.5f);
  EXPECT_NEAR(g->density(face), 0.5f * (1.f + 2.f * 0.1f + 3.f * 0.5f + 4.f * 0.5f), 1e-4f);
}

TEST(GridMedium, MajorantGridBoundsEveryDensitySampleAlongEveryRay) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  std::vector<float> d(9 * 7 * 5);
  for (float& x : d) x = u(rng) < 0.3f ? 0.f : 4.f * u(rng) * u(rng);  // sparse, spiky
  const auto m = make_grid(
      "\"integer nx\" 9 \"integer ny\" 7 \"integer nz\" 5 \"point3 p0\" [-1 -2 0] "
      "\"point3 p1\" [2 1 0.5] \"rgb sigma_a\" [0.5 0.5 0.5] \"rgb sigma_s\" [1 1 1] "
      "\"float density\" " +
          floats(d),
      "Rotate 35 1 1 0\nTranslate 0.3 0 -0.2");
  const SampledWavelengths lambda = SampledWavelengths::sample_uniform(0.5f, 400.f, 700.f);
  int rays_hitting = 0, points = 0;
  for (int r = 0; r < 2000; ++r) {
    // Rays from a sphere of radius 6 around the box towards random points near it.
    Vec3 o(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f);
    o = 6.f * glm::normalize(o);
    const Vec3 target(3.f * u(rng) - 1.5f, 3.f * u(rng) - 1.5f, 3.f * u(rng) - 1.5f);
    const Ray ray{o, glm::normalize(target - o)};
    MajorantIterator it = m->majorants(ray, 20.f, lambda);
    std::optional<float> prev_end;
    bool any = false;
    while (auto seg = it.next()) {
      any = true;
      ASSERT_LE(seg->t_min, seg->t_max);
      if (prev_end) EXPECT_NEAR(seg->t_min, *prev_end, 1e-4f);  // no gaps between voxels
      prev_end = seg->t_max;
      for (int k = 0; k < 8; ++k) {
        const float t = seg->t_min + (seg->t_max - seg->t_min) * u(rng);
        const MediumProperties mp = m->properties(ray.at(t), lambda);
        ++points;
        EXPECT_LE(mp.sigma_a[0] + mp.sigma_s[0], seg->sigma_maj[0] * (1.f + 1e-5f) + 1e-6f) << "ray " << r;
      }
    }
    rays_hitting += any;
  }
  EXPECT_GT(rays_hitting, 500);
  EXPECT_GT(points, 4000);
}

// The segments of a ray crossing the whole box start where it enters and end where it leaves
// (computed here for an axis-aligned box and a ray along a diagonal direction).
TEST(GridMedium, DdaSegmentsTileTheRaysPathThroughTheBox) {
  const auto m = make_grid("\"integer nx\" 2 \"integer ny\" 2 \"integer nz\" 2 \"float density\" [1 2 3 4 5 6 7 8]");
  const SampledWavelengths lambda = SampledWavelengths::sample_uniform(0.5f, 400.f, 700.f);
  const Vec3 d = glm::normalize(Vec3(1.f, 0.6f, 0.3f));
  const Ray ray{Vec3(-1.f, 0.1f, 0.2f), d};
  // Enters at x = 0 (t = 1 / d.x), leaves through the first face reached among x = 1, y = 1, z = 1.
  const float t_in = 1.f / d.x;
  const float t_out = std::min({2.f / d.x, (1.f - 0.1f) / d.y, (1.f - 0.2f) / d.z});
  MajorantIterator it = m->majorants(ray, 100.f, lambda);
  auto seg = it.next();
  ASSERT_TRUE(seg);
  EXPECT_NEAR(seg->t_min, t_in, 1e-4f);
  float end = seg->t_max;
  int n = 1;
  while ((seg = it.next())) {
    EXPECT_NEAR(seg->t_min, end, 1e-4f);
    end = seg->t_max;
    ++n;
  }
  EXPECT_NEAR(end, t_out, 1e-4f);
  EXPECT_GE(n, 8);  // x from 0 to 0.5 alone crosses 8 of the 16^3 majorant voxels
}

// Planck's law from h, c and k (CODATA), normalised at Wien's peak.
double planck_normalised(double lambda_nm, double kelvin) {
  const double h = 6.62606957e-34, c = 299792458.0, kb = 1.3806488e-23;
  auto b = [&](double l_m) { return 2 * h * c * c / (std::pow(l_m, 5) * (std::exp(h * c / (l_m * kb * kelvin)) - 1)); };
  return b(lambda_nm * 1e-9) / b(2.8977721e-3 / kelvin);
}

TEST(GridMedium, BlackbodyIsPlancksLawNormalisedToItsPeak) {
  for (float kelvin : {1000.f, 2500.f, 6500.f})
    for (float l : {380.f, 500.f, 650.f, 800.f})
      EXPECT_NEAR(normalized_blackbody(l, kelvin), planck_normalised(l, kelvin), 1e-4 * planck_normalised(l, kelvin))
          << kelvin << " K, " << l << " nm";
  EXPECT_NEAR(normalized_blackbody(2.8977721e-3f / 5000.f * 1e9f, 5000.f), 1.f, 1e-5f);
}

// Emission from temperature: (T - offset) * scale kelvin times the Lescale grid; none at or
// below 100 K; without Le or temperature the medium does not emit.
TEST(GridMedium, TemperatureEmitsABlackbodyTimesLescale) {
  const SampledWavelengths lambda = SampledWavelengths::sample_uniform(0.2f, 500.f, 600.f);
  const std::string grid = "\"integer nx\" 2 \"float density\" [1 1] ";
  const auto m = make_grid(grid +
                           "\"float temperature\" [21 21] \"float temperaturecutoff\" 1 "
                           "\"float temperaturescale\" 100 \"float Lescale\" [3 3]");
  EXPECT_TRUE(m->emissive());
  // At the box's centre: on the single sample along y and z, between two equal ones along x.
  const MediumProperties mp = m->properties(Vec3(0.5f), lambda);
  for (int i = 0; i < kSpectrumSamples; ++i)
    EXPECT_NEAR(mp.Le[i], 3.f * cie_y_integral() * planck_normalised(lambda[i], 2000.0), 1e-3f * mp.Le[i]);
  const auto cold = make_grid(grid +
                              "\"float temperature\" [1.5 1.5] \"float temperaturecutoff\" 1 "
                              "\"float temperaturescale\" 100");
  EXPECT_FLOAT_EQ(cold->properties(Vec3(0.5f), lambda).Le[0], 0.f);  // 50 K
  EXPECT_FALSE(make_grid(grid)->emissive());
}

TEST(GridMedium, BadInputIsAnErrorNamingFileLineAndParameter) {
  auto error = [](const std::string& params) -> std::string {
    try {
      make_grid(params);
    } catch (const SceneError& e) {
      return e.what();
    }
    return "";
  };
  const std::string two = "\"integer nx\" 2 ";
  for (auto [params, what] :
       {std::pair{two + "\"float density\" [1 2 3]", "parameter \"density\": has 3 values; nx*ny*nz = 2*1*1 = 2"},
        std::pair{two + "\"float density\" [1 -2]", "density"}, std::pair{std::string(""), "density"},
        std::pair{two + "\"float density\" [1 2] \"float temperature\" [1]", "temperature"},
        std::pair{two + "\"float density\" [1 2] \"float Lescale\" [1 2 3]", "Lescale"},
        std::pair{two + "\"float density\" [1 2] \"float temperature\" [1 2] \"rgb Le\" [1 1 1]", "Le"},
        std::pair{two + "\"float density\" [1 2] \"point3 p0\" [0 2 0]", "p1"},
        std::pair{two + "\"float density\" [1 2] \"integer ny\" 0", "ny"}}) {
    const std::string e = error(params);
    EXPECT_NE(e.find("g.pbrt:3"), std::string::npos) << e;
    EXPECT_NE(e.find(what), std::string::npos) << params << ": " << e;
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
