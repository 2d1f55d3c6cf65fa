#include "materials/diffuse_transmission_material.h"

#include "materials/diffuse_transmission_bxdf.h"
#include "materials/local_bsdf.h"
#include "materials/shading_normal.h"
#include "scene/texture_store.h"

namespace eyetrace {

namespace {

class DiffuseTransmissionMaterial final : public Material {
 public:
  DiffuseTransmissionMaterial(const SpectrumTexture* r, const SpectrumTexture* t, float scale, ShadingNormal shading)
      : r_(r), t_(t), scale_(scale), shading_(shading) {}
  const BSDF* bsdf(const SurfaceInteraction& hit, SampledWavelengths& lambda, ScratchBuffer& arena) const override {
    const SurfaceInteraction si = shading_.apply(hit);
    const TextureEvalContext tc(si);
    const DiffuseTransmissionBxDF bxdf(scale_ * r_->evaluate(tc, lambda), scale_ * t_->evaluate(tc, lambda));
    return make_local_bsdf(arena, si, bxdf, hit.ns);
  }

 private:
  const SpectrumTexture* r_;
  const SpectrumTexture* t_;
  float scale_;
  ShadingNormal shading_;
};

}  // namespace

const PluginSpec& diffusetransmission_material_spec() {
  static const PluginSpec spec{
      "Material", "Lambertian reflection and Lambertian transmission", "—",
      std::vector<ParamSpec>{param::spectrum_texture("reflectance", 0.25),
                             param::spectrum_texture("transmittance", 0.25),
                             param::real("scale", 1).at_least(0).describe("multiplies both (then clamped to [0, 1])")} +
          ShadingNormal::declared()};
  return spec;
}

std::unique_ptr<Material> create_diffusetransmission_material(const MaterialContext& ctx) {
  const PluginParams p(ctx.params, diffusetransmission_material_spec(), "diffusetransmission");
  return std::make_unique<DiffuseTransmissionMaterial>(ctx.textures.spectrum_param(p, "reflectance"),
                                                       ctx.textures.spectrum_param(p, "transmittance"),
                                                       p.get_float("scale"), ShadingNormal::read(ctx, p));
}

}  // namespace eyetrace
