#include "textures/texture_mapping.h"

#include "lights/sphere_mapping.h"

namespace eyetrace {

TextureMapping2D TextureMapping2D::read(const TextureContext& ctx) {
  const ParameterList& p = ctx.params;
  TextureMapping2D m;
  m.texture_from_world_ = ctx.world_from_texture.inverse();
  std::string kind = p.get_string("mapping", "uv");
  if (kind == "uv") {
    m.kind_ = Kind::UV;
    m.scale_ = Vec2(p.get_float("uscale", 1.f), p.get_float("vscale", 1.f));
  } else if (kind == "spherical") {
    m.kind_ = Kind::Spherical;
  } else if (kind == "cylindrical") {
    m.kind_ = Kind::Cylindrical;
  } else if (kind == "planar") {
    m.kind_ = Kind::Planar;
    m.v1_ = p.get_vector3("v1", m.v1_);
    m.v2_ = p.get_vector3("v2", m.v2_);
  } else {
    p.fail("mapping",
           fmt::format("unknown texture mapping \"{}\"; eyetrace supports uv, spherical, cylindrical, planar", kind));
  }
  if (m.kind_ == Kind::UV || m.kind_ == Kind::Planar)
    m.delta_ = Vec2(p.get_float("udelta", 0.f), p.get_float("vdelta", 0.f));
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
