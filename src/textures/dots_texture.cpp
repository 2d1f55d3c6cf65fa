#include "textures/dots_texture.h"

#include <cmath>

#include "scene/texture_store.h"
#include "textures/perlin_noise.h"
#include "textures/texture_mapping.h"
#include "textures/texture_value.h"

namespace eyetrace {

namespace {

template <typename Base>
class DotsTexture final : public TextureOf<Base> {
  using Value = typename TextureOf<Base>::Value;

 public:
  DotsTexture(TextureMapping2D map, const Base* inside, const Base* outside)
      : map_(map), inside_(inside), outside_(outside) {}
  Value value(const TextureEvalContext& ctx, const SampledWavelengths& lambda) const override {
    return TextureOf<Base>::of(inside_polka_dot(map_.map(ctx).st) ? *inside_ : *outside_, ctx, lambda);
  }

 private:
  TextureMapping2D map_;
  const Base* inside_;
  const Base* outside_;
};

}  // namespace

bool inside_polka_dot(Vec2 st) {
  if (!std::isfinite(st.x) || !std::isfinite(st.y)) return false;
  const float s_cell = std::floor(st.x + 0.5f), t_cell = std::floor(st.y + 0.5f);
  if (!(perlin_noise(s_cell + 0.5f, t_cell + 0.5f) > 0.f)) return false;
  constexpr float kRadius = 0.35f, kMaxShift = 0.5f - kRadius;
  const float s_centre = s_cell + kMaxShift * perlin_noise(s_cell + 1.5f, t_cell + 2.8f);
  const float t_centre = t_cell + kMaxShift * perlin_noise(s_cell + 4.5f, t_cell + 9.8f);
  const float ds = st.x - s_centre, dt = st.y - t_centre;
  return ds * ds + dt * dt < kRadius * kRadius;
}

const PluginSpec& dots_texture_spec() {
  static const PluginSpec spec{
      "Texture", "polka dots of radius 0.35 in the unit cells of (s, t), by Perlin noise",
      "pbrt-v4 (5f7a606) paints `inside` around the dots and `outside` in them (its Create passes them to "
      "constructors declared the other way round); eyetrace follows the names",
      std::vector<ParamSpec>{param::any_texture("inside", 1).describe("of the texture's kind"),
                             param::any_texture("outside", 0).describe("of the texture's kind")} +
          TextureMapping2D::declared()};
  return spec;
}

std::unique_ptr<FloatTexture> create_dots_float_texture(const TextureContext& ctx) {
  const PluginParams p(ctx.params, dots_texture_spec(), "dots");
  return std::make_unique<DotsTexture<FloatTexture>>(
      TextureMapping2D::read(ctx, p), ctx.textures.float_param(p, "inside"), ctx.textures.float_param(p, "outside"));
}

std::unique_ptr<SpectrumTexture> create_dots_spectrum_texture(const TextureContext& ctx) {
  const PluginParams p(ctx.params, dots_texture_spec(), "dots");
  return std::make_unique<DotsTexture<SpectrumTexture>>(TextureMapping2D::read(ctx, p),
                                                        ctx.textures.spectrum_param(p, "inside"),
                                                        ctx.textures.spectrum_param(p, "outside"));
}

}  // namespace eyetrace
