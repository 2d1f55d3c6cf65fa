#include "materials/dielectric_material.h"

#include "materials/dielectric_bxdf.h"
#include "materials/local_bsdf.h"
#include "materials/normal_map.h"
#include "materials/roughness.h"
#include "scene/spectrum_param.h"

namespace eyetrace {

namespace {

class DielectricMaterial final : public Material {
 public:
  DielectricMaterial(float eta, RoughnessParams roughness, const SpectrumTexture* normal_map)
      : eta_(eta), roughness_(roughness), normal_map_(normal_map) {}
  const BSDF* bsdf(const SurfaceInteraction& hit, ScratchBuffer& arena) const override {
    SurfaceInteraction si = apply_normal_map(normal_map_, hit);
    TrowbridgeReitz mf = roughness_.distribution(TextureEvalContext(si));
    return make_local_bsdf(arena, si, DielectricBxDF(eta_, mf), hit.ns);
  }

 private:
  float eta_;
  RoughnessParams roughness_;
  const SpectrumTexture* normal_map_;
};

}  // namespace

ParamSpec eta_at_550_param() {
  return param::float_or_spectrum("eta", 1.5).above(0).describe("index of refraction (a spectrum is taken at 550 nm)");
}

float read_eta_at_550(const PluginParams& params) {
  const float eta = params.get_spectrum_at("eta", 550.f);
  if (!(eta > 0.f) || !std::isfinite(eta))
    params.fail("eta", fmt::format("index of refraction {} must be positive", eta));
  return eta;
}

const PluginSpec& dielectric_material_spec() {
  static const PluginSpec spec{"Material", "a smooth or rough boundary of glass, water and the like",
                               "No dispersion: a spectral `eta` (e.g. `\"glass-BK7\"`) is used at 550 nm.",
                               std::vector<ParamSpec>{eta_at_550_param()} + RoughnessParams::declared() +
                                   std::vector<ParamSpec>{normal_map_param()}};
  return spec;
}

std::unique_ptr<Material> create_dielectric_material(const MaterialContext& ctx) {
  const PluginParams p(ctx.params, dielectric_material_spec(), "dielectric");
  return std::make_unique<DielectricMaterial>(read_eta_at_550(p), RoughnessParams::read(ctx, p),
                                              read_normal_map(ctx, p));
}

}  // namespace eyetrace
