#include "materials/mix_material.h"

#include <cstdint>

#include "core/fnv1a.h"
#include "samplers/hash.h"
#include "scene/texture_store.h"

namespace eyetrace {

namespace {

class MixMaterial final : public Material {
 public:
  MixMaterial(const Material* a, const Material* b, const FloatTexture* amount, uint64_t seed)
      : a_(a),
        b_(b),
        amount_(amount),
        seed_(seed),
        subsurface_((a && a->has_subsurface()) || (b && b->has_subsurface())) {}

  const BSDF* bsdf(const SurfaceInteraction& si, SampledWavelengths& lambda, ScratchBuffer& arena) const override {
    const Material* m = choose(si);
    // An "interface" component is a null material: the ray continues, as through an interface.
    return m ? m->bsdf(si, lambda, arena) : nullptr;
  }
  bool has_subsurface() const override { return subsurface_; }
  // The same choice as bsdf() at this hit: the component whose boundary the path crossed.
  const BSSRDF* bssrdf(const SurfaceInteraction& si, const SampledWavelengths& lambda,
                       ScratchBuffer& arena) const override {
    const Material* m = choose(si);
    return m ? m->bssrdf(si, lambda, arena) : nullptr;
  }

 private:
  const Material* choose(const SurfaceInteraction& si) const {
    const float amount = amount_->evaluate(TextureEvalContext(si));
    if (!(amount > 0.f)) return a_;  // also a NaN amount: the first, as pbrt-v4's comparisons give
    if (amount >= 1.f) return b_;
    return amount < mix_material_hash(si.p, si.wo, seed_) ? a_ : b_;
  }
  const Material* a_;
  const Material* b_;
  const FloatTexture* amount_;
  uint64_t seed_;
  bool subsurface_;
};

}  // namespace

float mix_material_hash(const Vec3& p, const Vec3& wo, uint64_t seed) {
  return hash_float(p.x, p.y, p.z, wo.x, wo.y, wo.z, seed);
}

const PluginSpec& mix_material_spec() {
  static const PluginSpec spec{
      "Material",
      "one of two named materials per hit, the second with probability amount",
      "The choice hashes the hit point, the direction and the two materials' names (pbrt-v4: their addresses), so "
      "it is the same in every run.",
      {param::strings("materials").size(2).describe("two MakeNamedMaterial names"),
       param::float_texture("amount", 0.5).describe("probability of the second")}};
  return spec;
}

std::unique_ptr<Material> create_mix_material(const MaterialContext& ctx) {
  const PluginParams p(ctx.params, mix_material_spec(), "mix");
  const Param* names = ctx.params.find("materials");
  if (!names) p.fail("materials", "the mix material needs \"string materials\" [\"a\" \"b\"]: two named materials");
  if (!ctx.named_material) p.fail("materials", "no named materials are available here");
  const Material* a = ctx.named_material(names->strings[0]);
  const Material* b = ctx.named_material(names->strings[1]);
  // Seeded by the two names: a mix nested in a mix then chooses independently of it (the same
  // hash would tie the two choices together), and the seed is the same in every run.
  const uint64_t seed = fnv1a(names->strings[1], fnv1a(names->strings[0] + '\0'));
  return std::make_unique<MixMaterial>(a, b, ctx.textures.float_param(p, "amount"), seed);
}

}  // namespace eyetrace
