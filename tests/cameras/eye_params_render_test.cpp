// Renders through corrected eyes (issue 16 part 3): a far vertical edge (radiance 1 for camera rays
// heading right of the line of sight, 0 left of it: a chart at infinity, since it depends on the
// ray's direction alone) imaged by the eye camera exactly as the renderer's camera rays sample it.
// Sharpness is the edge width W = sum over the columns of E (1 - E), E the edge-spread function
// (the pixels' mean radiance across the edge, averaged over the middle rows): 0 for a step,
// growing with the blur (w / 6 pixels for a linear ramp w pixels wide). Noise: W is measured on
// kReplicas independent sample sets; its standard error is their spread / sqrt(kReplicas).
// Claims: the -3 D myope corrected by a -3.112 D spectacle at 12 mm, or by a -3 D contact lens, is
// as sharp as the emmetropic eye within 4 standard errors plus 0.1 pixel (0.375 arcmin). The 0.1
// pixel is for real differences of the corrected eyes' residual aberrations from the emmetrope's
// (a longer eye, the spectacle's own spherical aberration and minification, the lens layer's
// change of the corneal asphericity): measured (Release, these seeds) emmetrope 0.400 +- 0.005,
// spectacles 0.437 +- 0.004, contact lens 0.348 +- 0.006 pixels, i.e. +0.04 and -0.05. A residual
// defocus of 0.05 D would add a 0.2 mrad (0.7 arcmin, 0.18 pixel) blur disc. The uncorrected
// myope (2.17 +- 0.006) is blurrier by more than 20 standard errors and 3 times wider.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../support/unity_id.h"
#include "cameras/lens_system_camera.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

constexpr int kSize = 48;  // pixels; the 3 degree field gives 3.75 arcmin a pixel
constexpr int kRows = 16;  // the middle rows averaged
constexpr int kSpp = 48;   // samples per pixel per replica
constexpr int kReplicas = 8;

std::unique_ptr<Camera> eye(const std::string& params) {
  SceneEntity e = parse_directive_text(
      "Camera \"navarro\" \"float wavelength\" 555 \"float pupildiameter\" 4 \"float fov\" 3 " + params, "Camera",
      "test");
  CameraContext ctx{e.params, Transform(), IVec2(kSize, kSize), ""};
  return create_named_eye_camera("navarro")(ctx);
}

// Edge width of one replica (pixels).
double edge_width(const Camera& cam, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  double width = 0.0;
  for (int x = 0; x < kSize; ++x) {
    double sum = 0.0, weights = 0.0;
    for (int y = (kSize - kRows) / 2; y < (kSize + kRows) / 2; ++y)
      for (int s = 0; s < kSpp; ++s) {
        CameraSample cs;
        cs.p_film = Vec2(float(x) + u(rng), float(y) + u(rng));
        cs.p_lens = Vec2(u(rng), u(rng));
        SampledWavelengths lambda = SampledWavelengths::sample_visible(u(rng));
        const std::optional<CameraRay> r = cam.generate_ray(cs, lambda);
        if (!r) continue;
        const double w = r->weight[0];
        weights += w;
        sum += w * (r->ray.d.x > 0.0f ? 1.0 : 0.0);
      }
    const double e = weights > 0.0 ? sum / weights : 0.0;
    width += e * (1.0 - e);
  }
  return width;
}

struct Width {
  double mean = 0.0, stderr_ = 0.0;
};
Width measure(const std::string& params) {
  const std::unique_ptr<Camera> cam = eye(params);
  double s = 0.0, s2 = 0.0;
  for (int k = 0; k < kReplicas; ++k) {
    const double w = edge_width(*cam, 1000u + uint32_t(k));
    s += w, s2 += w * w;
  }
  const double mean = s / kReplicas;
  return {mean, std::sqrt(std::max(0.0, s2 / kReplicas - mean * mean) / (kReplicas - 1))};
}

TEST(EyeParamsRender, CorrectedMyopeIsAsSharpAsTheEmmetrope) {
  const Width emmetrope = measure("");
  const Width myope = measure("\"float refractiveerror\" -3");
  const Width spectacles = measure("\"float refractiveerror\" -3 \"float spectaclesphere\" -3.112033");
  const Width contact = measure("\"float refractiveerror\" -3 \"float contactlens\" -3");
  std::printf(
      "edge width (pixels, +- standard error): emmetrope %.3f +- %.3f, -3 D myope %.3f +- %.3f, "
      "spectacles %.3f +- %.3f, contact lens %.3f +- %.3f\n",
      emmetrope.mean, emmetrope.stderr_, myope.mean, myope.stderr_, spectacles.mean, spectacles.stderr_, contact.mean,
      contact.stderr_);
  for (const Width& corrected : {spectacles, contact}) {
    const double noise = std::hypot(corrected.stderr_, emmetrope.stderr_);
    EXPECT_LT(std::abs(corrected.mean - emmetrope.mean), 4.0 * noise + 0.1);
  }
  const double noise = std::hypot(myope.stderr_, emmetrope.stderr_);
  EXPECT_GT(myope.mean - emmetrope.mean, 20.0 * noise);
  EXPECT_GT(myope.mean, 3.0 * emmetrope.mean);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
