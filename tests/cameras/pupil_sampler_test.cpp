// The eye camera's pupil sampling: useful-ray fraction, containment of every passing ray (a
// dense brute-force search of the sampling plane), uniform density over the stated area.
#include "cameras/pupil_sampler.h"
#include "../support/sample_count.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

#include "cameras/lens_system_camera.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::unique_ptr<LensSystemCamera> make_eye(const std::string& params, IVec2 res = IVec2(256, 256)) {
  SceneEntity e = parse_directive_text("Camera \"eye\" " + params, "Camera", "test");
  CameraContext ctx{e.params, Transform(), res, ""};
  std::unique_ptr<Camera> c = create_eye_camera(ctx);
  return std::unique_ptr<LensSystemCamera>(dynamic_cast<LensSystemCamera*>(c.release()));
}

// At the compiled wavelength, or at lambda_nm (a dispersive eye's rays).
bool passes(const LensSystemCamera& cam, double arc, glm::dvec2 q, double lambda_nm = 0.0) {
  const glm::dvec2 p = cam.retina().point(arc);
  const glm::dvec3 from(p.x, 0.0, p.y);
  const optics::Ray ray{from, glm::dvec3(q.x, q.y, cam.pupil().z_plane()) - from};
  const int first = cam.system().image_index() - 1;
  return (lambda_nm > 0.0 ? cam.system().trace_range(ray, first, 0, lambda_nm)
                          : cam.system().trace_range(ray, first, 0))
      .ok();
}

// Fraction of generated rays that reach the scene, over random film and lens samples.
double useful_fraction(const Camera& cam, IVec2 res, int n) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  int ok = 0;
  for (int i = 0; i < n; ++i) {
    CameraSample cs;
    cs.p_film = Vec2(res.x * u(rng), res.y * u(rng));
    cs.p_lens = Vec2(u(rng), u(rng));
    ok += cam.generate_ray(cs).has_value();
  }
  return double(ok) / n;
}

// The brief's target: >= 95% of the rays generated over a 5 mm pupil and a 60 degree field
// reach the scene (pbrt-v4's exit-pupil boxes waste at least a fifth). Measured: 0.977 for Navarro
// with 128 polygon directions (a render with 64 gave about 0.972), 0.977 to 0.978 for all four
// eyes. 50000 rays per eye: the standard error of a fraction near 0.977 is 0.0007, so the margin
// to 0.95 is 40 standard errors, and an eye at 0.94 would fail by 14 (400000 rays took 22 s of
// the sanitizer run).
TEST(PupilSampler, UsefulRayFractionAtLeast95Percent) {
  for (const char* model : {"navarro", "gullstrand", "legrand", "kooijman"}) {
    auto cam = make_eye(fmt::format("\"string model\" \"{}\" \"float pupildiameter\" 5 \"float fov\" 60", model));
    const double f = useful_fraction(*cam, IVec2(256, 256), 50000);
    std::printf("useful ray fraction, %s, 5 mm pupil, 60 deg fov: %.4f\n", model, f);
    EXPECT_GE(f, 0.95) << model;
  }
}

// Dense search: at many retina positions (interval ends and middles, where the polygon is
// furthest from a traced position, and random ones) no ray through a point of the plane
// outside the sampled polygon reaches the scene. The grid covers the passing region's box
// grown by 30% in each direction, at a spacing of 1/kFineGrid of it.
// Returns the fraction of passing grid rays found outside (0 is required where the passing
// region is convex, see below). Under the sanitizers the fine grid is 100 x 100 (a ninth of the
// traces: that pass looks for memory errors on these paths, the optimised build for the rays).
constexpr int kFineGrid = test::kSampleDivisor == 1 ? 300 : 100;
double passing_outside_fraction(const LensSystemCamera& cam, const std::string& label, double lambda_nm = 0.0) {
  const PupilSampler& ps = cam.pupil();
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> arcs;
  for (int k = 0; k <= 24; ++k) arcs.push_back(ps.max_arc_mm() * k / 24.0 * (1.0 - 1e-12));
  for (int k = 0; k < 12; ++k) arcs.push_back(ps.max_arc_mm() * u(rng));
  int outside = 0, passing = 0;
  for (double arc : arcs) {
    // Coarse search for the passing box, 0.1 mm grid over +-10 mm; a region smaller than that
    // grid is searched around the sampler's centre instead.
    glm::dvec2 lo(1e9), hi(-1e9);
    const glm::dvec2 c = ps.centre(arc);
    for (int i = 0; i <= 200; ++i)
      for (int j = 0; j <= 100; ++j) {
        const glm::dvec2 q(c.x - 10.0 + 0.1 * i, 0.1 * j);
        if (passes(cam, arc, q, lambda_nm)) lo = glm::min(lo, q), hi = glm::max(hi, q);
      }
    if (lo.x > hi.x) lo = c, hi = c;
    lo -= glm::dvec2(0.1);
    hi += glm::dvec2(0.1);
    const glm::dvec2 size = hi - lo;
    lo -= 0.3 * size;
    hi += 0.3 * size;
    lo.y = -hi.y;
    for (int i = 0; i < kFineGrid; ++i)
      for (int j = 0; j < kFineGrid; ++j) {
        const glm::dvec2 q(lo.x + (hi.x - lo.x) * (i + 0.5) / kFineGrid, lo.y + (hi.y - lo.y) * (j + 0.5) / kFineGrid);
        if (!passes(cam, arc, q, lambda_nm)) continue;
        ++passing;
        if (!ps.contains(arc, q)) ++outside;
      }
  }
  EXPECT_GT(passing, 1000) << label;
  std::printf("%s: %d of %d passing grid rays outside the sampled region\n", label.c_str(), outside, passing);
  return double(outside) / passing;
}

// Dense search: at many retina positions (interval ends, where the polygon is furthest from a
// traced middle, and random ones) no ray through a point of the plane outside the sampled
// polygon reaches the scene. The grid covers the passing region's box grown by 30% on each
// side at 1/kFineGrid of its width. Cases: the paper's pupil; a wide pupil and field where the lens
// rims and the cornea cut the pupil into a cat's eye with sharp corners; a tiny pupil where
// the region is a fraction of a millimetre.
TEST(PupilSampler, NoPassingRayOutsideTheSampledRegion) {
  EXPECT_EQ(passing_outside_fraction(*make_eye("\"float pupildiameter\" 5 \"float fov\" 60"), "navarro 5 mm"), 0.0);
  EXPECT_EQ(passing_outside_fraction(*make_eye("\"float pupildiameter\" 8 \"float fov\" 140"), "navarro 8 mm"), 0.0);
  EXPECT_EQ(passing_outside_fraction(*make_eye("\"string model\" \"legrand\" \"float pupildiameter\" 6 "
                                               "\"float accommodation\" 5 \"float fov\" 120"),
                                     "legrand accommodated"),
            0.0);
  EXPECT_EQ(
      passing_outside_fraction(*make_eye("\"string model\" \"kooijman\" \"float pupildiameter\" 0.5 \"float fov\" 120"),
                               "kooijman 0.5 mm"),
      0.0);
}

// A dispersive eye traces each sample at its own wavelength through tables built at the
// reference wavelength: they must hold the passing rays at the ends of the sampled range too
// (the lens behind the iris moves the passing region with the wavelength).
TEST(PupilSampler, DispersiveEyeHoldsEveryWavelength) {
  for (double lambda : {360.0, 830.0}) {
    auto cam = make_eye("\"float pupildiameter\" 5 \"float fov\" 60");
    ASSERT_TRUE(cam->dispersive());
    EXPECT_EQ(passing_outside_fraction(*cam, fmt::format("navarro 5 mm at {} nm", lambda), lambda), 0.0);
    auto acc = make_eye(
        "\"string model\" \"legrand\" \"float pupildiameter\" 6 \"float accommodation\" 5 "
        "\"float fov\" 120");
    EXPECT_EQ(passing_outside_fraction(*acc, fmt::format("legrand accommodated at {} nm", lambda), lambda), 0.0);
  }
}

// A multi-element camera lens (pbrt's double Gauss, US patent 2,673,491 at 50 mm) wide open,
// where several element rims cut the pupil across a 35 mm film.
TEST(PupilSampler, NoPassingRayOutsideForDoubleGaussLens) {
  const std::string dir = ::testing::TempDir();
  {
    std::ofstream f(dir + "/eyecam_dgauss2.dat");
    f << "29.475 3.76 1.67 25.2\n84.83 0.12 1 25.2\n19.275 4.025 1.67 23\n40.77 3.275 1.699 23\n"
         "12.75 5.705 1 18\n0 4.5 0 17.1\n-14.495 1.18 1.603 17\n40.77 6.065 1.658 20\n"
         "-20.385 0.19 1 20\n437.065 3.22 1.717 20\n-39.73 40 1 20\n";
  }
  SceneEntity e = parse_directive_text(
      "Camera \"realistic\" \"string lensfile\" \"eyecam_dgauss2.dat\" \"float aperturediameter\" 17.1", "Camera",
      "test");
  CameraContext ctx{e.params, Transform(), IVec2(300, 200), dir};
  std::unique_ptr<Camera> cam = create_realistic_camera(ctx);
  EXPECT_EQ(passing_outside_fraction(dynamic_cast<const LensSystemCamera&>(*cam), "double Gauss"), 0.0);
}

// Known limit (docs/eye-camera.md): the accommodated Gullstrand eye's nucleus is a thin lens
// with a sharp rim; rays grazing it bend so strongly that a crescent tens of micrometres wide,
// outside the main passing region and separated from it by rays the iris blocks, passes too.
// The sampler (a star-shaped region) does not find it; measured: 1e-4 of the passing rays.
TEST(PupilSampler, GullstrandNucleusRimCrescentIsBelowHalfPerMille) {
  const double f = passing_outside_fraction(
      *make_eye(
          "\"string model\" \"gullstrand\" \"float pupildiameter\" 7 \"float accommodation\" 8 \"float fov\" 100"),
      "gullstrand accommodated 7 mm");
  EXPECT_LT(f, 5e-4);
  EXPECT_EQ(
      passing_outside_fraction(*make_eye("\"string model\" \"gullstrand\" \"float pupildiameter\" 5 \"float fov\" 100"),
                               "gullstrand relaxed"),
      0.0);
}

// Chi-square test of the samples' density over a grid of cells inside the region.
void expect_uniform(const char* mapping, double arc_fraction) {
  auto cam =
      make_eye(std::string("\"float pupildiameter\" 6 \"float fov\" 100 \"string pupilmapping\" \"") + mapping + "\"");
  const PupilSampler& ps = cam->pupil();
  const double arc = arc_fraction * ps.max_arc_mm();
  {
    const double area = ps.area(arc);
    ASSERT_GT(area, 0.0);
    const int n = 400000, g = 24;
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<glm::dvec2> pts(n);
    glm::dvec2 lo(1e9), hi(-1e9);
    for (auto& q : pts) {
      double a;
      ASSERT_TRUE(ps.sample(arc, u(rng), u(rng), &q, &a));
      EXPECT_EQ(a, area);
      lo = glm::min(lo, q), hi = glm::max(hi, q);
    }
    const glm::dvec2 cell = (hi - lo) / double(g);
    std::vector<int> counts(g * g, 0);
    for (const auto& q : pts) {
      const int i = std::min(g - 1, int((q.x - lo.x) / cell.x)), j = std::min(g - 1, int((q.y - lo.y) / cell.y));
      ++counts[i * g + j];
    }
    double chi2 = 0.0;
    int cells = 0;
    for (int i = 0; i < g; ++i)
      for (int j = 0; j < g; ++j) {
        bool inside = true;
        for (int a = 0; a <= 4 && inside; ++a)
          for (int b = 0; b <= 4 && inside; ++b)
            inside = ps.contains(arc, lo + cell * glm::dvec2(i + a / 4.0, j + b / 4.0));
        if (!inside) continue;
        const double expected = n * cell.x * cell.y / area;
        chi2 += (counts[i * g + j] - expected) * (counts[i * g + j] - expected) / expected;
        ++cells;
      }
    ASSERT_GT(cells, 100);
    const double k = cells, z = (std::cbrt(chi2 / k) - (1.0 - 2.0 / (9.0 * k))) / std::sqrt(2.0 / (9.0 * k));
    EXPECT_LT(std::abs(z), 4.5) << mapping << " arc " << arc << " chi2 " << chi2 << " cells " << cells;
  }
}

// Both pupil mappings draw uniformly over the stated area (density 1 / area): unbiased.
TEST(PupilSampler, SamplesAreUniformOverTheStatedArea) {
  for (const char* mapping : {"concentric", "polar"})
    for (double fraction : {0.0, 0.37, 0.81}) expect_uniform(mapping, fraction);
}

// Mean squared error, over jittered k x k stratified pupil samples, of the fraction of the
// region beyond a straight edge (a defocused edge's blur as the pupil integrates it), against
// that fraction (returned in *truth) from 4 million independent random points.
double edge_fraction_mse(const PupilSampler& ps, double arc, int k, int trials, double* truth_out) {
  const glm::dvec2 c = ps.centre(arc);
  const double radius = std::sqrt(ps.area(arc) / 3.14159265358979);
  const glm::dvec2 normal(std::cos(0.5), std::sin(0.5));
  auto beyond = [&](glm::dvec2 q) { return glm::dot(q - c, normal) > 0.23 * radius; };
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  glm::dvec2 q;
  double a = 0.0, truth = 0.0;
  const int n_truth = 4000000;
  for (int i = 0; i < n_truth; ++i) truth += ps.sample(arc, u(rng), u(rng), &q, &a) && beyond(q);
  truth /= n_truth;
  *truth_out = truth;
  double mse = 0.0;
  for (int t = 0; t < trials; ++t) {
    double hits = 0.0;
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) hits += ps.sample(arc, (i + u(rng)) / k, (j + u(rng)) / k, &q, &a) && beyond(q);
    mse += (hits / (k * k) - truth) * (hits / (k * k) - truth);
  }
  return mse / trials;
}

// The concentric mapping keeps the square's strata compact in the pupil, so stratified samples
// integrate an edge across the pupil better than through the polar mapping, whose strata near
// the centre are slivers. Measured at 16x16 samples on axis, 2000 trials: MSE 4.7e-5 concentric,
// 7.9e-5 polar (ratio 1.69; each MSE is known to about 3%, so 1.3 is over 5 standard deviations
// away), against 8.9e-4 for 256 independent samples (the binomial p (1 - p) / N).
TEST(PupilSampler, ConcentricMappingStratifiesAnEdgeBetterThanPolar) {
  double mse[2], p = 0.0;
  int m = 0;
  for (const char* mapping : {"concentric", "polar"}) {
    auto cam =
        make_eye(std::string("\"float pupildiameter\" 4 \"float fov\" 60 \"string pupilmapping\" \"") + mapping + "\"");
    mse[m++] = edge_fraction_mse(cam->pupil(), 0.0, 16, 2000, &p);
  }
  const double independent = p * (1.0 - p) / 256.0;
  EXPECT_GT(mse[1], 1.3 * mse[0]) << "concentric " << mse[0] << " polar " << mse[1];
  // Both stratify (jittered sampling of an edge: far below the independent samples' error).
  EXPECT_LT(mse[0], independent / 8.0) << "independent " << independent;
  EXPECT_LT(mse[1], independent / 4.0) << "independent " << independent;
}

// The stated area is the polygon's: a fine grid count of contains() agrees within 0.5%.
TEST(PupilSampler, AreaMatchesContainment) {
  auto cam = make_eye("\"float pupildiameter\" 4 \"float fov\" 90");
  const PupilSampler& ps = cam->pupil();
  for (double arc : {0.0, 0.5 * ps.max_arc_mm(), ps.max_arc_mm()}) {
    const glm::dvec2 c = ps.centre(arc);
    const double half = 6.0;
    const int n = 1200;
    int inside = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        inside += ps.contains(arc, c + glm::dvec2(-half + 2 * half * (i + 0.5) / n, -half + 2 * half * (j + 0.5) / n));
    const double counted = inside * (2 * half / n) * (2 * half / n);
    EXPECT_NEAR(counted, ps.area(arc), 0.005 * ps.area(arc)) << arc;
  }
}

// contains() (a rough angle, cross products, and the polygon's inner and outer circles) against
// the crossing-number test on the polygon itself, at random points of a box around it and at
// points near its vertices, where the circles do not decide: every answer the same.
TEST(PupilSampler, ContainsIsThePolygonsCrossingNumberTest) {
  auto cam = make_eye("\"float pupildiameter\" 4 \"float fov\" 90");
  const PupilSampler& ps = cam->pupil();
  const int n = ps.directions();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double arc : {0.0, 0.3 * ps.max_arc_mm(), 0.8 * ps.max_arc_mm(), ps.max_arc_mm()}) {
    ASSERT_GT(ps.area(arc), 0.0) << arc;
    std::vector<glm::dvec2> v;
    double largest = 0.0;
    for (int j = 0; j < n; ++j) {
      const double r = ps.polygon_radius(arc, j), phi = 2.0 * M_PI * j / n;
      v.push_back(r * glm::dvec2(std::cos(phi), std::sin(phi)));
      largest = std::max(largest, r);
    }
    auto crossing_number = [&](glm::dvec2 p) {
      bool in = false;
      for (int j = 0, k = n - 1; j < n; k = j++)
        if ((v[j].y > p.y) != (v[k].y > p.y) && p.x < v[k].x + (p.y - v[k].y) * (v[j].x - v[k].x) / (v[j].y - v[k].y))
          in = !in;
      return in;
    };
    const glm::dvec2 c = ps.centre(arc);
    int mismatches = 0, inside = 0;
    for (int i = 0; i < 200000; ++i) {
      // Half the points in the box, half within 2 % of a vertex's radius of it.
      const glm::dvec2 p =
          i % 2 ? 1.2 * largest * glm::dvec2(u(rng), u(rng))
                : v[size_t(i / 2 % n)] * (1.0 + 0.02 * u(rng)) + 0.02 * largest * glm::dvec2(u(rng), u(rng));
      const bool expected = crossing_number(p);
      inside += expected;
      mismatches += ps.contains(arc, c + p) != expected;
    }
    EXPECT_EQ(mismatches, 0) << arc;
    EXPECT_GT(inside, 40000) << arc;  // both answers well represented
    EXPECT_LT(inside, 160000) << arc;
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
