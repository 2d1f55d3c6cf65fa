#include "materials/roughness.h"

#include "scene/texture_store.h"

namespace eyetrace {

// pbrt-v4 takes roughness >= 0; a negative constant is a mistake in the scene, not a surface
// (textures may still dip below 0 and count as 0 at the hit).
std::vector<ParamSpec> RoughnessParams::declared(const std::string& prefix, bool with_remap) {
  std::vector<ParamSpec> specs = {
      param::float_texture(prefix + "roughness", 0).at_least(0).describe("microfacet roughness (0: smooth)"),
      param::float_texture(prefix + "uroughness")
          .at_least(0)
          .shown_default(prefix + "roughness")
          .describe("roughness along u"),
      param::float_texture(prefix + "vroughness")
          .at_least(0)
          .shown_default(prefix + "roughness")
          .describe("roughness along v")};
  if (with_remap)
    specs.push_back(param::boolean("remaproughness", true).describe("roughness → Trowbridge-Reitz alpha, as pbrt-v4"));
  return specs;
}

RoughnessParams RoughnessParams::read(const MaterialContext& ctx, const PluginParams& params,
                                      const std::string& prefix) {
  RoughnessParams r;
  r.u = ctx.textures.float_param(params, prefix + "uroughness");
  r.v = ctx.textures.float_param(params, prefix + "vroughness");
  if (!r.u || !r.v) {
    const FloatTexture* both = ctx.textures.float_param(params, prefix + "roughness");
    if (!r.u) r.u = both;
    if (!r.v) r.v = both;
  }
  r.remap = params.get_bool("remaproughness");
  return r;
}

TrowbridgeReitz RoughnessParams::distribution(const TextureEvalContext& tc) const {
  float u_r = std::max(0.f, u->evaluate(tc)), v_r = std::max(0.f, v->evaluate(tc));
  if (!std::isfinite(u_r)) u_r = 0.f;
  if (!std::isfinite(v_r)) v_r = 0.f;
  if (remap) {
    u_r = TrowbridgeReitz::roughness_to_alpha(u_r);
    v_r = TrowbridgeReitz::roughness_to_alpha(v_r);
  }
  return TrowbridgeReitz(u_r, v_r);
}

}  // namespace eyetrace
