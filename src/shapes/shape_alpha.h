// Alpha cutouts, as every pbrt-v4 shape takes them ("float alpha" or "texture alpha", default
// 1): where alpha is 0 the surface is not there; below 1 a ray passes with probability 1 -
// alpha, decided by a hash of the ray's origin and direction (pbrt-v4's HashFloat), the same
// decision every time that ray is traced. Triangle meshes apply it in an Embree filter
// function, the quadrics in their own ray test. An area light on a cut-out shape emits only
// where the shape is (masks), except on a shape of constant alpha 0 (invisible), as pbrt-v4.
#pragma once
#include "core/texture.h"
#include "scene/registry.h"

namespace eyetrace {

struct ShapeAlpha {
  const FloatTexture* texture = nullptr;  // a named texture, or
  float constant = 1.f;                   // a constant (1: opaque)
  bool opaque() const { return !texture && constant >= 1.f; }
  // Whether the ray (o, d) meets the surface at the point `ctx` describes.
  bool passes(const TextureEvalContext& ctx, const Vec3& o, const Vec3& d) const;
  // Whether an area light on the shape emits nothing at this point: alpha 0, or below 1 for a
  // fraction 1 - alpha of points (a hash of the point, pbrt-v4's HashFloat(p)).
  bool masks(const TextureEvalContext& ctx) const;
  bool invisible() const { return !texture && !(constant > 0.f); }
};

// "alpha", for every shape's table, and its value read (a named texture from the scene's store).
ParamSpec alpha_param();
ShapeAlpha read_alpha(const ShapeContext& ctx, const PluginParams& params);

}  // namespace eyetrace
