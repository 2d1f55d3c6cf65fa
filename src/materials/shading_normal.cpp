#include "materials/shading_normal.h"

#include "materials/bump_map.h"
#include "materials/normal_map.h"
#include "scene/texture_store.h"

namespace eyetrace {

std::vector<ParamSpec> ShadingNormal::declared() {
  return {normal_map_param(),
          param::float_texture("displacement").describe("bump map: displacement along the normal (scene units)")};
}

ShadingNormal ShadingNormal::read(const MaterialContext& ctx, const PluginParams& params) {
  ShadingNormal s;
  s.normal_map = read_normal_map(ctx, params);
  s.displacement = ctx.textures.float_param(params, "displacement");  // null when absent (no default)
  return s;
}

SurfaceInteraction ShadingNormal::apply(const SurfaceInteraction& hit) const {
  if (normal_map) return apply_normal_map(normal_map, hit);
  return apply_bump_map(displacement, hit);
}

}  // namespace eyetrace
