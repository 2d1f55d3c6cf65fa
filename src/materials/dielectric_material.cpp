#include "materials/dielectric_material.h"

#include "materials/dielectric_bxdf.h"
#include "materials/local_bsdf.h"
#include "materials/roughness.h"
#include "materials/shading_normal.h"
#include "scene/spectrum_param.h"

namespace eyetrace {

namespace {

// A dispersive index refracts each wavelength its own way, so the path keeps only its hero
// wavelength (as pbrt-v4 does); a constant index keeps all four.
class DielectricMaterial final : public Material {
 public:
  DielectricMaterial(Spectrum eta, bool dispersive, RoughnessParams roughness, ShadingNormal shading)
      : eta_(std::move(eta)), dispersive_(dispersive), roughness_(roughness), shading_(shading) {}
  const BSDF* bsdf(const SurfaceInteraction& hit, SampledWavelengths& lambda, ScratchBuffer& arena) const override {
    SurfaceInteraction si = shading_.apply(hit);
    TrowbridgeReitz mf = roughness_.distribution(TextureEvalContext(si));
    if (dispersive_) lambda.terminate_secondary();
    return make_local_bsdf(arena, si, DielectricBxDF(eta_(lambda[0]), mf), hit.ns);
  }

 private:
  Spectrum eta_;
  bool dispersive_;
  RoughnessParams roughness_;
  ShadingNormal shading_;
};

}  // namespace

ParamSpec eta_at_550_param() {
  return param::float_or_spectrum("eta", 1.5).above(0).describe("index of refraction (a spectrum is taken at 550 nm)");
}

float read_eta_at_550(const PluginParams& params, const std::string& name) {
  const float eta = params.get_spectrum_at(name, 550.f);
  if (!(eta > 0.f) || !std::isfinite(eta))
    params.fail(name, fmt::format("index of refraction {} must be positive", eta));
  return eta;
}

const PluginSpec& dielectric_material_spec() {
  static const PluginSpec spec{
      "Material", "a smooth or rough boundary of glass, water and the like", "—",
      std::vector<ParamSpec>{param::float_or_spectrum("eta", 1.5)
                                 .above(0)
                                 .describe("index of refraction; a spectrum (e.g. `\"glass-BK7\"`) disperses")} +
          RoughnessParams::declared() + ShadingNormal::declared()};
  return spec;
}

DielectricEta read_dielectric_eta(const MaterialContext& ctx, const PluginParams& p, const std::string& name) {
  DielectricEta eta{Spectrum::constant(read_eta_at_550(p, name)), false};
  if (p.has(name) && ctx.params.find(name)->canonical_type() == "spectrum") {
    const SpectrumValue v = p.get_spectrum(name, SpectrumType::Unbounded);
    if (!v.rgb) {
      eta = {v.spectrum, true};
      for (float l = kLambdaMin; l <= kLambdaMax; l += 1.f)
        if (!(eta.spectrum(l) > 0.f) || !std::isfinite(eta.spectrum(l)))
          p.fail(name, fmt::format("index of refraction {} at {} nm must be positive", eta.spectrum(l), l));
    }
  }
  return eta;
}

std::unique_ptr<Material> create_dielectric_material(const MaterialContext& ctx) {
  const PluginParams p(ctx.params, dielectric_material_spec(), "dielectric");
  DielectricEta eta = read_dielectric_eta(ctx, p);
  return std::make_unique<DielectricMaterial>(std::move(eta.spectrum), eta.dispersive, RoughnessParams::read(ctx, p),
                                              ShadingNormal::read(ctx, p));
}

}  // namespace eyetrace
