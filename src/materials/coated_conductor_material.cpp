#include "materials/coated_conductor_material.h"

#include "materials/bxdf_util.h"
#include "materials/coated_conductor_bxdf.h"
#include "materials/conductor_material.h"
#include "materials/dielectric_material.h"
#include "materials/local_bsdf.h"
#include "materials/roughness.h"
#include "materials/shading_normal.h"
#include "scene/texture_store.h"

namespace eyetrace {

namespace {

class CoatedConductorMaterial final : public Material {
 public:
  struct Inputs {
    DielectricEta coat_eta;
    RoughnessParams coat, metal;
    ConductorIndex index;
    const FloatTexture* thickness;
    const SpectrumTexture* albedo;
    ShadingNormal shading;
  };
  explicit CoatedConductorMaterial(Inputs in) : in_(std::move(in)) {}

  const BSDF* bsdf(const SurfaceInteraction& hit, SampledWavelengths& lambda, ScratchBuffer& arena) const override {
    const SurfaceInteraction si = in_.shading.apply(hit);
    const TextureEvalContext tc(si);
    const float n = in_.coat_eta.spectrum(lambda[0]);
    if (in_.coat_eta.dispersive) lambda.terminate_secondary();  // pbrt-v4's rule for a varying coat index
    SampledSpectrum eta, k;
    in_.index.evaluate(tc, lambda, &eta, &k);
    float thickness = std::max(0.f, in_.thickness->evaluate(tc));
    if (!std::isfinite(thickness)) thickness = 0.f;
    const SampledSpectrum tau = thickness * (SampledSpectrum(1.f) - clamp_unit(in_.albedo->evaluate(tc, lambda)));
    // The metal's index relative to the coat, as pbrt-v4 divides it.
    const CoatedConductorBxDF bxdf(n, in_.coat.distribution(tc), in_.metal.distribution(tc), eta / n, k / n, tau);
    return make_local_bsdf(arena, si, bxdf, hit.ns);
  }

 private:
  Inputs in_;
};

}  // namespace

const PluginSpec& coatedconductor_material_spec() {
  static const PluginSpec spec{
      "Material", "a metal under a dielectric coat",
      "A closed-form model (coat reflection + the metal seen through the coat, see coated_conductor_bxdf.h), not "
      "pbrt-v4's stochastic layered random walk; hence `g`, `maxdepth`, `nsamples` do nothing.",
      std::vector<ParamSpec>{param::float_or_spectrum("interface.eta", 1.5).above(0).describe("the coat's index")} +
          RoughnessParams::declared("interface.", false) + ConductorIndex::declared("conductor.") +
          RoughnessParams::declared("conductor.") +
          std::vector<ParamSpec>{param::float_texture("thickness", 0.01).describe("of the coat"),
                                 param::spectrum_texture("albedo", 0).describe("of the coat's medium"),
                                 param::float_texture("g", 0).describe("read and unused"),
                                 param::integer("maxdepth", 10).range(1, 1 << 20).describe("read and unused"),
                                 param::integer("nsamples", 1).range(1, 1 << 20).describe("read and unused")} +
          ShadingNormal::declared()};
  return spec;
}

std::unique_ptr<Material> create_coatedconductor_material(const MaterialContext& ctx) {
  const PluginParams p(ctx.params, coatedconductor_material_spec(), "coatedconductor");
  CoatedConductorMaterial::Inputs in;
  in.coat_eta = read_dielectric_eta(ctx, p, "interface.eta");
  in.coat = RoughnessParams::read(ctx, p, "interface.");
  in.metal = RoughnessParams::read(ctx, p, "conductor.");
  in.index = ConductorIndex::read(ctx, p, "conductor.");
  in.thickness = ctx.textures.float_param(p, "thickness");
  in.albedo = ctx.textures.spectrum_param(p, "albedo");
  in.shading = ShadingNormal::read(ctx, p);
  ctx.textures.float_param(p, "g");  // a texture it names must exist, though the model has no use for it
  return std::make_unique<CoatedConductorMaterial>(std::move(in));
}

}  // namespace eyetrace
