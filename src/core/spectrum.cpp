// Spectra to RGB; see core/spectrum.h for the two conversions and why.
#include "core/spectrum.h"

#include <cmath>
#include <vector>

namespace eyetrace {

namespace {

SpectrumSamples sample_named(const NamedSpectrum& n) {
  SpectrumSamples s{};
  for (int i = 0; i < kCieRows; ++i) s[i] = evaluate_named_spectrum(n, cie_table()[i].lambda_nm);
  return s;
}

// Planck's law; constants as pbrt-v4 uses them (CODATA 2010).
double planck(double lambda_nm, double kelvin) {
  const double c = 299792458.0, h = 6.62606957e-34, kb = 1.3806488e-23;
  double l = lambda_nm * 1e-9;
  return (2.0 * h * c * c) / (std::pow(l, 5.0) * (std::exp((h * c) / (l * kb * kelvin)) - 1.0));
}

// The renderer's white: XYZ -> RGB of D65 itself, per channel, to divide out.
RGB d65_white_rgb() {
  static const RGB white = [] {
    SpectrumSamples d{};
    for (int i = 0; i < kCieRows; ++i) d[i] = cie_table()[i].d65;
    return xyz_to_linear_srgb(spectrum_to_xyz(d));
  }();
  return white;
}

}  // namespace

float interpolate_spectrum(std::span<const float> lambda, std::span<const float> value, float l) {
  size_t n = std::min(lambda.size(), value.size());
  if (n == 0) return 0.f;
  if (l <= lambda[0]) return value[0];
  if (l >= lambda[n - 1]) return value[n - 1];
  size_t j = 0;
  while (lambda[j + 1] < l) ++j;
  float t = (l - lambda[j]) / (lambda[j + 1] - lambda[j]);
  return (1.f - t) * value[j] + t * value[j + 1];
}

RGB named_spectrum_to_rgb(const NamedSpectrum& n) {
  switch (n.kind) {
    case NamedSpectrumKind::Glass: return RGB(evaluate_named_spectrum(n, 550.f));
    case NamedSpectrumKind::Metal: return reflectance_spectrum_to_rgb(sample_named(n));
    case NamedSpectrumKind::Illuminant: return emission_spectrum_to_rgb(sample_named(n));
  }
  return RGB(0.f);
}

SpectrumSamples sample_spectrum(std::span<const float> lambda_nm, std::span<const float> values) {
  SpectrumSamples s{};
  for (int i = 0; i < kCieRows; ++i) s[i] = interpolate_spectrum(lambda_nm, values, cie_table()[i].lambda_nm);
  return s;
}

RGB xyz_to_linear_srgb(const Vec3& xyz) {
  // Lindbloom's matrix, derived from the sRGB primaries and the D65 white (0.3127, 0.3290).
  return RGB(3.2404542f * xyz.x - 1.5371385f * xyz.y - 0.4985314f * xyz.z,
             -0.9692660f * xyz.x + 1.8760108f * xyz.y + 0.0415560f * xyz.z,
             0.0556434f * xyz.x - 0.2040259f * xyz.y + 1.0572252f * xyz.z);
}

Vec3 spectrum_to_xyz(const SpectrumSamples& s) {
  // Riemann sums at 5 nm; dividing by the sum of y-bar makes the step size cancel.
  double x = 0, y = 0, z = 0, y_sum = 0;
  const auto& t = cie_table();
  for (int i = 0; i < kCieRows; ++i) {
    x += double(t[i].x) * s[i];
    y += double(t[i].y) * s[i];
    z += double(t[i].z) * s[i];
    y_sum += t[i].y;
  }
  return Vec3(float(x / y_sum), float(y / y_sum), float(z / y_sum));
}

RGB reflectance_spectrum_to_rgb(const SpectrumSamples& s) {
  SpectrumSamples lit{};
  for (int i = 0; i < kCieRows; ++i) lit[i] = s[i] * cie_table()[i].d65;
  return xyz_to_linear_srgb(spectrum_to_xyz(lit)) / d65_white_rgb();
}

RGB emission_spectrum_to_rgb(const SpectrumSamples& s) {
  Vec3 xyz = spectrum_to_xyz(s);
  if (!(xyz.y > 0.f)) return RGB(0.f);
  return xyz_to_linear_srgb(xyz / xyz.y);
}

RGB blackbody_to_rgb(float kelvin) {
  // Relative to the value at 555 nm so that cold bodies stay inside float range; the result
  // is normalised to luminance 1 anyway (pbrt-v4 normalises to the peak, then to 1 nit).
  SpectrumSamples s{};
  double ref = planck(555.0, kelvin);
  for (int i = 0; i < kCieRows; ++i) s[i] = float(planck(cie_table()[i].lambda_nm, kelvin) / ref);
  return emission_spectrum_to_rgb(s);
}

}  // namespace eyetrace
