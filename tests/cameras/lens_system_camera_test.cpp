// The lens-system (eye) camera: irradiance normalisation and fall-off against an independent
// integration, geometry (axis, symmetry, upright image), focus against paraxial optics and the
// thin-lens camera, determinism.
#include "cameras/lens_system_camera.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include <fmt/format.h>

#include "../support/irradiance_integral.h"
#include "cameras/perspective_camera.h"
#include "filters/box_filter.h"
#include "filters/gaussian_filter.h"
#include "optics/paraxial.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// Monochromatic at 589.3 nm unless the test names a wavelength: these tests check geometry
// (focus, mapping, reversibility) at the reference wavelength; dispersion is tested apart.
std::unique_ptr<LensSystemCamera> eye_camera(const std::string& params, IVec2 res = IVec2(256, 256)) {
  const std::string mono = params.find("wavelength") == std::string::npos ? " \"float wavelength\" 589.3" : "";
  SceneEntity e = parse_directive_text("Camera \"eye\" " + params + mono, "Camera", "test");
  CameraContext ctx{e.params, Transform(), res, ""};
  std::unique_ptr<Camera> c = create_eye_camera(ctx);
  return std::unique_ptr<LensSystemCamera>(dynamic_cast<LensSystemCamera*>(c.release()));
}

// Mean weight (lost rays count 0) and its standard error over jittered-stratified lens samples.
struct Estimate {
  double mean = 0.0, stderr_ = 0.0;
};
Estimate mean_weight(const Camera& cam, Vec2 p_film, int n, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      CameraSample cs;
      cs.p_film = p_film;
      cs.p_lens = Vec2(std::min((i + u(rng)) / n, kOneMinusEpsilon), std::min((j + u(rng)) / n, kOneMinusEpsilon));
      auto r = cam.generate_ray(cs);
      const double w = r ? r->weight[0] : 0.0;
      sum += w;
      sum2 += w * w;
    }
  const double count = double(n) * n, mean = sum / count;
  // The i.i.d. standard error bounds the stratified one from above.
  return {mean, std::sqrt(std::max(0.0, sum2 / count - mean * mean) / count)};
}

// Raster position at visual field angle theta (degrees) along screen direction (cos, sin) of
// an "angle"-mapped camera with a square image of res pixels and the given fov.
Vec2 pixel_at_field(double theta, double azimuth_deg, double fov, int res) {
  const double s = theta / (0.5 * fov), phi = azimuth_deg * kPiDouble / 180.0;
  return Vec2(float(0.5 * res * (1.0 + s * std::cos(phi))), float(0.5 * res * (1.0 - s * std::sin(phi))));
}

// Depth (camera z) at which the rays of a bundle come closest together (smallest RMS radius),
// searched on a log scale between z0 and z1, and that radius.
std::pair<double, double> best_focus(const std::vector<Ray>& rays, double z0, double z1) {
  auto rms = [&](double z) {
    glm::dvec2 c(0.0), c2(0.0);
    for (const Ray& r : rays) {
      const double t = (z - r.o.z) / r.d.z;
      const glm::dvec2 p(r.o.x + t * r.d.x, r.o.y + t * r.d.y);
      c += p;
      c2 += p * p;
    }
    c /= double(rays.size());
    c2 /= double(rays.size());
    return std::sqrt(std::max(0.0, c2.x - c.x * c.x + c2.y - c.y * c.y));
  };
  double lo = std::log(z0), hi = std::log(z1), best = lo;
  for (int pass = 0; pass < 4; ++pass) {
    double best_rms = 1e300;
    for (int i = 0; i <= 200; ++i) {
      const double x = lo + (hi - lo) * i / 200;
      const double r = rms(std::exp(x));
      if (r < best_rms) best_rms = r, best = x;
    }
    const double step = (hi - lo) / 200;
    lo = best - 2 * step;
    hi = best + 2 * step;
  }
  return {std::exp(best), rms(std::exp(best))};
}

std::vector<Ray> bundle(const Camera& cam, Vec2 p_film, int n) {
  std::vector<Ray> rays;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      CameraSample cs;
      cs.p_film = p_film;
      cs.p_lens = Vec2((i + 0.5f) / n, (j + 0.5f) / n);
      if (auto r = cam.generate_ray(cs)) rays.push_back(r->ray);
    }
  return rays;
}

// A uniform white scene: the mean weight at the image centre is the radiance, 1. Tolerance:
// 5 standard errors (i.i.d. bound) of a 256 x 256 jittered estimate.
TEST(LensSystemCamera, UniformSceneCentreMeanWeightIsOne) {
  for (const char* params :
       {"\"float pupildiameter\" 5", "\"string model\" \"gullstrand\" \"float pupildiameter\" 2",
        "\"string model\" \"legrand\" \"float pupildiameter\" 8 \"float accommodation\" 3",
        "\"string model\" \"kooijman\"", "\"float accommodation\" 6 \"string mapping\" \"retina\""}) {
    auto cam = eye_camera(params);
    const Estimate e = mean_weight(*cam, Vec2(128.f, 128.f), 256, 1);
    EXPECT_NEAR(e.mean, 1.0, 5.0 * e.stderr_ + 1e-4) << params;
  }
}

// The camera's relative illumination equals an independent integral of cos(theta) over the
// directions that pass the traced eye (normalised by the same centre value), and falls off
// with field angle. Tolerance 1%: the cone integral's grid and both estimates' noise are below
// 0.3% at these sample counts.
TEST(LensSystemCamera, RelativeIlluminationMatchesIndependentIntegral) {
  auto cam = eye_camera("\"float pupildiameter\" 5 \"float fov\" 120", IVec2(512, 512));
  double previous = 2.0;
  for (double theta : {0.0, 15.0, 30.0, 45.0, 55.0}) {
    const Vec2 p = pixel_at_field(theta, 30.0, 120.0, 512);
    const Estimate e = mean_weight(*cam, p, 300, 2);
    const auto rp = cam->retina_point(p);
    ASSERT_TRUE(rp);
    const double independent = cam->weight_normalisation() * test::integrate_irradiance(*cam, *rp, 700);
    EXPECT_NEAR(e.mean, independent, 0.01 * independent) << theta;
    EXPECT_LT(e.mean, previous + 5.0 * e.stderr_) << theta;  // non-increasing within noise
    previous = e.mean;
  }
  EXPECT_LT(previous, 0.9);  // and the fall-off is real by 55 degrees
}

TEST(LensSystemCamera, AxialRayLeavesAlongTheAxis) {
  auto cam = eye_camera("\"float pupildiameter\" 5 \"float sceneunit\" 0.001");
  CameraSample cs;
  cs.p_film = Vec2(128.f, 128.f);
  cs.p_lens = Vec2(0.5f, 0.5f);  // the concentric map's centre: the pupil region's, on the axis here
  auto r = cam->generate_ray(cs);
  ASSERT_TRUE(r);
  EXPECT_NEAR(r->ray.d.x, 0.f, 1e-6f);
  EXPECT_NEAR(r->ray.d.y, 0.f, 1e-6f);
  EXPECT_NEAR(r->ray.d.z, 1.f, 1e-9f);
  // Leaves from the corneal vertex (scene unit = mm here).
  EXPECT_NEAR(r->ray.o.x, 0.f, 1e-5f);
  EXPECT_NEAR(r->ray.o.y, 0.f, 1e-5f);
  EXPECT_NEAR(r->ray.o.z, 0.f, 1e-5f);
}

// Rotating the pixel by 90 degrees about the image centre rotates the ray by 90 degrees about
// the camera axis (the eye is rotationally symmetric), for every lens sample.
TEST(LensSystemCamera, RotatedRetinaPointsGiveRotatedRays) {
  auto cam = eye_camera("\"float pupildiameter\" 6 \"float fov\" 90");
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  int compared = 0;
  for (int i = 0; i < 2000; ++i) {
    const int dx = 1 + int(u(rng) * 120), dy = int(u(rng) * 120);  // off the centre, where no azimuth exists
    CameraSample a, b;
    a.p_film = Vec2(128.f + dx, 128.f - dy);
    b.p_film = Vec2(128.f - dy, 128.f - dx);  // screen (sx, sy) rotated to (-sy, sx)
    a.p_lens = b.p_lens = Vec2(u(rng), u(rng));
    auto ra = cam->generate_ray(a), rb = cam->generate_ray(b);
    ASSERT_EQ(bool(ra), bool(rb));
    if (!ra) continue;
    ++compared;
    EXPECT_NEAR(rb->ray.d.x, -ra->ray.d.y, 2e-6f);
    EXPECT_NEAR(rb->ray.d.y, ra->ray.d.x, 2e-6f);
    EXPECT_NEAR(rb->ray.d.z, ra->ray.d.z, 2e-6f);
    EXPECT_NEAR(rb->ray.o.x, -ra->ray.o.y, 1e-8f);
    EXPECT_NEAR(rb->ray.o.y, ra->ray.o.x, 1e-8f);
    EXPECT_NEAR(rb->weight[0], ra->weight[0], 1e-5f * ra->weight[0]);
  }
  EXPECT_GT(compared, 1800);
}

// A scene point up-left of the axis must appear up-left in the image: the ray through an
// upper-left pixel goes up (+y) and left (-x) in camera space.
TEST(LensSystemCamera, ImageIsUprightAndNotMirrored) {
  for (const char* params :
       {"", "\"string mapping\" \"flat\"", "\"string mapping\" \"retina\"", "\"string model\" \"gullstrand\""}) {
    auto cam = eye_camera(params);
    CameraSample cs;
    cs.p_film = Vec2(40.f, 60.f);  // left of and above the centre (raster y grows downwards)
    cs.p_lens = Vec2(0.5f, 0.5f);  // the pupil region's centre (concentric map)
    auto r = cam->generate_ray(cs);
    ASSERT_TRUE(r) << params;
    EXPECT_LT(r->ray.d.x, -0.1f) << params;
    EXPECT_GT(r->ray.d.y, 0.05f) << params;
    // The more left than up the pixel, the more left than up the ray.
    EXPECT_GT(-r->ray.d.x, r->ray.d.y) << params;
  }
}

// Accommodation: rays from the retina centre (0.5 mm pupil: little spherical aberration) meet
// where paraxial optics puts the eye's far point, -1/refraction metres in front of the cornea.
// Tolerance 0.012 D: the best focus departs from the paraxial one by the eye's spherical
// aberration, which grows with the pupil squared (measured: up to 0.033 D at 1 mm, 0.008 D at
// 0.5 mm, at D = 8).
TEST(LensSystemCamera, AccommodatedEyeFocusesAtParaxialFarPoint) {
  for (double accommodation : {1.0, 2.0, 4.0, 8.0}) {
    auto cam = eye_camera(fmt::format("\"float pupildiameter\" 0.5 \"float accommodation\" {}", accommodation));
    const double refraction = optics::refraction_D(cam->prescription());
    ASSERT_LT(refraction, -0.5);
    const auto [z, rms] = best_focus(bundle(*cam, Vec2(128.f, 128.f), 40), 0.02, 50.0);
    EXPECT_NEAR(1.0 / z, -refraction, 0.012) << accommodation;
    EXPECT_LT(rms, 2e-5) << accommodation;  // a real focus: 20 um across
  }
  // Relaxed (emmetropic) eye: the bundle stays about a pupil wide out to 100 m.
  auto cam = eye_camera("\"float pupildiameter\" 1");
  std::vector<Ray> rays = bundle(*cam, Vec2(128.f, 128.f), 40);
  double spread = 0.0;
  for (const Ray& r : rays) spread = std::max(spread, double(std::hypot(r.at(100.f / r.d.z).x, r.at(100.f / r.d.z).y)));
  EXPECT_LT(spread, 0.003);  // 3 mm at 100 m (a 1 mm pupil; 0.01 D would add 1 mm)
}

// A realistic camera with one thin lens (f = 100 mm) focuses where the thin-lens camera with
// the same aperture and focus distance does: pbrt measures focusdistance from the film, so the
// plane of focus lies focusdistance - (film to front vertex) in front of the lens.
TEST(LensSystemCamera, ThinLensFileFocusesLikeThinLensCamera) {
  const std::string dir = ::testing::TempDir();
  {
    std::ofstream f(dir + "/eyecam_thin.dat");
    f << "# radius thickness eta aperture\n0 0 0 8\n100 0.3 1.5 8\n-100 100 0 8\n";
  }
  SceneEntity e = parse_directive_text(
      "Camera \"realistic\" \"string lensfile\" \"eyecam_thin.dat\" \"float aperturediameter\" 4 "
      "\"float focusdistance\" 2 \"float filmdiagonal\" 10",
      "Camera", "test");
  CameraContext ctx{e.params, Transform(), IVec2(128, 128), dir};
  std::unique_ptr<Camera> realistic = create_realistic_camera(ctx);
  auto* lens = dynamic_cast<LensSystemCamera*>(realistic.get());
  ASSERT_TRUE(lens);
  const double track_m = lens->prescription().axial_length_mm() * 1e-3;
  EXPECT_NEAR(track_m, 0.1 + 0.1 * 0.1 / (2.0 - 0.2), 0.001);  // thin-lens film distance, about 105.6 mm

  PerspectiveCamera::Settings s;
  s.fov_deg = 30.f;
  s.lens_radius = 0.002f;
  s.focal_distance = float(2.0 - track_m);
  PerspectiveCamera thin(Transform(), IVec2(128, 128), s);

  const auto [z_real, rms_real] = best_focus(bundle(*realistic, Vec2(64.f, 64.f), 40), 0.2, 20.0);
  const auto [z_thin, rms_thin] = best_focus(bundle(thin, Vec2(64.f, 64.f), 40), 0.2, 20.0);
  EXPECT_NEAR(z_thin, s.focal_distance, 1e-3 * s.focal_distance);
  EXPECT_NEAR(z_real, z_thin, 0.01 * z_thin);
  EXPECT_LT(rms_real, 1e-3);
}

// A real multi-element lens through "realistic": the double Gauss of pbrt's lens collection
// (US patent 2,673,491, scaled to 50 mm). At the image centre the mean weight is 1; most
// generated rays pass; the image is upright.
TEST(LensSystemCamera, DoubleGaussLensFile) {
  const std::string dir = ::testing::TempDir();
  {
    std::ofstream f(dir + "/eyecam_dgauss.dat");
    f << "# radius thickness index aperture\n"
         "29.475 3.76 1.67 25.2\n84.83 0.12 1 25.2\n19.275 4.025 1.67 23\n40.77 3.275 1.699 23\n"
         "12.75 5.705 1 18\n0 4.5 0 17.1\n-14.495 1.18 1.603 17\n40.77 6.065 1.658 20\n"
         "-20.385 0.19 1 20\n437.065 3.22 1.717 20\n-39.73 40 1 20\n";
  }
  SceneEntity e = parse_directive_text(
      "Camera \"realistic\" \"string lensfile\" \"eyecam_dgauss.dat\" \"float aperturediameter\" 17 "
      "\"float focusdistance\" 5",
      "Camera", "test");
  CameraContext ctx{e.params, Transform(), IVec2(300, 200), dir};
  std::unique_ptr<Camera> cam = create_realistic_camera(ctx);
  const Estimate centre = mean_weight(*cam, Vec2(150.f, 100.f), 200, 4);
  EXPECT_NEAR(centre.mean, 1.0, 5.0 * centre.stderr_ + 1e-4);
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  int ok = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    CameraSample cs;
    cs.p_film = Vec2(300 * u(rng), 200 * u(rng));
    cs.p_lens = Vec2(u(rng), u(rng));
    ok += cam->generate_ray(cs).has_value();
  }
  std::printf("double Gauss, 17 mm stop, 35 mm film: useful ray fraction %.4f\n", double(ok) / n);
  EXPECT_GT(double(ok) / n, 0.9);
  CameraSample cs;
  cs.p_film = Vec2(20.f, 30.f);  // upper left
  cs.p_lens = Vec2(0.5f, 0.5f);  // the pupil region's centre (concentric map)
  auto r = cam->generate_ray(cs);
  ASSERT_TRUE(r);
  EXPECT_LT(r->ray.d.x, 0.f);
  EXPECT_GT(r->ray.d.y, 0.f);
}

// pbrt-v4's realistic camera has a shutter (CameraBase): the time sample u becomes
// (1 - u) shutteropen + u shutterclose, and a moving camera sits where it is then. With
// TransformTimes 0 2 (+4 along x) and the shutter 1 to 3, u = 0.25 is time 1.5, 3 units along.
TEST(LensSystemCamera, RealisticCameraSpreadsTheTimeOverItsShutter) {
  const std::string dir = ::testing::TempDir();
  {
    std::ofstream f(dir + "/eyecam_singlet.dat");
    f << "0 5 0 10\n50 5 1.5 20\n-50 45 1 20\n";  // a stop, then a biconvex singlet
  }
  auto make = [&](const std::string& shutter, bool moving) {
    SceneEntity e = parse_directive_text(
        "Camera \"realistic\" \"string lensfile\" \"eyecam_singlet.dat\" \"float aperturediameter\" 10 " + shutter,
        "Camera", "test");
    CameraContext ctx{e.params, Transform(), IVec2(64, 64), dir};
    if (moving) ctx.world_from_camera_motion = AnimatedTransform(Transform(), 0.f, translate(Vec3(4, 0, 0)), 2.f);
    return create_realistic_camera(ctx);
  };
  CameraSample cs;
  cs.p_film = Vec2(32.f, 32.f);
  cs.p_lens = Vec2(0.5f, 0.5f);
  cs.time = 0.25f;
  auto still = make("", false)->generate_ray(cs);
  auto moved = make("\"float shutteropen\" 1 \"float shutterclose\" 3", true)->generate_ray(cs);
  ASSERT_TRUE(still);
  ASSERT_TRUE(moved);
  EXPECT_EQ(still->ray.time, 0.25f);  // the default shutter, 0 to 1
  EXPECT_FLOAT_EQ(moved->ray.time, 1.5f);
  EXPECT_NEAR(glm::length(moved->ray.o - (still->ray.o + Vec3(3, 0, 0))), 0.f, 1e-5f);
  EXPECT_NEAR(glm::length(moved->ray.d - still->ray.d), 0.f, 1e-6f);
}

TEST(LensSystemCamera, SameSampleGivesSameRay) {
  auto cam = eye_camera("\"float pupildiameter\" 5 \"float accommodation\" 2");
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  for (int i = 0; i < 1000; ++i) {
    CameraSample cs;
    cs.p_film = Vec2(256 * u(rng), 256 * u(rng));
    cs.p_lens = Vec2(u(rng), u(rng));
    auto a = cam->generate_ray(cs), b = cam->generate_ray(cs);
    ASSERT_EQ(bool(a), bool(b));
    if (!a) continue;
    EXPECT_EQ(a->ray.o, b->ray.o);
    EXPECT_EQ(a->ray.d, b->ray.d);
    EXPECT_EQ(a->weight[0], b->weight[0]);
  }
}

// Camera placement: the eye sits at the camera origin looking along camera +z, so the world
// ray is world_from_camera applied to the camera-space ray.
TEST(LensSystemCamera, WorldTransformIsApplied) {
  SceneEntity e = parse_directive_text("Camera \"navarro\" \"float pupildiameter\" 3", "Camera", "test");
  const Transform world_from_camera = look_at(Vec3(1, 2, 3), Vec3(1, 2, 10), Vec3(0, 1, 0)).inverse();
  CameraContext ctx{e.params, world_from_camera, IVec2(64, 64), ""};
  std::unique_ptr<Camera> cam = create_named_eye_camera("navarro")(ctx);
  auto* lens = dynamic_cast<LensSystemCamera*>(cam.get());
  CameraSample cs;
  cs.p_film = Vec2(20.f, 50.f);
  cs.p_lens = Vec2(0.3f, 0.6f);
  auto r = cam->generate_ray(cs);
  ASSERT_TRUE(r);
  // Same ray as the identity-placed camera, moved by +(1,2,3) and looking down world +z.
  SceneEntity e2 = parse_directive_text("Camera \"navarro\" \"float pupildiameter\" 3", "Camera", "test");
  CameraContext ctx2{e2.params, Transform(), IVec2(64, 64), ""};
  auto r0 = create_named_eye_camera("navarro")(ctx2)->generate_ray(cs);
  ASSERT_TRUE(r0);
  EXPECT_NEAR(r->ray.o.x, r0->ray.o.x + 1.f, 1e-6f);
  EXPECT_NEAR(r->ray.o.y, r0->ray.o.y + 2.f, 1e-6f);
  EXPECT_NEAR(r->ray.o.z, r0->ray.o.z + 3.f, 1e-6f);
  EXPECT_NEAR(glm::length(r->ray.d - r0->ray.d), 0.f, 1e-6f);
  EXPECT_NE(lens->to_string().find("navarro"), std::string::npos);
}

// Motion blur: an eye moving 2 units along +z over the TransformTimes 0 1 sends the ray of a
// sample with time 0.25 from where the still eye's ray leaves, moved by 0.5.
TEST(LensSystemCamera, MovingEyeIsPlacedAtTheSampleTime) {
  SceneEntity e = parse_directive_text("Camera \"navarro\" \"float pupildiameter\" 3", "Camera", "test");
  CameraContext ctx{e.params, Transform(), IVec2(64, 64), ""};
  ctx.world_from_camera_motion = AnimatedTransform(Transform(), 0.f, translate(Vec3(0, 0, 2)), 1.f);
  std::unique_ptr<Camera> moving = create_named_eye_camera("navarro")(ctx);
  SceneEntity e2 = parse_directive_text("Camera \"navarro\" \"float pupildiameter\" 3", "Camera", "test");
  CameraContext still{e2.params, Transform(), IVec2(64, 64), ""};
  std::unique_ptr<Camera> cam0 = create_named_eye_camera("navarro")(still);
  CameraSample cs;
  cs.p_film = Vec2(20.f, 50.f);
  cs.p_lens = Vec2(0.3f, 0.6f);
  cs.time = 0.25f;
  auto r = moving->generate_ray(cs), r0 = cam0->generate_ray(cs);
  ASSERT_TRUE(r);
  ASSERT_TRUE(r0);
  EXPECT_NEAR(glm::length(r->ray.o - (r0->ray.o + Vec3(0, 0, 0.5f))), 0.f, 1e-6f);
  EXPECT_NEAR(glm::length(r->ray.d - r0->ray.d), 0.f, 1e-6f);
  EXPECT_EQ(r->ray.time, 0.25f);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// generate_rays (the batch path the integrator takes) must equal generate_ray sample by
// sample, bit for bit, lost rays included, for every eye model and a batch size that is not a
// multiple of the internal batch.
TEST(LensSystemCamera, BatchGenerationEqualsSingle) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  for (const char* model : {"navarro", "gullstrand", "legrand", "kooijman", "arizona"}) {
    auto cam = eye_camera(fmt::format("\"string model\" \"{}\" \"float pupildiameter\" 6 \"float fov\" 100", model));
    std::vector<CameraSample> samples(203);
    for (CameraSample& cs : samples) {
      cs.p_film = Vec2(256.f * u(rng), 256.f * u(rng));
      cs.p_lens = Vec2(u(rng), u(rng));
      cs.time = u(rng);
    }
    std::vector<std::optional<CameraRay>> batch(samples.size());
    cam->generate_rays(samples.data(), batch.data(), samples.size());
    int lost = 0;
    for (size_t i = 0; i < samples.size(); ++i) {
      const std::optional<CameraRay> one = cam->generate_ray(samples[i]);
      ASSERT_EQ(one.has_value(), batch[i].has_value()) << model << " sample " << i;
      if (!one) {
        ++lost;
        continue;
      }
      EXPECT_EQ(one->ray.o, batch[i]->ray.o);
      EXPECT_EQ(one->ray.d, batch[i]->ray.d);
      EXPECT_EQ(one->ray.time, batch[i]->ray.time);
      EXPECT_EQ(one->weight[0], batch[i]->weight[0]);
    }
    EXPECT_LT(lost, int(samples.size()));
  }
}

// The same for the dispersive eye's spectral MIS: every wavelength's weight and pixel, with a
// Gaussian filter (weights within the pixel) and a box filter splatting within a tile.
TEST(LensSystemCamera, BatchGenerationEqualsSingleWithSpectralMis) {
  SceneEntity e = parse_directive_text("Camera \"navarro\" \"float pupildiameter\" 6 \"float fov\" 60", "Camera", "t");
  CameraContext ctx{e.params, Transform(), IVec2(64, 64), ""};
  std::unique_ptr<Camera> cam = create_named_eye_camera("navarro")(ctx);
  const BoxFilter box(Vec2(0.5f));
  const GaussianFilter gaussian(Vec2(1.5f), 0.5f);
  std::mt19937 rng(12);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  for (const Filter* filter : {static_cast<const Filter*>(&box), static_cast<const Filter*>(&gaussian)}) {
    std::vector<CameraSample> samples(203);
    std::vector<SampledWavelengths> lambdas, single;
    for (CameraSample& cs : samples) {
      const IVec2 pixel(int(64 * u(rng)), int(64 * u(rng)));
      const FilterSample fs = filter->sample(Vec2(u(rng), u(rng)));
      cs.p_film = Vec2(pixel) + Vec2(0.5f) + fs.offset;
      cs.p_lens = Vec2(u(rng), u(rng));
      cs.filter = filter, cs.filter_offset = fs.offset, cs.filter_weight = fs.weight;
      cs.splat = filter == &box, cs.splat_lo = pixel / 16 * 16, cs.splat_hi = cs.splat_lo + IVec2(16);
      lambdas.push_back(SampledWavelengths::sample_visible(u(rng)));
    }
    single = lambdas;
    std::vector<std::optional<CameraRay>> batch(samples.size());
    cam->generate_rays(samples.data(), lambdas.data(), batch.data(), samples.size());
    int splatted = 0;
    for (size_t i = 0; i < samples.size(); ++i) {
      const std::optional<CameraRay> one = cam->generate_ray(samples[i], single[i]);
      ASSERT_EQ(one.has_value(), batch[i].has_value()) << i;
      if (!one) continue;
      EXPECT_EQ(one->ray.d, batch[i]->ray.d);
      for (int k = 0; k < kSpectrumSamples; ++k) {
        EXPECT_EQ(one->weight[k], batch[i]->weight[k]) << i << " " << k;
        EXPECT_EQ(one->pixel_offset[k], batch[i]->pixel_offset[k]) << i << " " << k;
        EXPECT_EQ(single[i].pdf()[k], lambdas[i].pdf()[k]);
        splatted += one->pixel_offset[k] != IVec2(0);
      }
    }
    if (filter == &box) EXPECT_GT(splatted, 0);  // the case is tested
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
