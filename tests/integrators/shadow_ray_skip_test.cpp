// Light sampling traces a shadow ray only where the light sample can contribute, and the ray
// after the last bounce is traced only if a light can be hit. With the direct integrator and a
// camera that sees nothing but a diffuse plane, every camera ray makes exactly one scattering
// point, so shadow_rays + shadow_rays_skipped equals the camera rays; which of the two each
// point lands in, and how many rays are traced, follows from the lights.
#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

struct Counts {
  uint64_t camera_rays, rays_traced, shadow_rays, shadow_rays_skipped;
};

Counts render(const std::string& lights) {
  std::string text =
      "LookAt 0 0 1  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
      "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\n"
      "Sampler \"independent\" \"integer pixelsamples\" 4\nIntegrator \"direct\"\nWorldBegin\n" +
      lights +
      "Material \"diffuse\"\nShape \"trianglemesh\" \"point3 P\" [-5 -5 0  5 -5 0  5 5 0  -5 5 0]"
      " \"integer indices\" [0 1 2 0 2 3]\n";
  RenderSetup s = build_render_setup(parse_scene_string(text, "skip.pbrt", "."), {});
  RenderCounters c;
  RenderOptions o;
  o.threads = 1;
  s.integrator->render(*s.camera, *s.sampler, *s.film, o, c);
  return {c.camera_rays, c.rays_traced, c.shadow_rays, c.shadow_rays_skipped};
}

constexpr uint64_t kCameraRays = 16 * 16 * 4;

TEST(ShadowRaySkip, LightInFrontNeedsAShadowRayAtEveryPoint) {
  Counts c = render("LightSource \"distant\" \"point3 from\" [0 0 1] \"point3 to\" [0 0 0]\n");
  EXPECT_EQ(c.camera_rays, kCameraRays);
  EXPECT_EQ(c.shadow_rays, kCameraRays);
  EXPECT_EQ(c.shadow_rays_skipped, 0u);
  // A distant light cannot be hit, so after the one bounce no BSDF-sampled ray is traced to
  // look for emission: each camera ray and its shadow ray, nothing else.
  EXPECT_EQ(c.rays_traced, 2 * kCameraRays);
}

TEST(ShadowRaySkip, LightBehindThePlaneNeedsNone) {
  // The light shines on the back: the diffuse BRDF is zero for it (f cos = 0).
  Counts c = render("LightSource \"distant\" \"point3 from\" [0 0 -1] \"point3 to\" [0 0 0]\n");
  EXPECT_EQ(c.shadow_rays, 0u);
  EXPECT_EQ(c.shadow_rays_skipped, kCameraRays);
  EXPECT_EQ(c.rays_traced, kCameraRays);
}

TEST(ShadowRaySkip, NoLightNeedsNone) {
  Counts c = render("");
  EXPECT_EQ(c.shadow_rays, 0u);
  EXPECT_EQ(c.shadow_rays_skipped, kCameraRays);
  EXPECT_EQ(c.rays_traced, kCameraRays);
}

TEST(ShadowRaySkip, AnInfiniteLightIsLookedForAfterTheLastBounce) {
  // An environment light can be hit: the BSDF-sampled ray after the bounce is traced (MIS).
  Counts c = render("LightSource \"infinite\" \"rgb L\" [1 1 1]\n");
  EXPECT_EQ(c.rays_traced, 2 * kCameraRays + c.shadow_rays);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
