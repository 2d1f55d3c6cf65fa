#include "media/homogeneous_medium.h"

#include <cmath>

#include "lights/light_params.h"
#include "media/medium_params.h"

namespace eyetrace {

HomogeneousMedium::HomogeneousMedium(Spectrum sigma_a, Spectrum sigma_s, Spectrum Le, float g)
    : sigma_a_(std::move(sigma_a)), sigma_s_(std::move(sigma_s)), Le_(std::move(Le)), g_(g) {
  emissive_ = false;
  for (float l = kLambdaMin; l <= kLambdaMax; l += 1.f) emissive_ = emissive_ || Le_(l) > 0.f;
}

MediumProperties HomogeneousMedium::properties(const Vec3&, const SampledWavelengths& lambda) const {
  return MediumProperties{sigma_a_.sample(lambda), sigma_s_.sample(lambda), Le_.sample(lambda), g_};
}

MajorantIterator HomogeneousMedium::majorants(const Ray&, float t_max, const SampledWavelengths& lambda) const {
  return MajorantIterator(0.f, t_max, sigma_a_.sample(lambda) + sigma_s_.sample(lambda));
}

const PluginSpec& homogeneous_medium_spec() {
  static const PluginSpec spec{
      "MakeNamedMedium",
      "the same absorption, scattering (Henyey-Greenstein) and emission everywhere",
      "`preset` (pbrt-v4's measured scattering data) is not built in: it is an error.",
      {param::spectrum("sigma_a", 1).describe("absorption coefficient, per unit length"),
       param::spectrum("sigma_s", 1).describe("scattering coefficient, per unit length"),
       param::real("scale", 1).at_least(0).describe("multiplies `sigma_a` and `sigma_s`"),
       param::real("g", 0).describe("Henyey-Greenstein asymmetry, in (-1, 1): > 0 scatters forwards"),
       param::spectrum("Le", 0).describe("emitted radiance (illuminant spectrum), per unit of `sigma_a`"),
       param::real("Lescale", 1).at_least(0).describe("multiplies `Le`"),
       param::string("preset").describe("pbrt-v4's named measured media: not built in (an error)")}};
  return spec;
}

std::unique_ptr<Medium> create_homogeneous_medium(const MediumContext& ctx) {
  const PluginParams p(ctx.params, homogeneous_medium_spec(), "homogeneous");
  if (p.has("preset"))
    p.fail("preset", fmt::format("\"{}\": pbrt-v4's measured media presets are not built into eyetrace; give "
                                 "\"sigma_a\" and \"sigma_s\" instead",
                                 p.get_string("preset")));
  const float scale = p.get_float("scale");
  const float g = asymmetry_param(p);
  const Spectrum sigma_a = coefficient_param(p, "sigma_a").scaled(scale);
  const Spectrum sigma_s = coefficient_param(p, "sigma_s").scaled(scale);
  // pbrt-v4 reads Le as a light's emission (the colour space's illuminant for RGB, luminance
  // normalised for spectra), exactly as an area light's "L".
  std::optional<Spectrum> Le = emission_param_or_null(p, "Le");
  const Spectrum emission = Le ? Le->scaled(p.get_float("Lescale")) : Spectrum();
  return std::make_unique<HomogeneousMedium>(sigma_a, sigma_s, emission, g);
}

}  // namespace eyetrace
