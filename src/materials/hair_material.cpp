#include "materials/hair_material.h"

#include <algorithm>
#include <cmath>

#include "materials/bxdf_util.h"
#include "materials/hair_bxdf.h"
#include "materials/local_bsdf.h"
#include "scene/texture_store.h"

namespace eyetrace {

namespace {

// A texture may give any value where a scene constant is range-checked: a non-finite one
// becomes the default, an out-of-range one the nearest allowed.
float finite_or(float x, float fallback) { return std::isfinite(x) ? x : fallback; }

class HairMaterial final : public Material {
 public:
  struct Inputs {
    const SpectrumTexture* sigma_a = nullptr;      // absorption per unit radius, or
    const SpectrumTexture* reflectance = nullptr;  // the colour it is fitted to, or
    const FloatTexture* eumelanin = nullptr;       // the melanins (either may be null)
    const FloatTexture* pheomelanin = nullptr;
    const FloatTexture *eta, *beta_m, *beta_n, *alpha;
  };
  explicit HairMaterial(Inputs in) : in_(in) {}

  const BSDF* bsdf(const SurfaceInteraction& si, SampledWavelengths& lambda, ScratchBuffer& arena) const override {
    TextureEvalContext tc(si);
    // pbrt-v4 clamps the roughnesses to [0.01, 1]; an index must stay positive.
    const float beta_m = std::clamp(finite_or(in_.beta_m->evaluate(tc), 0.3f), 0.01f, 1.f);
    const float beta_n = std::clamp(finite_or(in_.beta_n->evaluate(tc), 0.3f), 0.01f, 1.f);
    const float eta = std::max(finite_or(in_.eta->evaluate(tc), 1.55f), 1e-3f);
    const float alpha = finite_or(in_.alpha->evaluate(tc), 0.f);
    const SampledSpectrum sigma_a = absorption(tc, lambda, beta_n);
    const float h = -1.f + 2.f * si.uv.y;  // v across the fibre: its edges are h = -1 and 1
    return make_local_bsdf(arena, si, HairBxDF(h, eta, sigma_a, beta_m, beta_n, alpha));
  }

 private:
  SampledSpectrum absorption(TextureEvalContext tc, const SampledWavelengths& lambda, float beta_n) const {
    if (in_.sigma_a) {
      tc.spectrum_type = SpectrumType::Unbounded;  // a coefficient, not a reflectance
      return clamp_non_negative(in_.sigma_a->evaluate(tc, lambda), 0.f);
    }
    if (in_.reflectance)
      return HairBxDF::sigma_a_from_reflectance(clamp_unit(in_.reflectance->evaluate(tc, lambda)), beta_n);
    auto concentration = [&](const FloatTexture* t) {
      return t ? std::max(0.f, finite_or(t->evaluate(tc), 0.f)) : 0.f;
    };
    const RGB rgb = HairBxDF::sigma_a_from_concentration(concentration(in_.eumelanin), concentration(in_.pheomelanin));
    return Spectrum::from_rgb(rgb, SpectrumType::Unbounded).sample(lambda);
  }

  Inputs in_;
};

// pbrt-v4's precedence: sigma_a, then reflectance, then the melanins; what is overridden is
// read (a texture it names must exist) and warned about, as pbrt-v4 warns.
void warn_overridden(const PluginParams& p) {
  const std::string reflectance = p.has("color") ? "color" : "reflectance";
  const std::string winner = p.has("sigma_a") ? "sigma_a" : p.has(reflectance) ? reflectance : "";
  if (winner.empty()) return;
  for (const std::string& name : {reflectance, std::string("eumelanin"), std::string("pheomelanin")})
    if (name != winner && p.has(name)) p.warn_param(name, fmt::format("ignored, since \"{}\" is given", winner));
}

}  // namespace

const PluginSpec& hair_material_spec() {
  static const PluginSpec spec{
      "Material",
      "a hair fibre: Chiang et al. 2016's BSDF, the fibre along dpdu and h = 2v - 1 across it",
      "M_p's ln I0 for arguments over 12 is its asymptotic series to 1/x^3, where pbrt-v4 halves the 1/(8x) term (up "
      "to "
      "0.5 % lower, docs/scene-format.md). As in pbrt-v4: no bump or normal map, and `color` is read as `reflectance`.",
      {param::spectrum_texture("sigma_a")
           .with_unit("1/radius")
           .describe("absorption coefficient inside the fibre (unbounded); overrides the others"),
       param::spectrum_texture("reflectance")
           .describe("colour of the hair, turned into sigma_a by Chiang et al.'s fit; overrides the melanins"),
       param::spectrum_texture("color").describe("pbrt-v4's older name of `reflectance` (not with it)"),
       param::float_texture("eumelanin")
           .at_least(0)
           .shown_default("1.3 when nothing else is given")
           .describe("concentration of the brown-black pigment"),
       param::float_texture("pheomelanin", 0).at_least(0).describe("concentration of the red-yellow pigment"),
       param::float_texture("eta", 1.55).above(0).describe("index of refraction of the fibre"),
       param::float_texture("beta_m", 0.3).at_least(0).describe("longitudinal roughness (clamped to [0.01, 1])"),
       param::float_texture("beta_n", 0.3).at_least(0).describe("azimuthal roughness (clamped to [0.01, 1])"),
       param::float_texture("alpha", 2).with_unit("deg").describe("tilt of the cuticle's scales")}};
  return spec;
}

std::unique_ptr<Material> create_hair_material(const MaterialContext& ctx) {
  const PluginParams p(ctx.params, hair_material_spec(), "hair");
  if (p.has("reflectance") && p.has("color"))
    p.fail("color", "give either \"reflectance\" or its older name \"color\", not both");
  HairMaterial::Inputs in;
  in.sigma_a = ctx.textures.spectrum_param(p, "sigma_a", SpectrumType::Unbounded);
  in.reflectance = ctx.textures.spectrum_param(p, p.has("color") ? "color" : "reflectance");
  in.eumelanin = ctx.textures.float_param(p, "eumelanin");
  in.pheomelanin = p.has("pheomelanin") ? ctx.textures.float_param(p, "pheomelanin") : nullptr;
  in.eta = ctx.textures.float_param(p, "eta");
  in.beta_m = ctx.textures.float_param(p, "beta_m");
  in.beta_n = ctx.textures.float_param(p, "beta_n");
  in.alpha = ctx.textures.float_param(p, "alpha");
  warn_overridden(p);
  if (in.sigma_a) {
    in.reflectance = nullptr;
    in.eumelanin = in.pheomelanin = nullptr;
  } else if (in.reflectance) {
    in.eumelanin = in.pheomelanin = nullptr;
  } else if (!in.eumelanin && !in.pheomelanin) {
    // pbrt-v4's default, brown hair: the sigma_a of eumelanin 1.3.
    const RGB brown = HairBxDF::sigma_a_from_concentration(1.3f, 0.f);
    in.sigma_a = ctx.textures.keep(
        std::make_unique<ConstantSpectrumTexture>(Spectrum::from_rgb(brown, SpectrumType::Unbounded)));
  }
  return std::make_unique<HairMaterial>(in);
}

}  // namespace eyetrace
