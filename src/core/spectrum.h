// Spectra: what a scene's colours and spectral parameters become (Spectrum, a function of
// wavelength), and the colorimetry that turns sampled radiance back into colour (CIE 1931
// XYZ, then linear sRGB: Rec.709 primaries, D65 white).
//
// An RGB value means different things by use (pbrt-v4's SpectrumType):
//  - Albedo: a reflectance in [0, 1]: Jakob & Hanika's smooth bounded spectrum
//    (core/rgb_to_spectrum.h), which under the colour space's white renders as that RGB;
//  - Unbounded: any non-negative value (conductor eta and k): the same shape scaled;
//  - Illuminant: an emission: the unbounded spectrum times the colour space's white (D65)
//    normalised to luminance 1, so "rgb L [1 1 1]" emits D65 of luminance 1.
// Emission given as a spectrum (blackbody, named illuminants, [lambda value] pairs) is
// normalised to luminance 1, as pbrt-v4 normalises lights to 1 nit times "scale"; a constant
// c used as an emission is c times the normalised white, like "rgb L [c c c]".
#pragma once
#include <array>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "core/cie_tables.h"
#include "core/math.h"
#include "core/named_spectra.h"
#include "core/rgb_to_spectrum.h"
#include "core/sampled_spectrum.h"

namespace eyetrace {

enum class SpectrumType { Albedo, Unbounded, Illuminant };

class Spectrum {
 public:
  Spectrum() = default;  // zero everywhere
  static Spectrum constant(float c);
  // `rgb` must be in [0, 1] for Albedo (callers clamp or reject) and non-negative otherwise.
  static Spectrum from_rgb(const RGB& rgb, SpectrumType type);
  // Piecewise linear through (lambda, value), constant beyond the ends; Illuminant: luminance 1.
  static Spectrum tabulated(std::vector<float> lambda_nm, std::vector<float> values, SpectrumType type);
  static Spectrum blackbody(float kelvin);  // luminance 1
  static Spectrum named(const NamedSpectrum& n, SpectrumType type);

  float operator()(float lambda_nm) const { return scale_ * shape(lambda_nm); }
  SampledSpectrum sample(const SampledWavelengths& lambda) const {
    SampledSpectrum s;
    for (int i = 0; i < kSpectrumSamples; ++i) s[i] = (*this)(lambda[i]);
    return s;
  }
  Spectrum scaled(float s) const {
    Spectrum r = *this;
    r.scale_ *= s;
    return r;
  }
  // The spectrum's colour: Albedo/Unbounded as a reflectance seen under the white (a constant c
  // gives (c, c, c)), Illuminant as the emitted colour (luminance = its Y).
  RGB to_rgb(SpectrumType type) const;
  float luminance() const;  // Y of the spectrum as an emission (the film's Y)

 private:
  enum class Kind { Zero, Constant, Sigmoid, SigmoidTimesWhite, Table, Blackbody };
  float shape(float lambda_nm) const;
  Kind kind_ = Kind::Zero;
  float scale_ = 1.f;
  SigmoidPolynomial poly_;
  float kelvin_ = 0.f;
  std::shared_ptr<const std::vector<float>> lambda_, values_;
};

// A spectral parameter as the scene gave it, until its use is known.
struct SpectrumValue {
  std::optional<RGB> rgb;  // "rgb" values, and constant spectra c as (c, c, c)
  Spectrum spectrum;       // otherwise: pairs, a named spectrum or a blackbody

  Spectrum as(SpectrumType type) const { return rgb ? Spectrum::from_rgb(*rgb, type) : spectrum; }
  // The colour it stands for: the RGB itself, or the spectrum's (core/spectrum.h: to_rgb).
  RGB to_rgb(SpectrumType type) const { return rgb ? *rgb : spectrum.to_rgb(type); }
};

// --- Colorimetry ---------------------------------------------------------------------------
// CIE 1931 colour matching functions, linear between the table's 5 nm rows, 0 outside them.
Vec3 cie_xyz_bar(float lambda_nm);
// The integral of the interpolated y-bar over wavelength (nm): Y of the constant spectrum 1.
float cie_y_integral();
// What sampled_to_xyz gives the constant spectrum 1 in expectation, exactly: the integrals of the
// interpolated x-bar, y-bar and z-bar over that of y-bar (Y = 1).
Vec3 equal_energy_xyz();
// The colour space's white (D65) as an emission of luminance 1, at lambda.
float white_illuminant(float lambda_nm);
// Monte Carlo estimate of XYZ (luminance scale: the constant spectrum 1 has Y = 1) from
// radiance at sampled wavelengths; terminated wavelengths (pdf 0) count for nothing.
Vec3 sampled_to_xyz(const SampledSpectrum& L, const SampledWavelengths& lambda);
// CIE 1931 XYZ to linear sRGB, scaled per channel so that the white illuminant above gives
// exactly (1, 1, 1) (its 5 nm tabulation sits 1e-4 off the nominal D65 white point).
RGB xyz_to_linear_srgb(const Vec3& xyz);
RGB sampled_to_rgb(const SampledSpectrum& L, const SampledWavelengths& lambda);
// sampled_to_rgb of a spectrum that is `value_over_pdf` times the density at one of a sample's
// wavelengths and 0 at the others, within float rounding: from a table of the CIE rows taken to
// linear sRGB once, scale and white folded in (a dispersive eye's splats form one colour per
// wavelength).
RGB wavelength_to_rgb(float lambda_nm, float value_over_pdf);

// A spectrum sampled at the CIE table's wavelengths (380..780 nm every 5 nm), for exact sums.
using SpectrumSamples = std::array<float, kCieRows>;
// XYZ of an emission spectrum, scaled so that the equal-energy spectrum 1 has Y = 1.
Vec3 spectrum_to_xyz(const SpectrumSamples& s);
// Piecewise linear through (lambda, value) points, constant beyond the ends; lambda_nm must
// increase (binary search).
float interpolate_spectrum(std::span<const float> lambda_nm, std::span<const float> values, float l_nm);
// Planck's law (W sr^-1 m^-3), for blackbody emitters.
double planck(double lambda_nm, double kelvin);

}  // namespace eyetrace
