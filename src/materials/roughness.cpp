#include "materials/roughness.h"

#include "scene/texture_store.h"

namespace eyetrace {

namespace {

// pbrt-v4 takes roughness >= 0; a negative constant is a mistake in the scene, not a surface
// (textures may still dip below 0 and count as 0 at the hit).
void check_not_negative(const ParameterList& params, const char* name) {
  const Param* p = params.find(name);
  if (p && p->canonical_type() == "float" && !p->numbers.empty() && p->numbers[0] < 0)
    params.fail(name, fmt::format("roughness {} must not be negative", p->numbers[0]));
}

}  // namespace

RoughnessParams RoughnessParams::read(const MaterialContext& ctx) {
  for (const char* name : {"roughness", "uroughness", "vroughness"}) check_not_negative(ctx.params, name);
  RoughnessParams r;
  r.u = ctx.textures.float_param_or_null(ctx.params, "uroughness");
  r.v = ctx.textures.float_param_or_null(ctx.params, "vroughness");
  if (!r.u || !r.v) {
    const FloatTexture* both = ctx.textures.float_param(ctx.params, "roughness", 0.f);
    if (!r.u) r.u = both;
    if (!r.v) r.v = both;
  }
  r.remap = ctx.params.get_bool("remaproughness", true);
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
