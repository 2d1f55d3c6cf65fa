#include "materials/diffuse_material.h"

#include "materials/lambertian_bxdf.h"
#include "materials/local_bsdf.h"
#include "materials/normal_map.h"
#include "scene/texture_store.h"

namespace eyetrace {

namespace {

class DiffuseMaterial final : public Material {
 public:
  DiffuseMaterial(const SpectrumTexture* reflectance, const SpectrumTexture* normal_map)
      : reflectance_(reflectance), normal_map_(normal_map) {}
  const BSDF* bsdf(const SurfaceInteraction& hit, ScratchBuffer& arena) const override {
    SurfaceInteraction si = apply_normal_map(normal_map_, hit);
    RGB r = reflectance_->evaluate(TextureEvalContext(si));
    return make_local_bsdf(arena, si, LambertianBxDF(r), hit.ns);
  }

 private:
  const SpectrumTexture* reflectance_;
  const SpectrumTexture* normal_map_;
};

}  // namespace

std::unique_ptr<Material> create_diffuse_material(const MaterialContext& ctx) {
  return std::make_unique<DiffuseMaterial>(ctx.textures.spectrum_param(ctx.params, "reflectance", RGB(0.5f)),
                                           read_normal_map(ctx));
}

}  // namespace eyetrace
