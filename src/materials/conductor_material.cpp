#include "materials/conductor_material.h"

#include <algorithm>

#include "materials/conductor_bxdf.h"
#include "materials/local_bsdf.h"
#include "materials/roughness.h"
#include "materials/shading_normal.h"
#include "scene/spectrum_param.h"
#include "scene/texture_store.h"

namespace eyetrace {

namespace {

Spectrum named(const std::string& name) { return Spectrum::named(*find_named_spectrum(name), SpectrumType::Unbounded); }

class ConductorMaterial final : public Material {
 public:
  ConductorMaterial(ConductorIndex index, RoughnessParams roughness, ShadingNormal shading)
      : index_(index), roughness_(roughness), shading_(shading) {}

  const BSDF* bsdf(const SurfaceInteraction& hit, SampledWavelengths& lambda, ScratchBuffer& arena) const override {
    SurfaceInteraction si = shading_.apply(hit);
    TextureEvalContext tc(si);
    SampledSpectrum eta, k;
    index_.evaluate(tc, lambda, &eta, &k);
    return make_local_bsdf(arena, si, ConductorBxDF(roughness_.distribution(tc), eta, k), hit.ns);
  }

 private:
  ConductorIndex index_;
  RoughnessParams roughness_;
  ShadingNormal shading_;
};

}  // namespace

std::vector<ParamSpec> ConductorIndex::declared(const std::string& prefix) {
  return {param::spectrum_texture(prefix + "eta").shown_default("\"metal-Cu-eta\"").describe("real part of the index"),
          param::spectrum_texture(prefix + "k").shown_default("\"metal-Cu-k\"").describe("imaginary part of the index"),
          param::spectrum_texture("reflectance")
              .describe(fmt::format("instead of `{0}eta` and `{0}k` (not with them)", prefix))};
}

ConductorIndex ConductorIndex::read(const MaterialContext& ctx, const PluginParams& p, const std::string& prefix) {
  check_constant_spectrum_sign(ctx.params, prefix + "eta", false);
  check_constant_spectrum_sign(ctx.params, prefix + "k", true);
  ConductorIndex c;
  c.eta = ctx.textures.spectrum_param(p, prefix + "eta", SpectrumType::Unbounded);
  c.k = ctx.textures.spectrum_param(p, prefix + "k", SpectrumType::Unbounded);
  c.reflectance = ctx.textures.spectrum_param(p, "reflectance");
  if (c.reflectance && (c.eta || c.k))
    p.fail("reflectance", fmt::format("give either \"reflectance\" or \"{0}eta\" and \"{0}k\", not both", prefix));
  if (!c.reflectance) {
    if (!c.eta) c.eta = ctx.textures.keep(std::make_unique<ConstantSpectrumTexture>(named("metal-Cu-eta")));
    if (!c.k) c.k = ctx.textures.keep(std::make_unique<ConstantSpectrumTexture>(named("metal-Cu-k")));
  }
  return c;
}

void ConductorIndex::evaluate(TextureEvalContext tc, const SampledWavelengths& lambda, SampledSpectrum* eta,
                              SampledSpectrum* k) const {
  if (reflectance) {
    // pbrt-v4: eta = 1 and the k whose normal-incidence reflectance k^2/(4+k^2) is r.
    SampledSpectrum r = min(clamp_unit(reflectance->evaluate(tc, lambda)), 0.9999f);
    *eta = SampledSpectrum(1.f);
    *k = 2.f * sqrt(r) * safe_div(SampledSpectrum(1.f), sqrt(SampledSpectrum(1.f) - r));
  } else {
    // Indices are not reflectances: RGB values become unbounded spectra.
    tc.spectrum_type = SpectrumType::Unbounded;
    *eta = clamp_non_negative(this->eta->evaluate(tc, lambda), 1.f);
    *k = clamp_non_negative(this->k->evaluate(tc, lambda), 0.f);
  }
}

const PluginSpec& conductor_material_spec() {
  static const PluginSpec spec{"Material", "a metal: Fresnel reflection of a complex index of refraction", "—",
                               ConductorIndex::declared() + RoughnessParams::declared() + ShadingNormal::declared()};
  return spec;
}

std::unique_ptr<Material> create_conductor_material(const MaterialContext& ctx) {
  const PluginParams p(ctx.params, conductor_material_spec(), "conductor");
  return std::make_unique<ConductorMaterial>(ConductorIndex::read(ctx, p), RoughnessParams::read(ctx, p),
                                             ShadingNormal::read(ctx, p));
}

}  // namespace eyetrace
