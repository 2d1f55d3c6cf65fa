#include "materials/diffuse_material.h"

#include "materials/lambertian_bxdf.h"
#include "materials/local_bsdf.h"
#include "materials/normal_map.h"
#include "scene/texture_store.h"

namespace eyetrace {

namespace {

class DiffuseMaterial final : public Material {
 public:
  DiffuseMaterial(const SpectrumTexture* reflectance, const ImageTexture* normal_map)
      : reflectance_(reflectance), normal_map_(normal_map) {}
  const BSDF* bsdf(const SurfaceInteraction& hit, SampledWavelengths& lambda, ScratchBuffer& arena) const override {
    SurfaceInteraction si = apply_normal_map(normal_map_, hit);
    SampledSpectrum r = reflectance_->evaluate(TextureEvalContext(si), lambda);
    return make_local_bsdf(arena, si, LambertianBxDF(r), hit.ns);
  }

 private:
  const SpectrumTexture* reflectance_;
  const ImageTexture* normal_map_;
};

}  // namespace

const PluginSpec& diffuse_material_spec() {
  static const PluginSpec spec{
      "Material", "Lambertian reflection", "—", {param::spectrum_texture("reflectance", 0.5), normal_map_param()}};
  return spec;
}

std::unique_ptr<Material> create_diffuse_material(const MaterialContext& ctx) {
  const PluginParams p(ctx.params, diffuse_material_spec(), "diffuse");
  return std::make_unique<DiffuseMaterial>(ctx.textures.spectrum_param(p, "reflectance"), read_normal_map(ctx, p));
}

}  // namespace eyetrace
