#include "materials/subsurface_material.h"

#include <algorithm>

#include "core/measured_media.h"
#include "materials/bssrdf_table.h"
#include "materials/bxdf_util.h"
#include "materials/dielectric_bxdf.h"
#include "materials/local_bsdf.h"
#include "materials/roughness.h"
#include "materials/shading_normal.h"
#include "materials/tabulated_bssrdf.h"
#include "scene/spectrum_param.h"
#include "scene/texture_store.h"

namespace eyetrace {

namespace {

// How the medium's coefficients are given: directly (sigma_a, sigma_s), or as a diffuse
// reflectance with a mean free path (mfp) that the table inverts.
struct SubsurfaceMedium {
  const SpectrumTexture* sigma_a = nullptr;
  const SpectrumTexture* sigma_s = nullptr;
  const SpectrumTexture* reflectance = nullptr;
  const SpectrumTexture* mfp = nullptr;
  float scale = 1.f;
};

class SubsurfaceMaterial final : public Material {
 public:
  SubsurfaceMaterial(SubsurfaceMedium medium, float g, float eta, RoughnessParams roughness, ShadingNormal shading)
      : medium_(medium),
        eta_(eta),
        roughness_(roughness),
        shading_(shading),
        table_(compute_beam_diffusion_table(g, eta)) {}

  const BSDF* bsdf(const SurfaceInteraction& hit, SampledWavelengths&, ScratchBuffer& arena) const override {
    const SurfaceInteraction si = shading_.apply(hit);
    return make_local_bsdf(arena, si, DielectricBxDF(eta_, roughness_.distribution(TextureEvalContext(si))), hit.ns);
  }

  bool has_subsurface() const override { return true; }

  const BSSRDF* bssrdf(const SurfaceInteraction& hit, const SampledWavelengths& lambda,
                       ScratchBuffer& arena) const override {
    const SurfaceInteraction si = shading_.apply(hit);
    TextureEvalContext tc(si);
    tc.spectrum_type = SpectrumType::Unbounded;  // coefficients and lengths, not reflectances
    SampledSpectrum sig_a, sig_s;
    if (medium_.sigma_a) {
      sig_a = clamp_non_negative(medium_.scale * medium_.sigma_a->evaluate(tc, lambda), 0.f);
      sig_s = clamp_non_negative(medium_.scale * medium_.sigma_s->evaluate(tc, lambda), 0.f);
    } else {
      const SampledSpectrum mfp = clamp_non_negative(medium_.scale * medium_.mfp->evaluate(tc, lambda), 0.f);
      tc.spectrum_type = SpectrumType::Albedo;
      subsurface_from_diffuse(table_, clamp_unit(medium_.reflectance->evaluate(tc, lambda)), mfp, &sig_a, &sig_s);
      // A zero mean free path (a texture dipping to 0) would make the coefficients infinite:
      // that wavelength gets no subsurface transport instead.
      for (int i = 0; i < kSpectrumSamples; ++i)
        if (!(mfp[i] > 0.f)) sig_a[i] = sig_s[i] = 0.f;
    }
    return arena.alloc<TabulatedBSSRDF>(si.p, si.ns, eta_, sig_a, sig_s, &table_);
  }

 private:
  SubsurfaceMedium medium_;
  float eta_;
  RoughnessParams roughness_;
  ShadingNormal shading_;
  BSSRDFTable table_;
};

// pbrt-v4's coefficients when none are given (its SubsurfaceMaterial::Create), mm^-1.
constexpr RGB kDefaultSigmaA{0.0011f, 0.0024f, 0.014f}, kDefaultSigmaS{2.55f, 3.21f, 3.77f};

const SpectrumTexture* constant_coefficient(const MaterialContext& ctx, const RGB& rgb) {
  return ctx.textures.keep(std::make_unique<ConstantSpectrumTexture>(Spectrum::from_rgb(rgb, SpectrumType::Unbounded)));
}

void warn_ignored(const PluginParams& p, const std::vector<std::string>& names, const std::string& why) {
  for (const std::string& n : names)
    if (p.has(n)) p.warn_param(n, fmt::format("ignored: {}", why));
}

SubsurfaceMedium read_medium(const MaterialContext& ctx, const PluginParams& p, float* g) {
  check_constant_spectrum_sign(ctx.params, "sigma_a", true);
  check_constant_spectrum_sign(ctx.params, "sigma_s", true);
  check_constant_spectrum_sign(ctx.params, "mfp", false);
  SubsurfaceMedium m;
  m.scale = p.get_float("scale");
  if (p.has("name")) {
    const MeasuredMedium* mm = find_measured_medium(p.get_string("name"));
    if (!mm) p.fail("name", fmt::format("no measured medium \"{}\"", p.get_string("name")));
    warn_ignored(p, {"sigma_a", "sigma_s", "reflectance", "mfp"}, "the named medium's coefficients apply");
    // The measured data are reduced scattering coefficients: isotropic scattering (pbrt-v4).
    if (*g != 0.f) p.warn_param("g", "ignored with a named medium (its data are reduced coefficients: g = 0)");
    *g = 0.f;
    m.sigma_a = constant_coefficient(ctx, mm->sigma_a);
    m.sigma_s = constant_coefficient(ctx, mm->sigma_prime_s);
    return m;
  }
  if (p.has("sigma_a") != p.has("sigma_s"))
    p.fail(p.has("sigma_a") ? "sigma_a" : "sigma_s", "\"sigma_a\" and \"sigma_s\" must be given together");
  if (p.has("sigma_a")) {
    warn_ignored(p, {"reflectance", "mfp"}, "\"sigma_a\" and \"sigma_s\" apply");
    m.sigma_a = ctx.textures.spectrum_param(p, "sigma_a", SpectrumType::Unbounded);
    m.sigma_s = ctx.textures.spectrum_param(p, "sigma_s", SpectrumType::Unbounded);
    return m;
  }
  if (p.has("reflectance")) {
    m.reflectance = ctx.textures.spectrum_param(p, "reflectance", SpectrumType::Albedo);
    m.mfp = ctx.textures.spectrum_param(p, "mfp", SpectrumType::Unbounded);
    return m;
  }
  warn_ignored(p, {"mfp"}, "\"mfp\" goes with \"reflectance\"");
  m.sigma_a = constant_coefficient(ctx, kDefaultSigmaA);
  m.sigma_s = constant_coefficient(ctx, kDefaultSigmaS);
  return m;
}

}  // namespace

const PluginSpec& subsurface_material_spec() {
  static const PluginSpec spec{
      "Material",
      "a dielectric boundary over a scattering medium: photon beam diffusion BSSRDF (pbrt-v4's TabulatedBSSRDF)",
      "Rendered by `path` and `volpath` as pbrt-v4's `volpath` does. Inside a `mix`, exit points are the hits on the "
      "mix's surfaces (pbrt-v4 resolves the mix at each hit). Coefficients are per scene unit, as in pbrt-v4 (the "
      "named "
      "data are in mm^-1: use \"scale\").",
      std::vector<ParamSpec>{
          param::string("name")
              .in(measured_medium_names())
              .describe("measured medium (Jensen et al. 2001, Narasimhan et al. 2006); sets g = 0"),
          param::spectrum_texture("sigma_a").describe("absorption coefficient (with sigma_s)"),
          param::spectrum_texture("sigma_s").describe("scattering coefficient (with sigma_a)"),
          param::spectrum_texture("reflectance").describe("diffuse reflectance the medium should have (with mfp)"),
          param::spectrum_texture("mfp", 1).describe("mean free path 1 / sigma_t, with reflectance"),
          param::real("scale", 1).above(0).describe("multiplies sigma_a and sigma_s (or mfp)"),
          param::real("eta", 1.33).above(0).describe("index of refraction of the boundary"),
          param::real("g", 0).open_range(-1, 1).describe("Henyey-Greenstein asymmetry of the medium")} +
          RoughnessParams::declared() + ShadingNormal::declared()};
  return spec;
}

std::unique_ptr<Material> create_subsurface_material(const MaterialContext& ctx) {
  const PluginParams p(ctx.params, subsurface_material_spec(), "subsurface");
  float g = p.get_float("g");
  const SubsurfaceMedium medium = read_medium(ctx, p, &g);
  return std::make_unique<SubsurfaceMaterial>(medium, g, p.get_float("eta"), RoughnessParams::read(ctx, p),
                                              ShadingNormal::read(ctx, p));
}

}  // namespace eyetrace
