#include "materials/thin_dielectric_material.h"

#include "materials/dielectric_material.h"
#include "materials/local_bsdf.h"
#include "materials/shading_normal.h"
#include "materials/thin_dielectric_bxdf.h"

namespace eyetrace {

namespace {

class ThinDielectricMaterial final : public Material {
 public:
  ThinDielectricMaterial(DielectricEta eta, ShadingNormal shading) : eta_(std::move(eta)), shading_(shading) {}
  const BSDF* bsdf(const SurfaceInteraction& hit, SampledWavelengths& lambda, ScratchBuffer& arena) const override {
    const SurfaceInteraction si = shading_.apply(hit);
    // The transmitted ray goes straight on whatever the wavelength, but the split between the
    // lobes depends on it: a varying eta keeps the hero wavelength only (pbrt-v4's rule).
    if (eta_.dispersive) lambda.terminate_secondary();
    return make_local_bsdf(arena, si, ThinDielectricBxDF(eta_.spectrum(lambda[0])), hit.ns);
  }

 private:
  DielectricEta eta_;
  ShadingNormal shading_;
};

}  // namespace

const PluginSpec& thindielectric_material_spec() {
  static const PluginSpec spec{
      "Material", "a thin slab of glass (a window pane): mirror reflection and straight transmission", "—",
      std::vector<ParamSpec>{
          param::float_or_spectrum("eta", 1.5).above(0).describe("index of refraction of the slab")} +
          ShadingNormal::declared()};
  return spec;
}

std::unique_ptr<Material> create_thindielectric_material(const MaterialContext& ctx) {
  const PluginParams p(ctx.params, thindielectric_material_spec(), "thindielectric");
  return std::make_unique<ThinDielectricMaterial>(read_dielectric_eta(ctx, p), ShadingNormal::read(ctx, p));
}

}  // namespace eyetrace
