// The diffracting eye camera (Camera "bool diffraction", cameras/camera_diffraction.cpp and
// wave_psf_table.h): its rays' directions have the wave PSF's first moment where the traced rays
// have theirs (the centroid of a PSF is the mean transverse ray aberration: Mahajan, "Optical
// Imaging and Aberrations" II, 2.2; so a sign error in turning the PSF into directions shows),
// the same sample gives the same ray, a dispersive eye keeps the hero wavelength only, and the
// cameras that cannot diffract say so naming the parameter.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "../support/unity_id.h"
#include "cameras/lens_system_camera.h"
#include "cameras/perspective_camera.h"
#include "core/error.h"
#include "filters/box_filter.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

const IVec2 kResolution(64, 64);

std::unique_ptr<LensSystemCamera> eye(const std::string& params) {
  SceneEntity e = parse_directive_text("Camera \"navarro\" " + params, "Camera", "test");
  CameraContext ctx{e.params, Transform(), kResolution, ""};
  std::unique_ptr<Camera> c = create_named_eye_camera("navarro")(ctx);
  return std::unique_ptr<LensSystemCamera>(dynamic_cast<LensSystemCamera*>(c.release()));
}

// Mean direction (unit vector of the weighted mean) of the rays from one raster point.
Vec3 mean_direction(const LensSystemCamera& cam, Vec2 p_film, int n) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  glm::dvec3 sum(0.0);
  for (int i = 0; i < n; ++i) {
    CameraSample cs;
    cs.p_film = p_film;
    cs.p_lens = Vec2(u(rng), u(rng));
    cs.time = u(rng);
    const std::optional<CameraRay> r = cam.generate_ray(cs);
    if (r) sum += double(r->weight[0]) * glm::dvec3(r->ray.d);
  }
  return Vec3(glm::normalize(sum));
}

// A 2 mm pupil at 555 nm; the raster point 10 degrees right of the centre (mapping "angle",
// 30 degree field over 64 pixels). Coma puts the image's centroid inside the chief ray's image,
// so the rays leaving one retina point have their mean 0.5 arcmin outside the chief ray's
// direction; the PSF's rays must have the same mean to Monte Carlo accuracy.
TEST(CameraDiffraction, RaysHaveTheTracedRaysMeanDirectionOffAxis) {
  const std::string params = "\"float pupildiameter\" 2 \"float wavelength\" 555 \"float fov\" 30";
  const auto geometric = eye(params), diffracting = eye(params + " \"bool diffraction\" true");
  ASSERT_TRUE(diffracting->diffraction());
  ASSERT_FALSE(geometric->diffraction());
  const Vec2 p(32.f + 32.f * 10.f / 15.f, 32.f);
  const int n = 40000;
  const Vec3 g = mean_direction(*geometric, p, n), d = mean_direction(*diffracting, p, n);
  const double arcmin = 180.0 * 60.0 / kPiDouble;
  const double field_g = std::atan2(double(g.x), double(g.z)) * arcmin,
               field_d = std::atan2(double(d.x), double(d.z)) * arcmin;
  std::printf("mean field angle: traced %.4f arcmin, diffracting %.4f arcmin (pixel's chief ray 600 arcmin)\n", field_g,
              field_d);
  EXPECT_NEAR(field_g, 600.0, 1.0);             // the mapping: the pixel's chief ray is at 10 degrees
  EXPECT_GT(field_g, 600.0 + 0.2);              // coma: the traced mean is outside the chief ray
  EXPECT_NEAR(field_d, field_g, 0.1);           // a flipped PSF would be 1 arcmin off
  EXPECT_NEAR(double(d.y), double(g.y), 3e-5);  // nothing across the meridian
}

TEST(CameraDiffraction, TheSameSampleGivesTheSameRay) {
  const auto cam = eye("\"float pupildiameter\" 2 \"float wavelength\" 555 \"float fov\" 30 \"bool diffraction\" true");
  CameraSample a;
  a.p_film = Vec2(20.3f, 40.7f);
  a.p_lens = Vec2(0.3f, 0.6f);
  CameraSample b = a;
  b.p_lens.x = 0.30001f;
  const auto ra = cam->generate_ray(a), ra2 = cam->generate_ray(a), rb = cam->generate_ray(b);
  ASSERT_TRUE(ra && ra2 && rb);
  EXPECT_EQ(ra->ray.d, ra2->ray.d);
  EXPECT_EQ(ra->ray.o, ra2->ray.o);
  EXPECT_NE(ra->ray.d, rb->ray.d);  // a different sample draws another PSF offset
  // The batch equals the single rays.
  CameraSample samples[3] = {a, b, a};
  std::optional<CameraRay> rays[3];
  cam->generate_rays(samples, rays, 3);
  EXPECT_EQ(rays[0]->ray.d, ra->ray.d);
  EXPECT_EQ(rays[1]->ray.d, rb->ray.d);
}

// Spectral MIS is bypassed, consistently: the secondaries are terminated even when the sample
// names its filter, and the camera does not splat; the hero alone is the plain estimator that
// tests/cameras/spectral_mis_slowtest.cpp takes as the reference.
TEST(CameraDiffraction, DispersiveEyeKeepsTheHeroWavelengthOnly) {
  const auto cam = eye("\"float pupildiameter\" 2 \"float fov\" 30 \"bool diffraction\" true");
  ASSERT_TRUE(cam->dispersive());
  EXPECT_FALSE(cam->splats());
  EXPECT_TRUE(eye("\"float pupildiameter\" 2 \"float fov\" 30")->splats());
  const BoxFilter box(Vec2(0.5f));
  CameraSample cs;
  cs.p_film = Vec2(30.5f, 31.5f);
  cs.p_lens = Vec2(0.4f, 0.5f);
  cs.filter = &box;
  SampledWavelengths lambda = SampledWavelengths::sample_visible(0.3f);
  const auto r = cam->generate_ray(cs, lambda);
  ASSERT_TRUE(r);
  EXPECT_TRUE(lambda.secondary_terminated());
  EXPECT_GT(cam->psf_table()->wavelength_nodes(), 5);
}

// A 5 mm iris (5.7 mm entrance pupil) at 555 nm: every PSF of the table is wider than a 128
// pupil grid can hold (phase steps above pi/2), i.e. aberration-dominated, so every node is left
// geometric and the rays are the traced ones, bit for bit.
TEST(CameraDiffraction, AberrationDominatedNodesKeepTheTracedRays) {
  const std::string params = "\"float pupildiameter\" 5 \"float wavelength\" 555 \"float fov\" 30";
  const auto geometric = eye(params), diffracting = eye(params + " \"bool diffraction\" true");
  ASSERT_TRUE(diffracting->diffraction());
  EXPECT_EQ(diffracting->psf_table()->geometric_nodes(), diffracting->psf_table()->nodes());
  CameraSample cs;
  cs.p_film = Vec2(40.2f, 21.9f);
  cs.p_lens = Vec2(0.7f, 0.2f);
  const auto a = geometric->generate_ray(cs), b = diffracting->generate_ray(cs);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->ray.d, b->ray.d);
  EXPECT_EQ(a->weight[0], b->weight[0]);
  // At 2 mm none is.
  EXPECT_EQ(eye("\"float pupildiameter\" 2 \"float wavelength\" 555 \"float fov\" 30 \"bool diffraction\" true")
                ->psf_table()
                ->geometric_nodes(),
            0);
}

// The PSF's random numbers are hashed from the sample's own dimensions, so a render is still a
// function of the seed alone (as tests/integrators/reproducibility_test.cpp requires of every
// camera): the cornell box through a diffracting dispersive eye, 1 and 2 threads.
Image render_cornell(int threads, uint64_t seed) {
  SceneDescription desc = parse_scene_file(std::string(EYETRACE_SOURCE_DIR) + "/scenes/cornell-box.pbrt");
  RenderOverrides o;
  o.camera = parse_directive_text(
      "Camera \"navarro\" \"float pupildiameter\" 2 \"float fov\" 40 \"bool diffraction\" true", "Camera", "test");
  o.resolution = IVec2(32, 24);
  o.spp = 4;
  o.seed = seed;
  RenderSetup s = build_render_setup(desc, o);
  RenderCounters counters;
  RenderOptions opts;
  opts.threads = threads;
  opts.progress = false;
  s.integrator->render(*s.camera, *s.sampler, *s.film, opts, counters);
  EXPECT_EQ(counters.nonfinite_samples.load(), 0u);
  return s.film->image();
}

TEST(CameraDiffraction, SameSeedSameImageForAnyThreadCount) {
  const Image one = render_cornell(1, 3), two = render_cornell(2, 3), other = render_cornell(2, 4);
  EXPECT_TRUE(one.pixels == two.pixels) << "images differ between 1 and 2 threads";
  EXPECT_FALSE(one.pixels == other.pixels) << "the seed has no effect";
}

void expect_error_naming_diffraction(const std::string& camera, const std::string& params) {
  SceneEntity e =
      parse_directive_text("Camera \"" + camera + "\" " + params + " \"bool diffraction\" true", "Camera", "test");
  CameraContext ctx{e.params, Transform(), kResolution, ""};
  try {
    if (camera == "realistic")
      create_realistic_camera(ctx);
    else
      create_perspective_camera(ctx);
    ADD_FAILURE() << camera << ": no error";
  } catch (const SceneError& err) {
    const std::string what = err.what();
    EXPECT_NE(what.find("diffraction"), std::string::npos) << what;
    EXPECT_NE(what.find("eye cameras"), std::string::npos) << camera << ": " << what;
  }
}

TEST(CameraDiffraction, CamerasWithoutAWavePsfRejectTheParameter) {
  expect_error_naming_diffraction("perspective", "");
  expect_error_naming_diffraction("realistic", "\"string lensfile\" \"any.dat\"");
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
