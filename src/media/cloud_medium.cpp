#include "media/cloud_medium.h"

#include <algorithm>
#include <cmath>

#include "media/medium_params.h"
#include "textures/perlin_noise.h"

namespace eyetrace {

Vec3 perlin_noise_gradient(const Vec3& p) {
  constexpr float delta = 0.01f;
  const float n = perlin_noise(p);
  return (Vec3(perlin_noise(p + Vec3(delta, 0.f, 0.f)), perlin_noise(p + Vec3(0.f, delta, 0.f)),
               perlin_noise(p + Vec3(0.f, 0.f, delta))) -
          Vec3(n)) /
         delta;
}

CloudMedium::CloudMedium(MediumBox box, Spectrum sigma_a, Spectrum sigma_s, float g, Params shape)
    : box_(std::move(box)), sigma_a_(std::move(sigma_a)), sigma_s_(std::move(sigma_s)), g_(g), shape_(shape) {}

float CloudMedium::density_in_medium_space(const Vec3& p) const {
  Vec3 pp = shape_.frequency * p;
  if (shape_.wispiness > 0.f) {
    float v_omega = 0.05f * shape_.wispiness, v_lambda = 10.f;
    for (int i = 0; i < 2; ++i) {
      pp += v_omega * perlin_noise_gradient(v_lambda * pp);
      v_omega *= 0.5f;
      v_lambda *= 1.99f;
    }
  }
  float d = 0.f, omega = 0.5f, lambda = 1.f;
  for (int i = 0; i < 5; ++i) {
    d += omega * perlin_noise(lambda * pp);
    omega *= 0.5f;
    lambda *= 1.99f;
  }
  d = std::clamp((1.f - p.y) * 4.5f * shape_.density * d, 0.f, 1.f);
  d += 2.f * std::max(0.f, 0.5f - p.y);
  return std::clamp(d, 0.f, 1.f);
}

MediumProperties CloudMedium::properties(const Vec3& p, const SampledWavelengths& lambda) const {
  // As pbrt-v4, the density is not cut at the box: only majorants() confines the medium.
  const float d = density_in_medium_space(box_.to_medium(p));
  return MediumProperties{sigma_a_.sample(lambda) * d, sigma_s_.sample(lambda) * d, SampledSpectrum(0.f), g_};
}

MajorantIterator CloudMedium::majorants(const Ray& ray, float t_max, const SampledWavelengths& lambda) const {
  const auto c = box_.clip(ray, t_max);
  if (!c) return MajorantIterator();
  return MajorantIterator(c->t0, c->t1, sigma_a_.sample(lambda) + sigma_s_.sample(lambda));
}

const PluginSpec& cloud_medium_spec() {
  static const PluginSpec spec{
      "MakeNamedMedium",
      "pbrt-v4's procedural cloud: Perlin-noise density in a box, thinning with height",
      "—",
      {param::real("density", 1).at_least(0).describe("scales the noise sum before clamping to [0, 1]"),
       param::real("wispiness", 1).at_least(0).describe("how far the noise's gradient displaces lookups"),
       param::real("frequency", 5).describe("noise frequency, per unit length of the medium's space"),
       param::point3("p0", Vec3(0.f)).describe("the box's lower corner, in the medium's space"),
       param::point3("p1", Vec3(1.f)).describe("the box's upper corner, in the medium's space"),
       param::spectrum("sigma_a", 1).describe("absorption coefficient at density 1, per unit length"),
       param::spectrum("sigma_s", 1).describe("scattering coefficient at density 1, per unit length"),
       param::real("g", 0).describe("Henyey-Greenstein asymmetry, in (-1, 1)")}};
  return spec;
}

std::unique_ptr<Medium> create_cloud_medium(const MediumContext& ctx) {
  const PluginParams p(ctx.params, cloud_medium_spec(), "cloud");
  CloudMedium::Params shape{p.get_float("density"), p.get_float("wispiness"), p.get_float("frequency")};
  if (!std::isfinite(shape.frequency)) p.fail("frequency", "must be finite");
  MediumBox box{medium_bounds_param(p), ctx.world_from_medium.inverse()};
  return std::make_unique<CloudMedium>(std::move(box), coefficient_param(p, "sigma_a"), coefficient_param(p, "sigma_s"),
                                       asymmetry_param(p), shape);
}

}  // namespace eyetrace
