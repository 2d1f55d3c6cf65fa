// The eye camera through systems that are not rotationally symmetric (symmetric_stand_in.h):
// the envelope's pupil regions hold every ray the real system passes (dense check, with a toric
// cornea, a decentred iris and a measured wavefront on it), the
// camera's irradiance equals an independent integration that never uses the envelope, an
// astigmatic eye blurs lines of one orientation only, by the amount geometric optics gives,
// and the systems the envelope cannot bound are refused by name.
#include "cameras/symmetric_stand_in.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "../support/irradiance_integral.h"
#include "cameras/lens_system_camera.h"
#include "optics/corneal_astigmatism.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/phase_plate.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

constexpr double kArcminPerRad = 60.0 * 180.0 / kPiDouble;

// The relaxed Navarro eye at `pupil` mm, made exactly emmetropic (paraxially) by its length.
optics::Prescription navarro(double pupil) {
  SceneEntity e = parse_directive_text(
      "Camera \"navarro\" \"float wavelength\" 589.3 \"float pupildiameter\" " + std::to_string(pupil), "Camera", "t");
  CameraContext ctx{e.params, Transform(), IVec2(8, 8), ""};
  std::unique_ptr<Camera> c = create_named_eye_camera("navarro")(ctx);
  optics::Prescription p = dynamic_cast<LensSystemCamera&>(*c).prescription();
  optics::set_refraction(p, 0.0);
  return p;
}

// A measured wavefront on the iris (a phase plate of OSA coefficients over the iris's radius):
// oblique and vertical astigmatism, defocus, coma and spherical aberration.
void add_plate(optics::Prescription& p) {
  const int stop = p.stop_index();
  const std::vector<double> c_um = {0, 0, 0, 0.5, 0.3, -0.4, 0, 0.2, -0.15, 0, 0, 0, 0.1};
  p.surfaces[static_cast<size_t>(stop)].phase_plate =
      std::make_shared<optics::PhasePlate>(c_um, p.surfaces[static_cast<size_t>(stop)].semi_diameter_mm);
}

LensSystemCamera camera(const optics::Prescription& p, double fov, int res) {
  LensSystemCamera::Settings s;
  s.fov_deg = fov;
  return LensSystemCamera(p, Transform(), IVec2(res, res), s);
}

TEST(SymmetricStandIn, EnvelopeKeepsTheEyeBehindTheIrisAndHoldsTheDecentredOpening) {
  optics::Prescription p = navarro(4.0);
  optics::set_corneal_cylinder(p, -1.5, 90.0);
  optics::set_pupil_decentration(p, 0.6, -0.8);
  const optics::Prescription env = pupil_envelope(p);
  const int stop = p.stop_index(), env_stop = env.stop_index();
  ASSERT_EQ(env_stop, 1);  // one flat surface in front of the iris
  EXPECT_TRUE(env.rotationally_symmetric());
  EXPECT_DOUBLE_EQ(env.surfaces[1].semi_diameter_mm, 2.0 + 1.0);  // 2 mm + |(0.6, -0.8)|
  EXPECT_DOUBLE_EQ(env.object_index, p.surfaces[static_cast<size_t>(stop) - 1].index_after);
  const std::vector<double> z = p.vertex_z_mm(), ze = env.vertex_z_mm();
  for (size_t i = static_cast<size_t>(stop); i < p.surfaces.size(); ++i)
    EXPECT_DOUBLE_EQ(ze[i - static_cast<size_t>(stop) + 1], z[i]) << i;
  const optics::Prescription eq = symmetric_equivalent(p);
  EXPECT_TRUE(eq.rotationally_symmetric());
  EXPECT_NEAR(eq.surfaces[0].profile.curvature, p.surfaces[0].profile.mean_curvature(), 1e-15);
  add_plate(p);
  EXPECT_TRUE(pupil_envelope(p).rotationally_symmetric());
  EXPECT_TRUE(symmetric_equivalent(p).rotationally_symmetric());
}

// Every ray the real system passes from a retina point lies inside the envelope's polygon for
// that point: random plane points over a square larger than any pupil region, at retina
// points of random arc and azimuth.
TEST(SymmetricStandIn, PupilRegionsHoldEveryPassingRay) {
  optics::Prescription p = navarro(5.0);
  optics::set_corneal_cylinder(p, -3.0, 30.0);
  optics::set_pupil_decentration(p, 0.5, 0.4);
  add_plate(p);
  const LensSystemCamera cam = camera(p, 60.0, 64);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int passing = 0, outside = 0;
  for (int i = 0; i < 400; ++i) {
    const double a = cam.pupil().max_arc_mm() * u(rng), phi = 2.0 * kPiDouble * u(rng);
    const glm::dvec2 m(std::cos(phi), std::sin(phi)), rp = cam.retina().point(a);
    const glm::dvec3 from(rp.x * m.x, rp.x * m.y, rp.y);
    for (int j = 0; j < 1000; ++j) {
      const glm::dvec2 q(8.0 * (2.0 * u(rng) - 1.0), 8.0 * (2.0 * u(rng) - 1.0));  // system frame
      const optics::Ray ray{from, glm::dvec3(q, cam.pupil().z_plane()) - from};
      if (!cam.system().trace_range(ray, cam.system().image_index() - 1, 0).ok()) continue;
      ++passing;
      const glm::dvec2 local(q.x * m.x + q.y * m.y, -q.x * m.y + q.y * m.x);  // meridian frame
      if (!cam.pupil().contains(a, local)) ++outside;
    }
  }
  EXPECT_GT(passing, 10000);
  EXPECT_EQ(outside, 0) << "of " << passing;
}

double mean_weight(const Camera& cam, Vec2 p_film, int n) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      CameraSample cs;
      cs.p_film = p_film;
      cs.p_lens = Vec2(std::min((i + u(rng)) / n, kOneMinusEpsilon), std::min((j + u(rng)) / n, kOneMinusEpsilon));
      const auto r = cam.generate_ray(cs);
      if (r) sum += r->weight[0];
    }
  return sum / (double(n) * n);
}

TEST(SymmetricStandIn, IrradianceMatchesAnIndependentIntegration) {
  optics::Prescription p = navarro(4.0);
  optics::set_corneal_cylinder(p, -2.0, 120.0);
  optics::set_pupil_decentration(p, 0.7, 0.3);
  add_plate(p);
  const LensSystemCamera cam = camera(p, 90.0, 256);
  for (const Vec2 px :
       {Vec2(128.f, 128.f), Vec2(40.f, 128.f), Vec2(216.f, 128.f), Vec2(128.f, 30.f), Vec2(60.f, 200.f)}) {
    const auto rp = cam.retina_point(px);
    ASSERT_TRUE(rp);
    const double independent = cam.weight_normalisation() * test::integrate_irradiance(cam, *rp, 600);
    EXPECT_NEAR(mean_weight(cam, px, 300), independent, 0.01 * independent) << px.x << " " << px.y;
  }
}

// A distant black/white edge through the camera: the fraction of the light at each pixel of
// the row (vertical edge, x) or column (horizontal edge, y) through the image centre.
std::vector<double> edge_profile(const LensSystemCamera& cam, int res, bool vertical_edge) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  std::vector<double> out;
  for (int k = 0; k < res; ++k) {
    double lit = 0.0, all = 0.0;
    for (int s = 0; s < 4096; ++s) {
      CameraSample cs;
      const float along = k + u(rng), across = 0.5f * res;
      cs.p_film = vertical_edge ? Vec2(along, across) : Vec2(across, along);
      cs.p_lens = Vec2(std::min((s % 64 + u(rng)) / 64.f, kOneMinusEpsilon),
                       std::min((s / 64 + u(rng)) / 64.f, kOneMinusEpsilon));
      const auto r = cam.generate_ray(cs);
      if (!r) continue;
      all += r->weight[0];
      if ((vertical_edge ? r->ray.d.x : r->ray.d.y) > 0.f) lit += r->weight[0];
    }
    out.push_back(all > 0.0 ? lit / all : 0.0);
  }
  return out;
}

// Distance (pixels) between where a monotonic profile crosses 0.1 and 0.9.
double width_10_90(const std::vector<double>& f) {
  auto crossing = [&](double level) {
    for (size_t i = 0; i + 1 < f.size(); ++i) {
      const double a = f[i] - level, b = f[i + 1] - level;
      if ((a <= 0.0) != (b <= 0.0)) return double(i) + a / (a - b);
    }
    return -1.0;
  };
  return std::abs(crossing(0.9) - crossing(0.1));
}

// The edge's profile as an independent forward trace predicts it: rays from a distant axial
// point, on a grid over the entrance pupil, traced object -> retina through the real system;
// where they land (in pixels, along the profile's axis) is the line spread, whose cumulative
// sum, averaged over the pixel as the camera's samples are, is the edge profile.
std::vector<double> forward_edge_profile(const LensSystemCamera& cam, double ep_radius, int res, bool x_axis) {
  const auto c0 = cam.retina_point(Vec2(0.5f * res, 0.5f * res)),
             c1 = cam.retina_point(Vec2(0.5f * res + 8.f, 0.5f * res));
  const double mm_per_px = glm::length(c1->position - c0->position) / 8.0;
  std::vector<double> land;
  const int n = 300;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = ep_radius * (2.0 * (i + 0.5) / n - 1.0), y = ep_radius * (2.0 * (j + 0.5) / n - 1.0);
      if (x * x + y * y > ep_radius * ep_radius) continue;
      const optics::TraceResult r = cam.system().trace_forward({{x, y, -5.0}, {0.0, 0.0, 1.0}});
      if (r.ok()) land.push_back((x_axis ? r.ray.origin.x : r.ray.origin.y) / mm_per_px);
    }
  std::sort(land.begin(), land.end());
  std::vector<double> out;
  for (int k = 0; k < res; ++k) {
    double sum = 0.0;
    for (int s = 0; s < 200; ++s) {
      const double edge = k + (s + 0.5) / 200 - 0.5 * res;
      sum += double(std::lower_bound(land.begin(), land.end(), edge) - land.begin()) / land.size();
    }
    out.push_back(sum / 200);
  }
  return out;
}

// Cylinder -1.5 D at axis 90 (a minus cylinder: the horizontal meridian is 1.5 D too strong,
// the vertical one in focus): a distant point is drawn out into a horizontal line, so a
// vertical edge blurs and a horizontal one stays sharp. The widths agree with the forward
// trace, and the vertical edge's with the closed form of pure defocus in one meridian (light
// spread as the pupil's width, a semicircle law over D_EP x 1.5 D), to within what the eye's
// own spherical aberration adds.
TEST(SymmetricStandIn, AstigmaticEyeBlursOneOrientationAsGeometricOpticsSays) {
  const double pupil = 3.0, cylinder = -1.5, fov = 1.0;
  const int res = 96;
  optics::Prescription p = navarro(pupil);
  const double ep_mm = optics::paraxial_analysis(p).entrance_pupil.diameter_mm;
  optics::set_corneal_cylinder(p, cylinder, 90.0);
  const LensSystemCamera cam = camera(p, fov, res);
  const double arcmin_per_px = fov * 60.0 / res;
  const double vertical = width_10_90(edge_profile(cam, res, true)) * arcmin_per_px;
  const double horizontal = width_10_90(edge_profile(cam, res, false)) * arcmin_per_px;
  const double traced_x = width_10_90(forward_edge_profile(cam, 0.55 * ep_mm, res, true)) * arcmin_per_px;
  const double traced_y = width_10_90(forward_edge_profile(cam, 0.55 * ep_mm, res, false)) * arcmin_per_px;
  EXPECT_NEAR(vertical, traced_x, 0.05 * traced_x);
  EXPECT_NEAR(horizontal, traced_y, 0.1 * traced_y + 0.1 * arcmin_per_px);
  EXPECT_LT(horizontal, 0.25 * vertical);

  const double radius_px = 0.5 * ep_mm * 1e-3 * std::abs(cylinder) * kArcminPerRad / arcmin_per_px;
  auto semicircle_cdf = [](double t) {
    t = std::clamp(t, -1.0, 1.0);
    return 0.5 + (t * std::sqrt(1.0 - t * t) + std::asin(t)) / kPiDouble;
  };
  std::vector<double> closed_form;
  for (int k = 0; k < res; ++k) {
    double sum = 0.0;
    for (int s = 0; s < 200; ++s) sum += semicircle_cdf((k + (s + 0.5) / 200 - 0.5 * res) / radius_px);
    closed_form.push_back(sum / 200);
  }
  const double predicted = width_10_90(closed_form) * arcmin_per_px;
  EXPECT_GT(vertical, predicted);  // aberrations only add
  EXPECT_LT(vertical, predicted + 1.5 * horizontal);

  // The same eye without the cylinder blurs neither.
  const LensSystemCamera plain = camera(navarro(pupil), fov, res);
  EXPECT_LT(width_10_90(edge_profile(plain, res, true)) * arcmin_per_px, 0.25 * vertical);
  std::printf("vertical %.3f (traced %.3f, closed form %.3f) horizontal %.3f (traced %.3f) arcmin\n", vertical,
              traced_x, predicted, horizontal, traced_y);
}

TEST(SymmetricStandIn, RefusesWhatTheEnvelopeCannotBound) {
  optics::Prescription tilted_lens = navarro(4.0);
  const int stop = tilted_lens.stop_index();
  tilted_lens.surfaces[static_cast<size_t>(stop) + 1].placement.tilt_x_deg = 2.0;
  try {
    (void)pupil_envelope(tilted_lens);
    FAIL() << "no error";
  } catch (const optics::OpticsError& e) {
    EXPECT_NE(std::string(e.what()).find("between the iris and the image"), std::string::npos) << e.what();
  }
  optics::Prescription tilted_iris = navarro(4.0);
  tilted_iris.surfaces[static_cast<size_t>(stop)].placement.tilt_y_deg = 5.0;
  EXPECT_THROW((void)pupil_envelope(tilted_iris), optics::OpticsError);

  optics::Prescription astigmat = navarro(4.0);
  optics::set_corneal_cylinder(astigmat, -1.0, 10.0);
  LensSystemCamera::Settings s;
  s.diffraction = true;
  try {
    LensSystemCamera(astigmat, Transform(), IVec2(8, 8), s);
    FAIL() << "no error";
  } catch (const optics::OpticsError& e) {
    EXPECT_EQ(e.option(), "diffraction");
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
