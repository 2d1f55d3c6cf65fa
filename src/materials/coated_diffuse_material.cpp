#include "materials/coated_diffuse_material.h"

#include "materials/coated_diffuse_bxdf.h"
#include "materials/dielectric_material.h"
#include "materials/local_bsdf.h"
#include "materials/roughness.h"
#include "materials/shading_normal.h"
#include "scene/texture_store.h"

namespace eyetrace {

namespace {

class CoatedDiffuseMaterial final : public Material {
 public:
  struct Inputs {
    CoatConstants coat;
    RoughnessParams roughness;
    const SpectrumTexture* reflectance;
    const FloatTexture* thickness;
    const SpectrumTexture* albedo;
    ShadingNormal shading;
  };
  explicit CoatedDiffuseMaterial(const Inputs& in) : in_(in) {}

  const BSDF* bsdf(const SurfaceInteraction& hit, SampledWavelengths& lambda, ScratchBuffer& arena) const override {
    SurfaceInteraction si = in_.shading.apply(hit);
    TextureEvalContext tc(si);
    float thickness = std::max(0.f, in_.thickness->evaluate(tc));
    if (!std::isfinite(thickness)) thickness = 0.f;
    SampledSpectrum scattered = clamp_unit(in_.albedo->evaluate(tc, lambda));
    SampledSpectrum tau = thickness * (SampledSpectrum(1.f) - scattered);
    SampledSpectrum r = in_.reflectance->evaluate(tc, lambda);
    return make_local_bsdf(arena, si, CoatedDiffuseBxDF(in_.coat, in_.roughness.distribution(tc), r, tau), hit.ns);
  }

 private:
  Inputs in_;
};

}  // namespace

const PluginSpec& coateddiffuse_material_spec() {
  static const PluginSpec spec{
      "Material", "a diffuse base under a dielectric coat",
      "A closed-form two-lobe model (coat reflection + diffuse base with the coat's Fresnel transmission and "
      "absorption), not pbrt-v4's stochastic layered random walk; hence `g`, `maxdepth`, `nsamples` do nothing.",
      std::vector<ParamSpec>{param::spectrum_texture("reflectance", 0.5).describe("of the base"),
                             param::float_texture("thickness", 0.01).describe("of the coat"),
                             param::spectrum_texture("albedo", 0).describe("of the coat's medium"),
                             eta_at_550_param()} +
          RoughnessParams::declared() + ShadingNormal::declared() +
          std::vector<ParamSpec>{param::float_texture("g", 0).describe("read and unused"),
                                 param::integer("maxdepth", 10).range(1, 1 << 20).describe("read and unused"),
                                 param::integer("nsamples", 1).range(1, 1 << 20).describe("read and unused")}};
  return spec;
}

std::unique_ptr<Material> create_coateddiffuse_material(const MaterialContext& ctx) {
  const PluginParams p(ctx.params, coateddiffuse_material_spec(), "coateddiffuse");
  CoatedDiffuseMaterial::Inputs in;
  in.coat = CoatConstants::make(read_eta_at_550(p));
  in.roughness = RoughnessParams::read(ctx, p);
  in.reflectance = ctx.textures.spectrum_param(p, "reflectance");
  in.thickness = ctx.textures.float_param(p, "thickness");
  in.albedo = ctx.textures.spectrum_param(p, "albedo");
  in.shading = ShadingNormal::read(ctx, p);
  ctx.textures.float_param(p, "g");  // a texture it names must exist, though the model has no use for it
  return std::make_unique<CoatedDiffuseMaterial>(in);
}

}  // namespace eyetrace
