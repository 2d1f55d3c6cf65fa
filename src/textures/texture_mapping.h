// pbrt-v4's 2D texture mappings, from a hit to texture coordinates (s, t):
//  "uv" (default): s = uscale u + udelta, t = vscale v + vdelta;
//  "spherical": equal-area square of the direction to the texture-space point;
//  "cylindrical": s = (pi + atan2(y, x)) / (2 pi), t = z in texture space;
//  "planar": s = udelta + dot(p, v1), t = vdelta + dot(p, v2) in texture space.
#pragma once
#include "core/texture.h"
#include "core/transform.h"
#include "scene/registry.h"

namespace eyetrace {

struct TextureCoords {
  Vec2 st{0.f};
  float width = 0.f;  // filter width in (s, t) units; 0 point-samples
};

class TextureMapping2D {
 public:
  // "mapping" and the parameters of each mapping, for the tables of the textures that map.
  static std::vector<ParamSpec> declared();
  static TextureMapping2D read(const TextureContext& ctx, const PluginParams& p);
  // Errors naming a mapping parameter given to a texture that does not map in 2-D.
  static void reject(const PluginParams& p, const std::string& why);
  TextureCoords map(const TextureEvalContext& ctx) const;

 private:
  enum class Kind { UV, Spherical, Cylindrical, Planar };
  Kind kind_ = Kind::UV;
  Vec2 scale_{1.f}, delta_{0.f};
  Vec3 v1_{1.f, 0.f, 0.f}, v2_{0.f, 1.f, 0.f};
  Transform texture_from_world_;
};

// Texture-space point for solid (3D) textures.
class TextureMapping3D {
 public:
  static TextureMapping3D read(const TextureContext& ctx);
  Vec3 map(const TextureEvalContext& ctx) const { return texture_from_world_.point(ctx.p); }

 private:
  Transform texture_from_world_;
};

}  // namespace eyetrace
