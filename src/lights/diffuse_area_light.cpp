#include "lights/diffuse_area_light.h"

#include <filesystem>

#include "core/sampling.h"
#include "lights/light_params.h"
#include "scene/scene_files.h"

namespace eyetrace {

namespace {

RGB mean_pixel(const RGBImage& image) {
  RGB sum(0.f);
  for (const RGB& p : image.pixels) sum += p;
  return sum / float(image.pixels.size());
}

}  // namespace

DiffuseAreaLight::DiffuseAreaLight(const Shape& shape, const Spectrum& L, float scale, bool two_sided,
                                   std::optional<RGBImage> image)
    : shape_(shape),
      L_(L),
      scale_(scale),
      two_sided_(two_sided),
      image_(std::move(image)),
      area_(shape.area()),
      mean_(image_ ? channel_mean(mean_pixel(*image_)) : channel_mean(L)),
      invisible_(shape.invisible()) {}

SampledSpectrum DiffuseAreaLight::emitted(const Vec3& n, Vec2 uv, const Vec3& w,
                                          const SampledWavelengths& lambda) const {
  if (!two_sided_ && glm::dot(n, w) <= 0.f) return SampledSpectrum(0.f);
  if (image_) return scale_ * rgb_emission(image_->bilerp(Vec2(uv.x, 1.f - uv.y)), lambda);
  return scale_ * L_.sample(lambda);
}

SampledSpectrum DiffuseAreaLight::L(const SurfaceInteraction& hit, const Vec3& w,
                                    const SampledWavelengths& lambda) const {
  if (shape_.alpha_masked(TextureEvalContext(hit))) return SampledSpectrum(0.f);
  return emitted(hit.n, hit.uv, w, lambda);
}

std::optional<LightLiSample> DiffuseAreaLight::sample_li(const LightSampleContext& ctx, Vec2 u,
                                                         const SampledWavelengths& lambda) const {
  ShapeSample ss = shape_.sample_area(u);
  if (!invisible_) {
    TextureEvalContext tc;
    tc.p = ss.p;
    tc.n = ss.n;
    tc.uv = ss.uv;
    if (shape_.alpha_masked(tc)) return std::nullopt;
  }
  Vec3 d = ss.p - ctx.p;
  float dist2 = glm::dot(d, d);
  if (!(dist2 > 0.f) || !(ss.pdf_area > 0.f)) return std::nullopt;
  Vec3 wi = d / std::sqrt(dist2);
  // Seen edge-on the light covers no solid angle: the density would be infinite.
  float cos_light = std::abs(glm::dot(ss.n, wi));
  if (!(cos_light > 0.f)) return std::nullopt;
  float pdf = ss.pdf_area * dist2 / cos_light;
  SampledSpectrum Le = emitted(ss.n, ss.uv, -wi, lambda);
  if (!std::isfinite(pdf) || is_black(Le)) return std::nullopt;
  LightLiSample s;
  s.L = Le;
  s.wi = wi;
  s.pdf = pdf;
  s.p_light = ss.p;
  s.p_light_error = ss.p_error;
  s.n_light = ss.n;
  return s;
}

float DiffuseAreaLight::pdf_li(const LightSampleContext& ctx, const Vec3&, const SurfaceInteraction* hit) const {
  if (!hit || !(area_ > 0.f)) return 0.f;
  // The geometry comes from the two points alone: wi need not be normalised by the caller.
  Vec3 d = hit->p - ctx.p;
  float dist2 = glm::dot(d, d);
  if (!(dist2 > 0.f)) return 0.f;
  float cos_light = std::abs(glm::dot(hit->n, d)) / std::sqrt(dist2);
  if (!(cos_light > 0.f)) return 0.f;
  float pdf = dist2 / (area_ * cos_light);
  return std::isfinite(pdf) ? pdf : 0.f;
}

std::optional<LightLeSample> DiffuseAreaLight::sample_le(Vec2 u1, Vec2 u2, const SampledWavelengths& lambda,
                                                         float time) const {
  const ShapeSample ss = shape_.sample_area(u1);
  if (!(ss.pdf_area > 0.f)) return std::nullopt;
  if (!invisible_) {
    TextureEvalContext tc;
    tc.p = ss.p;
    tc.n = ss.n;
    tc.uv = ss.uv;
    if (shape_.alpha_masked(tc)) return std::nullopt;
  }
  // Two-sided: the first half of u2.x picks the front, the second the back, each rescaled to
  // [0, 1) so the hemisphere sample keeps its stratification.
  bool back = false;
  if (two_sided_) {
    back = u2.x >= 0.5f;
    u2.x = std::min(back ? 2.f * (u2.x - 0.5f) : 2.f * u2.x, kOneMinusEpsilon);
  }
  Vec3 w_local = sample_cosine_hemisphere(u2);
  const float pdf_dir = cosine_hemisphere_pdf(w_local.z) * (two_sided_ ? 0.5f : 1.f);
  if (!(pdf_dir > 0.f)) return std::nullopt;
  if (back) w_local.z = -w_local.z;
  const Vec3 w = Frame(ss.n).to_world(w_local);
  LightLeSample s;
  s.L = emitted(ss.n, ss.uv, w, lambda);
  if (is_black(s.L)) return std::nullopt;
  s.ray = spawn_ray(ss.p, ss.p_error, ss.n, w, time);
  s.n = ss.n;
  s.pdf_pos = ss.pdf_area;
  s.pdf_dir = pdf_dir;
  return s;
}

float DiffuseAreaLight::power() const { return (two_sided_ ? 2.f : 1.f) * kPi * std::max(area_, 0.f) * scale_ * mean_; }

const PluginSpec& diffuse_area_light_spec() {
  static const PluginSpec spec{
      "AreaLightSource",
      "emission from a shape's surface, equal in every direction",
      "—",
      {emission_param_spec("L", "emitted radiance"),
       param::string("filename").describe("an RGB image indexed by the shape's (u, v), instead of `L`"),
       scale_param_spec(), param::boolean("twosided", false).describe("emit from both sides"),
       photometric_param_spec("power", "total emitted power")}};
  return spec;
}

std::unique_ptr<Light> create_diffuse_area_light(const AreaLightContext& ctx) {
  const PluginParams params(ctx.params, diffuse_area_light_spec(), "diffuse");
  std::optional<Spectrum> L = emission_param_or_null(params, "L");
  float scale = scale_param(params);
  bool two_sided = params.get_bool("twosided");
  std::optional<float> phi = photometric_param(params, "power");
  const std::string filename = params.has("filename") ? params.get_string("filename") : "";

  std::optional<RGBImage> image;
  const Spectrum emission = L ? *L : emission_param(params, "L");  // absent: the declared default
  float luminance_emitted = emission.luminance();
  if (!filename.empty()) {
    if (L) params.fail("filename", "an area light takes \"L\" or \"filename\", not both");
    std::string path = resolve_scene_file(ctx.search_dir, filename);
    if (!std::filesystem::exists(path))
      params.fail_missing_file("filename", fmt::format("emission image \"{}\" not found", path));
    std::string error;
    image = read_rgb_image(path, &error);
    if (!image) params.fail("filename", fmt::format("cannot read emission image \"{}\": {}", path, error));
    luminance_emitted = luminance(mean_pixel(*image));
  }
  float k_e = (two_sided ? 2.f : 1.f) * kPi * ctx.shape.area() * luminance_emitted;
  scale *= photometric_factor(phi, k_e);
  return std::make_unique<DiffuseAreaLight>(ctx.shape, emission, scale, two_sided, std::move(image));
}

}  // namespace eyetrace
