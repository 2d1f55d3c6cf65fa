// Stress test of eye cameras with prescriptions (the rotationally symmetric ones the camera
// renders: axial or refractive ametropia, spectacle lenses of either sign at 5-25 mm, contact
// lenses, random pupils, accommodations within a random age's amplitude, fields up to 170 degrees):
// over 2 million random camera samples every returned ray is finite with a unit direction and a
// weight in [0, max_weight()], and really passes the eye and its lenses: traced back from the
// scene it lands on its retina point (to 1e-4 mm; rays within float rounding of an aperture edge
// may flip, bounded at 1 in 1000).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <fmt/format.h>

#include "../support/unity_id.h"
#include "cameras/lens_system_camera.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

TEST(EyeParamsPrescriptionSlow, TwoMillionSamplesThroughCorrectedEyesAreFiniteAndReal) {
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::uniform_real_distribution<float> uf(0.f, 1.f);
  long samples = 0, rays = 0, reversed = 0, reverse_failures = 0;
  int cameras = 0;
  while (samples < 2'000'000) {
    const double error = -10.0 + 20.0 * u(rng);
    std::string text = fmt::format(
        "Camera \"navarro\" \"float refractiveerror\" {} \"string ametropia\" \"{}\" \"float pupildiameter\" {} "
        "\"float fov\" {} \"float age\" {} \"float accommodation\" {}",
        error, cameras % 2 ? "refractive" : "axial", 1.0 + 7.0 * u(rng), 10.0 + 160.0 * u(rng), 40.0 + 20 * u(rng),
        0.5 * u(rng));
    if (cameras % 3 != 2)
      text += fmt::format(" \"float spectaclesphere\" {} \"float vertexdistance\" {}", -10.0 + 20.0 * u(rng),
                          5.0 + 20.0 * u(rng));
    if (cameras % 3 != 0) text += fmt::format(" \"float contactlens\" {}", -10.0 + 20.0 * u(rng));
    if (cameras % 4 == 1) text += " \"float wavelength\" 555";
    ++cameras;
    SceneEntity e = parse_directive_text(text, "Camera", "slow");
    const IVec2 res(16 + int(300 * u(rng)), 16 + int(300 * u(rng)));
    CameraContext ctx{e.params, Transform(), res, ""};
    std::unique_ptr<Camera> made;
    ASSERT_NO_THROW(made = create_named_eye_camera("navarro")(ctx)) << text;
    const auto& cam = dynamic_cast<const LensSystemCamera&>(*made);
    const double bound = cam.max_weight();
    ASSERT_TRUE(std::isfinite(bound) && bound > 0.0) << text;
    const double mm_per_unit = 1.0 / cam.settings().scene_units_per_mm;
    for (int i = 0; i < 100'000; ++i) {
      CameraSample cs;
      cs.p_film = Vec2(res.x * uf(rng), res.y * uf(rng));
      cs.p_lens = Vec2(std::min(uf(rng), kOneMinusEpsilon), std::min(uf(rng), kOneMinusEpsilon));
      cs.wavelength_u = uf(rng);
      ++samples;
      SampledWavelengths lambda = SampledWavelengths::sample_visible(cs.wavelength_u);
      const auto r = cam.generate_ray(cs, lambda);
      if (!r) continue;
      ++rays;
      const Ray& ray = r->ray;
      const bool finite = std::isfinite(ray.o.x) && std::isfinite(ray.o.y) && std::isfinite(ray.o.z) &&
                          std::isfinite(ray.d.x) && std::isfinite(ray.d.y) && std::isfinite(ray.d.z);
      ASSERT_TRUE(finite && std::abs(glm::length(ray.d) - 1.f) < 1e-5f) << text;
      ASSERT_TRUE(std::isfinite(r->weight[0]) && r->weight[0] >= 0.f && r->weight[0] <= bound * (1.0 + 1e-6))
          << text << ": weight " << r->weight[0] << " bound " << bound;
      if (i % 16 != 0) continue;
      // The scene ray turned round (camera frame -> eye frame: x and z mirrored, as the camera
      // builds it) and traced forward lands on the pixel's retina point.
      const auto rp = cam.retina_point(cs.p_film);
      ASSERT_TRUE(rp) << text;
      const glm::dvec3 o(-double(ray.o.x) * mm_per_unit, double(ray.o.y) * mm_per_unit, -double(ray.o.z) * mm_per_unit);
      const glm::dvec3 d(-double(ray.d.x), double(ray.d.y), -double(ray.d.z));
      const optics::Ray back_ray{o + 1e-3 * d, -d};
      const optics::TraceResult back =
          cam.dispersive() ? cam.system().trace_range(back_ray, 0, cam.system().image_index(), double(lambda[0]))
                           : cam.system().trace_forward(back_ray);
      ++reversed;
      if (!back.ok() || glm::length(back.ray.origin - rp->position) > 1e-4) ++reverse_failures;
    }
  }
  std::printf("%d cameras, %ld samples, %ld rays (%.1f%%), %ld reversed, %ld not reversible\n", cameras, samples, rays,
              100.0 * rays / samples, reversed, reverse_failures);
  EXPECT_LT(reverse_failures, reversed / 1000 + 1);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
