#include "media/homogeneous_medium.h"

#include <cmath>

#include "core/measured_media.h"
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
      "`preset` names pbrt-v4's measured media (Jensen et al. 2001, Narasimhan et al. 2006), in mm^-1 as pbrt-v4 "
      "has them; an unknown name is an error (pbrt-v4 warns and uses the defaults).",
      {param::spectrum("sigma_a", 1).describe("absorption coefficient, per unit length"),
       param::spectrum("sigma_s", 1).describe("scattering coefficient, per unit length"),
       param::real("scale", 1).at_least(0).describe("multiplies `sigma_a` and `sigma_s`"),
       param::real("g", 0).describe("Henyey-Greenstein asymmetry, in (-1, 1): > 0 scatters forwards"),
       param::spectrum("Le", 0).describe("emitted radiance (illuminant spectrum), per unit of `sigma_a`"),
       param::real("Lescale", 1).at_least(0).describe("multiplies `Le`"),
       param::string("preset").describe(
           "a named measured medium (\"Skin1\", \"Ketchup\", ...): its `sigma_a` and reduced scattering "
           "coefficient as `sigma_s`, in place of those parameters")}};
  return spec;
}

std::unique_ptr<Medium> create_homogeneous_medium(const MediumContext& ctx) {
  const PluginParams p(ctx.params, homogeneous_medium_spec(), "homogeneous");
  const float scale = p.get_float("scale");
  const float g = asymmetry_param(p);
  Spectrum sigma_a = coefficient_param(p, "sigma_a"), sigma_s = coefficient_param(p, "sigma_s");
  if (p.has("preset")) {
    const std::string name = p.get_string("preset");
    const MeasuredMedium* mm = find_measured_medium(name);
    if (!mm) {
      const std::string hint = closest_match(name, measured_medium_names());
      p.fail("preset", fmt::format("no measured medium \"{}\"{}", name,
                                   hint.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", hint)));
    }
    for (const char* given : {"sigma_a", "sigma_s"})
      if (p.has(given)) p.warn_param(given, "ignored: the preset's coefficients apply (as in pbrt-v4)");
    // pbrt-v4 takes the reduced scattering coefficient as sigma_s and keeps "g" as given.
    sigma_a = Spectrum::from_rgb(mm->sigma_a, SpectrumType::Unbounded);
    sigma_s = Spectrum::from_rgb(mm->sigma_prime_s, SpectrumType::Unbounded);
  }
  sigma_a = sigma_a.scaled(scale);
  sigma_s = sigma_s.scaled(scale);
  // pbrt-v4 reads Le as a light's emission (the colour space's illuminant for RGB, luminance
  // normalised for spectra), exactly as an area light's "L".
  std::optional<Spectrum> Le = emission_param_or_null(p, "Le");
  const Spectrum emission = Le ? Le->scaled(p.get_float("Lescale")) : Spectrum();
  return std::make_unique<HomogeneousMedium>(sigma_a, sigma_s, emission, g);
}

}  // namespace eyetrace
