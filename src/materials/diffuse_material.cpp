#include "materials/diffuse_material.h"

#include "materials/lambertian_bxdf.h"
#include "materials/local_bsdf.h"
#include "materials/shading_normal.h"
#include "scene/texture_store.h"

namespace eyetrace {

namespace {

class DiffuseMaterial final : public Material {
 public:
  DiffuseMaterial(const SpectrumTexture* reflectance, ShadingNormal shading)
      : reflectance_(reflectance), shading_(shading) {}
  const BSDF* bsdf(const SurfaceInteraction& hit, SampledWavelengths& lambda, ScratchBuffer& arena) const override {
    SurfaceInteraction si = shading_.apply(hit);
    SampledSpectrum r = reflectance_->evaluate(TextureEvalContext(si), lambda);
    return make_local_bsdf(arena, si, LambertianBxDF(r), hit.ns);
  }

 private:
  const SpectrumTexture* reflectance_;
  ShadingNormal shading_;
};

}  // namespace

const PluginSpec& diffuse_material_spec() {
  static const PluginSpec spec{
      "Material", "Lambertian reflection", "—",
      std::vector<ParamSpec>{param::spectrum_texture("reflectance", 0.5)} + ShadingNormal::declared()};
  return spec;
}

std::unique_ptr<Material> create_diffuse_material(const MaterialContext& ctx) {
  const PluginParams p(ctx.params, diffuse_material_spec(), "diffuse");
  return std::make_unique<DiffuseMaterial>(ctx.textures.spectrum_param(p, "reflectance"), ShadingNormal::read(ctx, p));
}

}  // namespace eyetrace
