#include "materials/coated_diffuse_material.h"

#include "materials/coated_diffuse_bxdf.h"
#include "materials/dielectric_material.h"
#include "materials/local_bsdf.h"
#include "materials/normal_map.h"
#include "materials/roughness.h"
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
    const SpectrumTexture* normal_map;
  };
  explicit CoatedDiffuseMaterial(const Inputs& in) : in_(in) {}

  const BSDF* bsdf(const SurfaceInteraction& hit, ScratchBuffer& arena) const override {
    SurfaceInteraction si = apply_normal_map(in_.normal_map, hit);
    TextureEvalContext tc(si);
    float thickness = std::max(0.f, in_.thickness->evaluate(tc));
    if (!std::isfinite(thickness)) thickness = 0.f;
    RGB scattered = clamp_unit(in_.albedo->evaluate(tc));
    RGB tau = thickness * (RGB(1.f) - scattered);
    RGB r = in_.reflectance->evaluate(tc);
    return make_local_bsdf(arena, si, CoatedDiffuseBxDF(in_.coat, in_.roughness.distribution(tc), r, tau), hit.ns);
  }

 private:
  Inputs in_;
};

}  // namespace

std::unique_ptr<Material> create_coateddiffuse_material(const MaterialContext& ctx) {
  const ParameterList& p = ctx.params;
  CoatedDiffuseMaterial::Inputs in;
  in.coat = CoatConstants::make(read_eta_at_550(p, 1.5f));
  in.roughness = RoughnessParams::read(ctx);
  in.reflectance = ctx.textures.spectrum_param(p, "reflectance", RGB(0.5f));
  in.thickness = ctx.textures.float_param(p, "thickness", 0.01f);
  in.albedo = ctx.textures.spectrum_param(p, "albedo", RGB(0.f));
  in.normal_map = read_normal_map(ctx);
  // Read so that they are not reported as unused; the closed-form model has no use for them.
  ctx.textures.float_param(p, "g", 0.f);
  p.get_int_in("maxdepth", 10, 1, 1 << 20);
  p.get_int_in("nsamples", 1, 1, 1 << 20);
  return std::make_unique<CoatedDiffuseMaterial>(in);
}

}  // namespace eyetrace
