#include "lights/goniometric_light.h"

#include <numeric>

#include "core/sampling.h"
#include "lights/light_image.h"
#include "lights/light_params.h"
#include "lights/sphere_mapping.h"

namespace eyetrace {

std::vector<float> channel_average(const RGBImage& image) {
  std::vector<float> out(image.pixels.size());
  for (size_t i = 0; i < out.size(); ++i) out[i] = (image.pixels[i].r + image.pixels[i].g + image.pixels[i].b) / 3.f;
  return out;
}

static float mean_of(const std::vector<float>& v) {
  return v.empty() ? 0.f : float(std::accumulate(v.begin(), v.end(), 0.0) / double(v.size()));
}

GoniometricLight::GoniometricLight(const Transform& world_from_light, const Spectrum& I, std::vector<float> diagram,
                                   int width)
    : light_from_world_(world_from_light.inverse()),
      p_(world_from_light.point(Vec3(0.f))),
      I_(I),
      diagram_(std::move(diagram)),
      width_(width),
      mean_(mean_of(diagram_)) {}

float GoniometricLight::diagram_value(const Vec3& w) const {
  Vec3 wl = light_from_world_.vector(w);
  const float len = glm::length(wl);
  if (!(len > 0.f) || !std::isfinite(len)) return 0.f;
  // pbrt-v4's swapYZ: the diagram's sphere has the light's y and z exchanged.
  const Vec2 uv = equal_area_sphere_to_square(Vec3(wl.x, wl.z, wl.y) / len);
  const int x = std::clamp(int(uv.x * float(width_)), 0, width_ - 1);
  const int y = std::clamp(int(uv.y * float(width_)), 0, width_ - 1);
  return diagram_[size_t(y) * size_t(width_) + size_t(x)];
}

std::optional<LightLiSample> GoniometricLight::sample_li(const LightSampleContext& ctx, Vec2,
                                                         const SampledWavelengths& lambda) const {
  const Vec3 d = p_ - ctx.p;
  const float dist2 = glm::dot(d, d);
  // A shading point on the light itself receives no defined irradiance.
  if (!(dist2 > 0.f) || !std::isfinite(dist2)) return std::nullopt;
  const Vec3 wi = d / std::sqrt(dist2);
  const SampledSpectrum I = intensity(-wi, lambda);
  if (is_black(I)) return std::nullopt;
  LightLiSample s;
  s.L = I / dist2;
  s.wi = wi;
  s.pdf = 1.f;
  s.p_light = p_;
  return s;
}

std::optional<LightLeSample> GoniometricLight::sample_le(Vec2 u1, Vec2, const SampledWavelengths& lambda,
                                                         float time) const {
  const Vec3 w = sample_uniform_sphere(u1);
  const SampledSpectrum I = intensity(w, lambda);
  if (is_black(I)) return std::nullopt;
  LightLeSample s;
  s.L = I;
  s.ray = Ray{p_, w, kInfinity, time};
  s.pdf_pos = 1.f;
  s.pdf_dir = uniform_sphere_pdf();
  return s;
}

void GoniometricLight::pdf_le(const Vec3&, const Vec3&, const Vec3&, float* pdf_pos, float* pdf_dir) const {
  *pdf_pos = 0.f;  // a point: no other position could have been sampled (pbrt-v4)
  *pdf_dir = uniform_sphere_pdf();
}

// pbrt-v4's Phi: 4 pi I times the diagram's mean (equal-area pixels).
float GoniometricLight::power() const { return channel_mean(I_) * 4.f * kPi * mean_; }

const PluginSpec& goniometric_light_spec() {
  static const PluginSpec spec{
      "LightSource",
      "a point light whose intensity follows an equal-area image over the sphere",
      "`filename` is required (pbrt-v4 5f7a606 warns that it is missing, then aborts on a failed check); an image with "
      "a "
      "non-finite value is an "
      "error, as in pbrt-v4. An image with both R, G, B and Y channels is read by its R, G, B (pbrt-v4 refuses it).",
      {emission_param_spec("I", "intensity, times the image"), scale_param_spec(),
       photometric_param_spec("power", "total power: 4 pi times the image's average (I's RGB colour not counted)"),
       param::string("filename").describe("square image in the equal-area octahedral mapping; RGB is averaged")}};
  return spec;
}

std::unique_ptr<Light> create_goniometric_light(const LightContext& ctx) {
  const PluginParams params(ctx.params, goniometric_light_spec(), "goniometric");
  const Spectrum I = emission_param(params, "I");
  float scale = scale_param(params);
  const std::optional<float> phi = photometric_param(params, "power");
  const RGBImage image = read_light_image(params, ctx.search_dir, "goniometric");
  if (image.width != image.height)
    params.fail("filename", fmt::format("image \"{}\" is {}x{}: a goniometric diagram is a square equal-area map",
                                        params.get_string("filename"), image.width, image.height));
  std::vector<float> diagram = channel_average(image);
  // pbrt-v4: k_e = 4 pi times the image's average; I's spectrum is already of luminance 1.
  scale *= photometric_factor(phi, 4.f * kPi * mean_of(diagram));
  return std::make_unique<GoniometricLight>(ctx.world_from_light, I.scaled(scale), std::move(diagram), image.width);
}

}  // namespace eyetrace
