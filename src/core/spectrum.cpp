// Spectra and colorimetry; see core/spectrum.h for the conventions and why.
#include "core/spectrum.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace eyetrace {

namespace {

const CieRow& row(int i) { return cie_table()[i]; }

// D65 divided by its luminance (core/cie_tables.h).
const SpectrumSamples& white_samples() { return kCieWhite; }

// The CIE rows i, i + 1 around lambda and the fraction t between them; false outside
// [380, 780] nm (every table sampled at the rows is 0 there).
bool cie_segment(float lambda, int* i, float* t) {
  const float x = (lambda - kCieLambdaMin) / kCieLambdaStep;
  if (!(x >= 0.f && x <= float(kCieRows - 1))) return false;
  *i = std::min(int(x), kCieRows - 2);
  *t = x - float(*i);
  return true;
}

// Linear interpolation in a table sampled at the CIE rows; 0 outside [380, 780] nm.
float cie_interpolate(const SpectrumSamples& s, float lambda) {
  int i;
  float t;
  if (!cie_segment(lambda, &i, &t)) return 0.f;
  return (1.f - t) * s[i] + t * s[i + 1];
}

SpectrumSamples samples_of(const Spectrum& s) {
  SpectrumSamples out{};
  for (int i = 0; i < kCieRows; ++i) out[i] = s(row(i).lambda_nm);
  return out;
}

}  // namespace

// --- Spectrum ------------------------------------------------------------------------------

Spectrum Spectrum::constant(float c) {
  Spectrum s;
  s.kind_ = Kind::Constant;
  s.scale_ = c;
  return s;
}

Spectrum Spectrum::from_rgb(const RGB& rgb, SpectrumType type) {
  Spectrum s;
  if (type == SpectrumType::Albedo) {
    s.kind_ = Kind::Sigmoid;
    s.poly_ = RGBToSpectrumTable::srgb()(glm::clamp(rgb, RGB(0.f), RGB(1.f)));
    return s;
  }
  // Unbounded: the bounded spectrum of rgb / (2 max) scaled by 2 max, so that the sigmoid
  // stays away from its flat ends where a large value would force a box-like spectrum.
  const float m = std::max({rgb.r, rgb.g, rgb.b, 0.f});
  s.kind_ = type == SpectrumType::Illuminant ? Kind::SigmoidTimesWhite : Kind::Sigmoid;
  if (m <= 0.f) {
    s.kind_ = Kind::Zero;
    return s;
  }
  s.scale_ = 2.f * m;
  s.poly_ = RGBToSpectrumTable::srgb()(glm::max(rgb, RGB(0.f)) / s.scale_);
  return s;
}

Spectrum Spectrum::tabulated(std::vector<float> lambda_nm, std::vector<float> values, SpectrumType type) {
  Spectrum s;
  s.kind_ = Kind::Table;
  s.lambda_ = std::make_shared<const std::vector<float>>(std::move(lambda_nm));
  s.values_ = std::make_shared<const std::vector<float>>(std::move(values));
  if (type == SpectrumType::Illuminant) {
    const float y = s.luminance();
    s.scale_ = y > 0.f ? 1.f / y : 0.f;
  }
  return s;
}

Spectrum Spectrum::blackbody(float kelvin) {
  Spectrum s;
  s.kind_ = Kind::Blackbody;
  s.kelvin_ = kelvin;
  const float y = s.luminance();
  s.scale_ = y > 0.f ? 1.f / y : 0.f;
  return s;
}

Spectrum Spectrum::named(const NamedSpectrum& n, SpectrumType type) {
  std::vector<float> lambda, values;
  if (n.analytic) {
    for (int i = 0; i < kCieRows; ++i) {
      lambda.push_back(row(i).lambda_nm);
      values.push_back(n.analytic(row(i).lambda_nm));
    }
  } else {
    for (size_t i = 0; i + 1 < n.interleaved.size(); i += 2) {
      lambda.push_back(n.interleaved[i]);
      values.push_back(n.interleaved[i + 1]);
    }
  }
  return tabulated(std::move(lambda), std::move(values),
                   n.kind == NamedSpectrumKind::Illuminant ? SpectrumType::Illuminant : type);
}

float Spectrum::shape(float lambda) const {
  switch (kind_) {
    case Kind::Zero: return 0.f;
    case Kind::Constant: return 1.f;
    case Kind::Sigmoid: return poly_(lambda);
    case Kind::SigmoidTimesWhite: return poly_(lambda) * white_illuminant(lambda);
    case Kind::Table: return interpolate_spectrum(*lambda_, *values_, lambda);
    case Kind::Blackbody: return float(planck(lambda, kelvin_) / planck(555.0, kelvin_));
  }
  return 0.f;
}

float Spectrum::luminance() const { return spectrum_to_xyz(samples_of(*this)).y; }

RGB Spectrum::to_rgb(SpectrumType type) const {
  SpectrumSamples s = samples_of(*this);
  if (type != SpectrumType::Illuminant)
    for (int i = 0; i < kCieRows; ++i) s[i] *= white_samples()[i];
  return xyz_to_linear_srgb(spectrum_to_xyz(s));
}

// --- Colorimetry ---------------------------------------------------------------------------

Vec3 cie_xyz_bar(float lambda) {
  int i;
  float t;
  if (!cie_segment(lambda, &i, &t)) return Vec3(0.f);
  const CieRow &a = row(i), &b = row(i + 1);
  return Vec3((1.f - t) * a.x + t * b.x, (1.f - t) * a.y + t * b.y, (1.f - t) * a.z + t * b.z);
}

float cie_y_integral() {
  // The exact integral of the piecewise-linear y-bar: the trapezoid rule on its rows.
  static const float integral = [] {
    double s = 0.0;
    for (int i = 0; i + 1 < kCieRows; ++i) s += 0.5 * (double(row(i).y) + row(i + 1).y) * kCieLambdaStep;
    return float(s);
  }();
  return integral;
}

float white_illuminant(float lambda) { return cie_interpolate(white_samples(), lambda); }

Vec3 equal_energy_xyz() {
  // The trapezoid rule on the rows is exact for the piecewise-linear functions, as in
  // cie_y_integral (every wavelength the table covers has a positive sampling density).
  static const Vec3 xyz = [] {
    glm::dvec3 s(0.0);
    for (int i = 0; i + 1 < kCieRows; ++i)
      s += 0.5 *
           glm::dvec3(double(row(i).x) + row(i + 1).x, double(row(i).y) + row(i + 1).y,
                      double(row(i).z) + row(i + 1).z) *
           double(kCieLambdaStep);
    return Vec3(s / s.y);
  }();
  return xyz;
}

Vec3 sampled_to_xyz(const SampledSpectrum& L, const SampledWavelengths& lambda) {
  const SampledSpectrum pdf = lambda.pdf();
  Vec3 xyz(0.f);
  for (int i = 0; i < kSpectrumSamples; ++i)
    if (pdf[i] != 0.f && L[i] != 0.f) xyz += cie_xyz_bar(lambda[i]) * (L[i] / pdf[i]);
  return xyz / (float(kSpectrumSamples) * cie_y_integral());
}

namespace {

// Lindbloom's matrix, derived from the sRGB primaries and the D65 white (0.3127, 0.3290).
RGB xyz_to_srgb_matrix(const Vec3& v) {
  return RGB(3.2404542f * v.x - 1.5371385f * v.y - 0.4985314f * v.z,
             -0.9692660f * v.x + 1.8760108f * v.y + 0.0415560f * v.z,
             0.0556434f * v.x - 0.2040259f * v.y + 1.0572252f * v.z);
}

const RGB& srgb_white() {
  static const RGB white = xyz_to_srgb_matrix(spectrum_to_xyz(white_samples()));
  return white;
}

}  // namespace

RGB xyz_to_linear_srgb(const Vec3& xyz) { return xyz_to_srgb_matrix(xyz) / srgb_white(); }

RGB wavelength_to_rgb(float lambda_nm, float value_over_pdf) {
  // The colour matching functions' rows taken to linear sRGB once, with sampled_to_xyz's
  // 1 / (N integral of y-bar) and xyz_to_linear_srgb's white. The interpolation between rows
  // commutes with that linear map, so this is cie_xyz_bar's.
  static const std::array<RGB, kCieRows> rgb_rows = [] {
    const float k = 1.f / (float(kSpectrumSamples) * cie_y_integral());
    std::array<RGB, kCieRows> rows;
    for (int i = 0; i < kCieRows; ++i) rows[size_t(i)] = xyz_to_linear_srgb(Vec3(row(i).x, row(i).y, row(i).z) * k);
    return rows;
  }();
  int i;
  float t;
  if (!cie_segment(lambda_nm, &i, &t)) return RGB(0.f);
  return ((1.f - t) * rgb_rows[size_t(i)] + t * rgb_rows[size_t(i) + 1]) * value_over_pdf;
}

RGB sampled_to_rgb(const SampledSpectrum& L, const SampledWavelengths& lambda) {
  return xyz_to_linear_srgb(sampled_to_xyz(L, lambda));
}

Vec3 spectrum_to_xyz(const SpectrumSamples& s) {
  // Riemann sums at 5 nm; dividing by the sum of y-bar makes the step size cancel.
  double x = 0, y = 0, z = 0, y_sum = 0;
  for (int i = 0; i < kCieRows; ++i) {
    x += double(row(i).x) * s[i];
    y += double(row(i).y) * s[i];
    z += double(row(i).z) * s[i];
    y_sum += row(i).y;
  }
  return Vec3(float(x / y_sum), float(y / y_sum), float(z / y_sum));
}

float interpolate_spectrum(std::span<const float> lambda, std::span<const float> value, float l) {
  size_t n = std::min(lambda.size(), value.size());
  if (n == 0) return 0.f;
  if (n == 1 || l <= lambda[0]) return value[0];  // one point: no segment to read (even for a NaN l)
  if (l >= lambda[n - 1]) return value[n - 1];
  // Binary search (tables are hundreds of points, read at every wavelength of every sample):
  // the first point not below l, whose left neighbour starts the segment. That is the segment
  // the former linear scan found, also when l is a point (t = 1 on the segment to its left),
  // so results are bit for bit the same. A NaN l compares false everywhere: segment 0, NaN.
  const size_t i = size_t(std::lower_bound(lambda.begin(), lambda.begin() + n, l) - lambda.begin());
  const size_t j = std::max<size_t>(i, 1) - 1;
  float t = (l - lambda[j]) / (lambda[j + 1] - lambda[j]);
  return (1.f - t) * value[j] + t * value[j + 1];
}

// Planck's law; constants as pbrt-v4 uses them (CODATA 2010).
double planck(double lambda_nm, double kelvin) {
  const double c = 299792458.0, h = 6.62606957e-34, kb = 1.3806488e-23;
  double l = lambda_nm * 1e-9;
  return (2.0 * h * c * c) / (std::pow(l, 5.0) * (std::exp((h * c) / (l * kb * kelvin)) - 1.0));
}

}  // namespace eyetrace
