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

float read_eta_at_550(const ParameterList& params, float def) {
  const Param* p = params.find("eta");
  float eta =
      p && p->canonical_type() != "float" ? params.get_spectrum_at("eta", 550.f, def) : params.get_float("eta", def);
  if (!(eta > 0.f) || !std::isfinite(eta))
    params.fail("eta", fmt::format("index of refraction {} must be positive", eta));
  return eta;
}

std::unique_ptr<Material> create_dielectric_material(const MaterialContext& ctx) {
  float eta = read_eta_at_550(ctx.params, 1.5f);
  return std::make_unique<DielectricMaterial>(eta, RoughnessParams::read(ctx), read_normal_map(ctx));
}

}  // namespace eyetrace
