// The "thindielectric" material (pbrt-v4's ThinDielectricBxDF): the slab's reflectance is the
// sum of the rays reflected after 0, 2, 4, ... internal bounces, summed here term by term
// (independent of the closed form in the code); at normal incidence it is 2R/(1+R) with R the
// single face's ((n-1)/(n+1))^2, 7.69 % for n = 1.5; the transmitted ray goes straight on; and
// through the renderer a pane in front of an emitter passes exactly 1 - R' of its radiance.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/render_text.h"
#include "../support/unity_id.h"
#include "materials/fresnel.h"
#include "materials/thin_dielectric_bxdf.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// R' by summing the series: out at the first face (R), or in (T), then 2k internal reflections
// (R^2k), then out at the first face again (T) after one more reflection (R).
double slab_reflectance(double r) {
  double sum = r, term = (1 - r) * r * (1 - r);
  for (int k = 0; k < 2000 && term > 1e-18; ++k, term *= r * r) sum += term;
  return sum;
}

TEST(ThinDielectric, ReflectanceIsTheSumOfTheInternalBounces) {
  for (float cos_o : {1.f, 0.8f, 0.5f, 0.2f, 0.05f}) {
    const ThinDielectricBxDF b(1.5f);
    const Vec3 wo(std::sqrt(1.f - cos_o * cos_o), 0.f, cos_o);
    const double expected = slab_reflectance(fresnel_dielectric(cos_o, 1.5f));
    // uc just below R' reflects, just above transmits: the split is at R'.
    auto reflected = b.sample_f(wo, float(expected) * 0.999f, Vec2(0.5f));
    auto transmitted = b.sample_f(wo, float(expected) * 1.001f, Vec2(0.5f));
    ASSERT_TRUE(reflected && transmitted);
    EXPECT_TRUE(reflected->flags & kReflection);
    EXPECT_TRUE(transmitted->flags & kTransmission);
    EXPECT_NEAR(reflected->pdf, expected, 1e-6);
    EXPECT_NEAR(reflected->f[0] * cos_o / reflected->pdf, 1.0, 1e-5);  // weight 1: the lobe's share
    EXPECT_NEAR(transmitted->pdf, 1.0 - expected, 1e-6);
    EXPECT_EQ(transmitted->wi, -wo);  // straight through
    EXPECT_EQ(reflected->wi, Vec3(-wo.x, -wo.y, wo.z));
  }
  // Normal incidence, n = 1.5: R = 0.04, R' = 2R / (1 + R) = 0.076923.
  EXPECT_NEAR(slab_reflectance(0.04), 0.08 / 1.04, 1e-12);
}

double mean_through_pane(bool pane) {
  const std::string text = fmt::format(R"(
    LookAt 0 0 5  0 0 0  0 1 0
    Camera "perspective" "float fov" 4
    Film "rgb" "integer xresolution" 32 "integer yresolution" 32
    Sampler "independent" "integer pixelsamples" 256
    Integrator "path" "integer maxdepth" 5
    WorldBegin
    AttributeBegin
      Material "diffuse" "rgb reflectance" [0 0 0]  # the emitter reflects nothing the pane sends back
      AreaLightSource "diffuse" "rgb L" [1 1 1]
      Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-3 -3 -1  3 -3 -1  3 3 -1  -3 3 -1]
    AttributeEnd
    {}
  )",
                                       pane ? R"(Material "thindielectric" "float eta" 1.5
    Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-2 -2 1  2 -2 1  2 2 1  -2 2 1])"
                                            : "");
  return test::image_mean(test::render_text(text, "pane.pbrt"));
}

TEST(ThinDielectric, APanePassesOneMinusItsReflectance) {
  const double bare = mean_through_pane(false);
  ASSERT_GT(bare, 0.5);
  // Rays within 3 degrees of the normal: R' differs from its normal value by < 1e-5 there. Each
  // sample either passes (weight 1, probability T') or is reflected into the dark: a binomial
  // mean of 32 x 32 x 256 samples, allowed 4 standard deviations.
  const double t = 1.0 - 0.08 / 1.04, sigma = std::sqrt(t * (1 - t) / (32 * 32 * 256));
  EXPECT_NEAR(mean_through_pane(true) / bare, t, 4 * sigma);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
