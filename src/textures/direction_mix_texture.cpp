#include "textures/direction_mix_texture.h"

#include <cmath>

#include "scene/texture_store.h"
#include "textures/texture_value.h"

namespace eyetrace {

namespace {

template <typename Base>
class DirectionMixTexture final : public TextureOf<Base> {
  using Value = typename TextureOf<Base>::Value;

 public:
  DirectionMixTexture(const Base* tex1, const Base* tex2, Vec3 dir) : tex1_(tex1), tex2_(tex2), dir_(dir) {}
  Value value(const TextureEvalContext& ctx, const SampledWavelengths& lambda) const override {
    const float a = std::min(1.f, std::abs(glm::dot(ctx.n, dir_)));
    // The texture whose weight is zero is not evaluated (it may be expensive), as in pbrt-v4.
    const Value t1 = a != 0.f ? TextureOf<Base>::of(*tex1_, ctx, lambda) : Value(0.f);
    const Value t2 = a != 1.f ? TextureOf<Base>::of(*tex2_, ctx, lambda) : Value(0.f);
    return a * t1 + (1.f - a) * t2;
  }

 private:
  const Base* tex1_;
  const Base* tex2_;
  Vec3 dir_;  // unit, world space
};

// "dir" into world space and made unit; a zero or non-finite direction is an error.
Vec3 read_dir(const TextureContext& ctx, const PluginParams& p) {
  const Vec3 d = ctx.world_from_texture.vector(p.get_vector3("dir"));
  const float len = glm::length(d);
  if (!(len > 0.f) || !std::isfinite(len)) p.fail("dir", "the direction must be nonzero and finite");
  return d / len;
}

}  // namespace

const PluginSpec& directionmix_texture_spec() {
  static const PluginSpec spec{
      "Texture",
      "|n . dir| tex1 + (1 − |n . dir|) tex2 (n the geometric normal)",
      "—",
      {param::any_texture("tex1", 0).describe("of the texture's kind; where the surface faces dir"),
       param::any_texture("tex2", 1).describe("of the texture's kind; where it is edge-on"),
       param::vector3("dir", Vec3(0, 1, 0)).describe("in the texture's coordinate system")}};
  return spec;
}

std::unique_ptr<FloatTexture> create_directionmix_float_texture(const TextureContext& ctx) {
  const PluginParams p(ctx.params, directionmix_texture_spec(), "directionmix");
  return std::make_unique<DirectionMixTexture<FloatTexture>>(ctx.textures.float_param(p, "tex1"),
                                                             ctx.textures.float_param(p, "tex2"), read_dir(ctx, p));
}

std::unique_ptr<SpectrumTexture> create_directionmix_spectrum_texture(const TextureContext& ctx) {
  const PluginParams p(ctx.params, directionmix_texture_spec(), "directionmix");
  return std::make_unique<DirectionMixTexture<SpectrumTexture>>(
      ctx.textures.spectrum_param(p, "tex1"), ctx.textures.spectrum_param(p, "tex2"), read_dir(ctx, p));
}

}  // namespace eyetrace
