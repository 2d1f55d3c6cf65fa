// Parameter conventions every light shares (pbrt-v4 semantics): an emission spectrum
// (core/spectrum.h, SpectrumType::Illuminant) defaulting to white, a non-negative "scale", and the photometric
// normalisations "power" / "illuminance", which rescale the emission so that the luminance
// of the emitted quantity equals the value given, "scale" then multiplying on top (pbrt-v4:
// a scene with "scale" 2 and "power" 100 emits 200). Declared here once, for every light's table.
#pragma once
#include <optional>
#include <string>

#include "scene/param_spec.h"

namespace eyetrace {

// An emission spectrum, default white (the colour space's illuminant, as pbrt-v4 defaults).
ParamSpec emission_param_spec(const std::string& name, const std::string& doc);
ParamSpec scale_param_spec();
// A photometric target ("power", "illuminance"), > 0 when given.
ParamSpec photometric_param_spec(const std::string& name, const std::string& doc);

// The emission; negative values are errors naming the parameter.
Spectrum emission_param(const PluginParams& params, const std::string& name);
// The same, nullopt when absent (for lights where "L" competes with an image).
std::optional<Spectrum> emission_param_or_null(const PluginParams& params, const std::string& name);
float scale_param(const PluginParams& params);
// nullopt when absent.
std::optional<float> photometric_param(const PluginParams& params, const std::string& name);
// The factor that makes `emitted_luminance` (> 0) equal `target`; 1 when there is no
// target, or when nothing is emitted (a black light cannot be normalised: stays black).
float photometric_factor(std::optional<float> target, float emitted_luminance);

// Mean of the channels: the scalar "power" the light sampler weighs lights by (pbrt-v4
// averages Phi over the sampled wavelengths; a blue light still gets shadow rays).
inline float channel_mean(const RGB& c) { return (c.r + c.g + c.b) / 3.f; }
inline float channel_mean(const Spectrum& s) { return channel_mean(s.to_rgb(SpectrumType::Illuminant)); }
// An emission at the sample's wavelengths from an RGB (image texels).
inline SampledSpectrum rgb_emission(const RGB& c, const SampledWavelengths& lambda) {
  return Spectrum::from_rgb(c, SpectrumType::Illuminant).sample(lambda);
}

}  // namespace eyetrace
