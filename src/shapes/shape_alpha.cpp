#include "shapes/shape_alpha.h"

#include "samplers/hash.h"
#include "scene/texture_store.h"

namespace eyetrace {

bool ShapeAlpha::passes(const TextureEvalContext& ctx, const Vec3& o, const Vec3& d) const {
  if (opaque()) return true;
  const float a = texture ? texture->evaluate(ctx) : constant;
  if (a >= 1.f) return true;
  if (!(a > 0.f)) return false;  // 0, negative or NaN: no surface
  // pbrt-v4's HashFloat(o, d): uniform in [0, 1), the same for the same ray.
  return hash_float(o.x, o.y, o.z, d.x, d.y, d.z) <= a;
}

bool ShapeAlpha::masks(const TextureEvalContext& ctx) const {
  if (opaque()) return false;
  const float a = texture ? texture->evaluate(ctx) : constant;
  if (a >= 1.f) return false;
  if (!(a > 0.f)) return true;
  return hash_float(ctx.p.x, ctx.p.y, ctx.p.z) > a;
}

ParamSpec alpha_param() {
  return param::float_texture("alpha", 1)
      .describe("cutout: 0 no surface, 1 opaque, between: passes that fraction of rays");
}

ShapeAlpha read_alpha(const ShapeContext& ctx, const PluginParams& params) {
  ShapeAlpha alpha;
  const Param* p = params.list().find("alpha");
  if (!p) return alpha;
  if (p->canonical_type() != "texture") {
    alpha.constant = params.get_float("alpha");
    return alpha;
  }
  if (!ctx.textures) params.fail("alpha", "a texture alpha needs the scene's textures (internal: none given)");
  alpha.texture = ctx.textures->float_param(params, "alpha");
  return alpha;
}

}  // namespace eyetrace
