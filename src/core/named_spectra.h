// The named spectra of pbrt-v4 scenes ("metal-Cu-eta", "glass-BK7", "stdillum-D65", ...), all
// of pbrt-v4's, as functions of wavelength in nm.
#pragma once
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace eyetrace {

enum class NamedSpectrumKind {
  Metal,       // conductor eta or k: projected to RGB like a reflectance
  Glass,       // dielectric index: used at 550 nm only (the renderer is not dispersive)
  Illuminant,  // emission: normalised to luminance 1
  Sensor,      // a camera's spectral response (pbrt-v4's canon_*, nikon_*, sony_*, ...): as given
};

struct NamedSpectrum {
  std::string_view name;
  NamedSpectrumKind kind;
  std::span<const float> interleaved;  // (lambda nm, value) pairs; empty if `analytic` is set
  float (*analytic)(float lambda_nm) = nullptr;
};

const NamedSpectrum* find_named_spectrum(std::string_view name);  // null if unknown
std::vector<std::string> named_spectrum_names();
// Value at a wavelength; piecewise linear in the table, clamped to its end values.
float evaluate_named_spectrum(const NamedSpectrum& s, float lambda_nm);

}  // namespace eyetrace
