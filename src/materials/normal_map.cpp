#include "materials/normal_map.h"

#include <filesystem>

#include "scene/scene_files.h"
#include "scene/texture_store.h"
#include "textures/imagemap_texture.h"

namespace eyetrace {

ParamSpec normal_map_param() {
  return param::string("normalmap").describe("image of tangent-space normals (read linear, wrapped by repetition)");
}

const ImageTexture* read_normal_map(const MaterialContext& ctx, const PluginParams& params) {
  if (!params.has("normalmap")) return nullptr;
  const Param* p = ctx.params.find("normalmap");
  std::string file = params.get_string("normalmap");
  std::filesystem::path path(resolve_scene_file(ctx.search_dir, file));
  if (!std::filesystem::is_regular_file(path))
    ctx.params.fail_missing_file("normalmap", fmt::format("image file \"{}\" not found", path.string()));
  // Reuse the imagemap texture with the settings pbrt-v4 reads normal maps with.
  ParameterList image(p->loc);
  auto add = [&](const char* name, const std::string& value) {
    Param q;
    q.type = "string";
    q.name = name;
    q.loc = p->loc;
    q.strings = {value};
    image.add(q);
  };
  add("filename", path.string());
  add("encoding", "linear");
  add("wrap", "repeat");
  std::unique_ptr<ImageTexture> tex =
      create_imagemap_image_texture(TextureContext{image, Transform(), ctx.textures, ""});
  const ImageTexture* map = tex.get();
  ctx.textures.keep(std::move(tex));
  return map;
}

SurfaceInteraction apply_normal_map(const ImageTexture* map, const SurfaceInteraction& si) {
  if (!map) return si;
  RGB c = map->rgb(TextureEvalContext(si));
  Vec3 local = 2.f * c - Vec3(1.f);
  float len2 = glm::dot(local, local);
  if (!(len2 > 0.f) || !std::isfinite(len2)) return si;
  local /= std::sqrt(len2);
  // Tangent frame: x along dpdu (made orthogonal to ns), z along ns.
  Vec3 x = si.dpdu - si.ns * glm::dot(si.ns, si.dpdu);
  float xl = glm::dot(x, x);
  if (!(xl > 1e-12f)) return si;
  x /= std::sqrt(xl);
  Vec3 y = glm::cross(si.ns, x);
  Vec3 ns = glm::normalize(x * local.x + y * local.y + si.ns * local.z);
  if (glm::dot(ns, si.n) < 0.f) ns = -ns;  // keep the shading normal on the geometric side
  SurfaceInteraction out = si;
  out.ns = ns;
  Vec3 t = si.dpdu - ns * glm::dot(ns, si.dpdu);
  if (glm::dot(t, t) > 1e-12f) out.dpdu = glm::normalize(t) * glm::length(si.dpdu);
  return out;
}

}  // namespace eyetrace
