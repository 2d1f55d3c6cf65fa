#include "textures/texture_mapping.h"

#include <algorithm>
#include <map>

#include "lights/sphere_mapping.h"

namespace eyetrace {

std::vector<ParamSpec> TextureMapping2D::declared() {
  return {param::string("mapping", "uv")
              .in({"uv", "spherical", "cylindrical", "planar"})
              .describe("(u, v) or texture-space point → (s, t)"),
          param::real("uscale", 1).describe("`uv`"),
          param::real("vscale", 1).describe("`uv`"),
          param::real("udelta", 0).describe("`uv`, `planar`"),
          param::real("vdelta", 0).describe("`uv`, `planar`"),
          param::vector3("v1", Vec3(1.f, 0.f, 0.f)).describe("`planar`: s axis"),
          param::vector3("v2", Vec3(0.f, 1.f, 0.f)).describe("`planar`: t axis")};
}

namespace {

// The mappings each parameter belongs to: one given for another mapping would do nothing.
const std::map<std::string, std::vector<std::string>>& mapping_users() {
  static const std::map<std::string, std::vector<std::string>> users{
      {"uscale", {"uv"}},           {"vscale", {"uv"}}, {"udelta", {"uv", "planar"}},
      {"vdelta", {"uv", "planar"}}, {"v1", {"planar"}}, {"v2", {"planar"}}};
  return users;
}

}  // namespace

void TextureMapping2D::reject(const PluginParams& p, const std::string& why) {
  for (const auto& [name, kinds] : mapping_users())
    if (p.has(name)) p.fail(name, why);
  if (p.has("mapping")) p.fail("mapping", why);
}

TextureMapping2D TextureMapping2D::read(const TextureContext& ctx, const PluginParams& p) {
  TextureMapping2D m;
  m.texture_from_world_ = ctx.world_from_texture.inverse();
  const std::string kind = p.get_string("mapping");  // one of the declared choices
  for (const auto& [name, kinds] : mapping_users())
    if (p.has(name) && std::find(kinds.begin(), kinds.end(), kind) == kinds.end())
      p.fail(name, fmt::format("does nothing with mapping \"{}\"", kind));
  m.kind_ = kind == "spherical"     ? Kind::Spherical
            : kind == "cylindrical" ? Kind::Cylindrical
            : kind == "planar"      ? Kind::Planar
                                    : Kind::UV;
  m.scale_ = Vec2(p.get_float("uscale"), p.get_float("vscale"));
  m.delta_ = Vec2(p.get_float("udelta"), p.get_float("vdelta"));
  m.v1_ = p.get_vector3("v1");
  m.v2_ = p.get_vector3("v2");
  return m;
}

TextureCoords TextureMapping2D::map(const TextureEvalContext& ctx) const {
  TextureCoords c;
  switch (kind_) {
    case Kind::UV:
      c.st = scale_ * ctx.uv + delta_;
      c.width = ctx.footprint * std::max(std::abs(scale_.x), std::abs(scale_.y));
      break;
    case Kind::Spherical: {
      Vec3 d = texture_from_world_.point(ctx.p);
      float len = glm::length(d);
      c.st = len > 0.f ? equal_area_sphere_to_square(d / len) : Vec2(0.5f);
      break;
    }
    case Kind::Cylindrical: {
      Vec3 q = texture_from_world_.point(ctx.p);
      c.st = Vec2((kPi + std::atan2(q.y, q.x)) * kInv2Pi, q.z);
      break;
    }
    case Kind::Planar: {
      Vec3 q = texture_from_world_.point(ctx.p);
      c.st = Vec2(delta_.x + glm::dot(q, v1_), delta_.y + glm::dot(q, v2_));
      break;
    }
  }
  return c;
}

TextureMapping3D TextureMapping3D::read(const TextureContext& ctx) {
  TextureMapping3D m;
  m.texture_from_world_ = ctx.world_from_texture.inverse();
  return m;
}

}  // namespace eyetrace
