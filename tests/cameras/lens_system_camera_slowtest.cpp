// Stress test of the eye cameras: over 10 million random camera samples through randomly
// configured preset eyes (accommodation across each model's range, pupils 0.5-9 mm, fields of
// view up to 179.9 degrees, all three mappings, odd image shapes), every returned ray is finite
// with a unit direction and a weight in [0, max_weight()], and every returned ray really
// passes the eye: traced back into the eye from the scene it lands on its retina point. The
// same for eyes with a random corneal cylinder and a random decentred iris.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../support/unity_id.h"
#include "cameras/lens_system_camera.h"
#include "optics/corneal_astigmatism.h"
#include "optics/eye_models.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

struct Counts {
  long samples = 0, rays = 0, reversed = 0, reverse_failures = 0;
};

void stress(const LensSystemCamera& cam, IVec2 res, int n, std::mt19937& rng, Counts& counts,
            const std::string& label) {
  std::uniform_real_distribution<float> u(0.f, 1.f);
  const double bound = cam.max_weight();
  ASSERT_TRUE(std::isfinite(bound) && bound > 0.0) << label;
  const double mm_per_unit = 1.0 / cam.settings().scene_units_per_mm;
  int failures = 0;
  for (int i = 0; i < n && failures < 5; ++i) {
    CameraSample cs;
    cs.p_film = Vec2(res.x * u(rng), res.y * u(rng));
    cs.p_lens = Vec2(std::min(u(rng), kOneMinusEpsilon), std::min(u(rng), kOneMinusEpsilon));
    ++counts.samples;
    cs.wavelength_u = u(rng);
    SampledWavelengths lambda = SampledWavelengths::sample_visible(cs.wavelength_u);
    const auto r = cam.generate_ray(cs, lambda);
    if (!r) continue;
    ++counts.rays;
    const Ray& ray = r->ray;
    const bool finite = std::isfinite(ray.o.x) && std::isfinite(ray.o.y) && std::isfinite(ray.o.z) &&
                        std::isfinite(ray.d.x) && std::isfinite(ray.d.y) && std::isfinite(ray.d.z);
    const bool unit = std::abs(glm::length(ray.d) - 1.f) < 1e-5f;
    const bool weight_ok = std::isfinite(r->weight[0]) && r->weight[0] >= 0.f && r->weight[0] <= bound * (1.0 + 1e-6);
    if (!finite || !unit || !weight_ok) {
      ++failures;
      ADD_FAILURE() << label << ": bad ray at film " << cs.p_film.x << "," << cs.p_film.y << " lens " << cs.p_lens.x
                    << "," << cs.p_lens.y << " weight " << r->weight[0] << " bound " << bound;
    }
    if (i % 16 != 0) continue;
    // Reversibility: the scene ray, turned round and traced forward into the eye, reaches the
    // retina at the pixel's retina point (double trace of the float ray: agreement to 1e-4 mm).
    const auto rp = cam.retina_point(cs.p_film);
    ASSERT_TRUE(rp) << label;
    const glm::dvec3 o(-double(ray.o.x) * mm_per_unit, double(ray.o.y) * mm_per_unit, -double(ray.o.z) * mm_per_unit);
    const glm::dvec3 d(-double(ray.d.x), double(ray.d.y), -double(ray.d.z));
    // A dispersive eye traced the hero wavelength: the way back is at that wavelength too.
    const optics::Ray reversed{o + 1e-3 * d, -d};
    const optics::TraceResult back =
        cam.dispersive() ? cam.system().trace_range(reversed, 0, cam.system().image_index(), double(lambda[0]))
                         : cam.system().trace_forward(reversed);
    ++counts.reversed;
    // Rays within float rounding of an aperture edge may flip: counted, bounded below.
    if (!back.ok() || glm::length(back.ray.origin - rp->position) > 1e-4) {
      ++counts.reverse_failures;
      if (counts.reverse_failures < 20)
        printf("%s\n  status %s surf %d dist %g arc %g film %g %g\n", label.c_str(), optics::to_string(back.status),
               back.surface, glm::length(back.ray.origin - rp->position), rp->arc_mm, cs.p_film.x, cs.p_film.y);
    }
  }
}

TEST(LensSystemCameraSlow, TenMillionRandomSamplesAreFiniteUnitBoundedAndReal) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::vector<std::string> models = {"navarro", "gullstrand", "legrand", "kooijman", "arizona", "escudero-sanz"};
  const char* mappings[] = {"angle", "flat", "retina"};
  Counts counts;
  int cameras = 0, skipped = 0;
  while (counts.samples < 10'200'000) {
    const std::string model = models[cameras % models.size()];
    const double max_a = optics::max_accommodation_D(model);
    const double accommodation = max_a * u(rng);
    const double pupil = 0.5 + 8.5 * u(rng);
    const double fov = cameras % 4 == 0 ? 179.9 : 1.0 + 178.9 * u(rng);
    const char* mapping = mappings[(cameras / 2) % 3];
    const IVec2 res(16 + int(500 * u(rng)), 16 + int(500 * u(rng)));
    const std::string text = fmt::format(
        "Camera \"eye\" \"string model\" \"{}\" \"float accommodation\" {} \"float pupildiameter\" {} \"float fov\" {} "
        "\"string mapping\" \"{}\" \"float sceneunit\" {}",
        model, accommodation, pupil, fov, mapping, cameras % 3 == 0 ? 0.001 : 1.0);
    ++cameras;
    SceneEntity e = parse_directive_text(text, "Camera", "slow");
    CameraContext ctx{e.params, Transform(), res, ""};
    std::unique_ptr<Camera> cam;
    try {
      cam = create_eye_camera(ctx);
    } catch (const SceneError& err) {
      // Only a fov beyond the chief ray's reach may refuse a flat/retina mapping.
      ASSERT_NE(std::string(mapping), "angle") << err.what();
      ASSERT_NE(std::string(err.what()).find("\"fov\""), std::string::npos) << err.what();
      ++skipped;
      continue;
    }
    stress(dynamic_cast<const LensSystemCamera&>(*cam), res, 200'000, rng, counts, text);
    if (HasFailure()) return;
  }
  std::printf(
      "%d cameras (%d refused a too-wide fov for flat/retina), %ld samples, %ld rays (%.1f%%), %ld reversed, "
      "%ld not reversible\n",
      cameras, skipped, counts.samples, counts.rays, 100.0 * counts.rays / counts.samples, counts.reversed,
      counts.reverse_failures);
  EXPECT_GE(counts.samples, 10'000'000);
  EXPECT_LT(counts.reverse_failures, counts.reversed / 1000 + 1);
}

// Eyes that are not rotationally symmetric (symmetric_stand_in.h): a random corneal cylinder at
// a random axis and a random decentred iris on each preset model, dispersive or not.
TEST(LensSystemCameraSlow, NonSymmetricEyesGiveFiniteBoundedRealRays) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::vector<std::string> models = {"navarro", "gullstrand", "legrand", "kooijman", "arizona", "escudero-sanz"};
  Counts counts;
  int cameras = 0;
  while (counts.samples < 3'000'000) {
    const std::string model = models[cameras % models.size()];
    const double pupil = 1.0 + 7.0 * u(rng), fov = 1.0 + 150.0 * u(rng);
    const std::string text = fmt::format("Camera \"{}\" \"float pupildiameter\" {} \"float fov\" {}{}", model, pupil,
                                         fov, cameras % 2 ? "" : " \"float wavelength\" 555");
    SceneEntity e = parse_directive_text(text, "Camera", "slow");
    const IVec2 res(16 + int(300 * u(rng)), 16 + int(300 * u(rng)));
    CameraContext ctx{e.params, Transform(), res, ""};
    std::unique_ptr<Camera> plain = create_named_eye_camera(model)(ctx);
    const auto& base = dynamic_cast<const LensSystemCamera&>(*plain);
    optics::Prescription p = base.prescription();
    const double cylinder = -6.0 * u(rng), axis = 180.0 * u(rng);
    const double dx = 1.0 * (2.0 * u(rng) - 1.0), dy = 1.0 * (2.0 * u(rng) - 1.0);
    optics::set_corneal_cylinder(p, cylinder, axis);
    optics::set_pupil_decentration(p, dx, dy);
    ++cameras;
    const LensSystemCamera cam(p, Transform(), res, base.settings());
    stress(cam, res, 100'000, rng, counts,
           fmt::format("{} cylinder {} x {} decentred {} {}", text, cylinder, axis, dx, dy));
    if (HasFailure()) return;
  }
  std::printf("%d non-symmetric cameras, %ld samples, %ld rays (%.1f%%), %ld reversed, %ld not reversible\n", cameras,
              counts.samples, counts.rays, 100.0 * counts.rays / counts.samples, counts.reversed,
              counts.reverse_failures);
  EXPECT_LT(counts.reverse_failures, counts.reversed / 1000 + 1);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
