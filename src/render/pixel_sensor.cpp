#include "render/pixel_sensor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/named_spectra.h"
#include "core/spectrum.h"
#include "core/white_balance.h"
#include "render/swatch_reflectances.h"

namespace eyetrace {

namespace {

constexpr int kFirstNm = 360, kLastNm = 830;  // pbrt-v4's Lambda_min, Lambda_max

// A named spectrum's table value at lambda, 0 outside the table (pbrt-v4's PiecewiseLinearSpectrum;
// core/named_spectra.h's evaluate_named_spectrum holds the end values instead).
float table_or_zero(const NamedSpectrum& s, float lambda_nm) {
  const auto& v = s.interleaved;
  if (v.size() < 4 || lambda_nm < v.front() || lambda_nm > v[v.size() - 2]) return 0.f;
  return evaluate_named_spectrum(s, lambda_nm);
}

// The colour space's white (D65) at lambda, as an illuminant of any scale.
double output_white(double lambda_nm) { return white_illuminant(float(lambda_nm)); }

// Solves A X = B in the least-squares sense for the 3x3 X (rows of A, B: the swatches), by the
// normal equations as pbrt-v4's LinearLeastSquares, and returns the matrix M with b = M a for
// each row (X transposed).
glm::dmat3 least_squares(const double a[kSwatchCount][3], const double b[kSwatchCount][3]) {
  glm::dmat3 ata(0.0), atb(0.0);  // [col][row]
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int r = 0; r < kSwatchCount; ++r) {
        ata[j][i] += a[r][i] * a[r][j];
        atb[j][i] += a[r][i] * b[r][j];
      }
  // A singular system (no light to fit under) gives a NaN matrix, which finite() reports.
  if (!(std::abs(glm::determinant(ata)) > 1e-300)) return glm::dmat3(std::nan(""));
  return glm::transpose(glm::inverse(ata) * atb);
}

}  // namespace

void PixelSensor::set_matrix(const glm::dmat3& m) {
  xyz_from_responses_d_ = m;
  xyz_from_responses_ = glm::mat3(m);
}

PixelSensor PixelSensor::cie1931(double white_balance_kelvin) {
  PixelSensor s;
  if (white_balance_kelvin > 0.0) {
    glm::dvec3 source(0.0);
    for (int l = kFirstNm; l <= kLastNm; ++l)
      source += glm::dvec3(cie_xyz_bar(float(l))) * white_balance_illuminant(white_balance_kelvin, l);
    // The target is the white the film's XYZ -> linear sRGB maps to (1, 1, 1) exactly (its 5 nm
    // sums), so that a balanced white is neutral in the output to rounding.
    const glm::dvec3 target(spectrum_to_xyz(kCieWhite));
    s.set_matrix(bradford_adaptation(xy_from_xyz(source), xy_from_xyz(target)));
  }
  return s;
}

std::optional<PixelSensor> PixelSensor::camera(std::string_view name, double white_balance_kelvin) {
  const std::string base(name);
  const NamedSpectrum* curve[3] = {find_named_spectrum(base + "_r"), find_named_spectrum(base + "_g"),
                                   find_named_spectrum(base + "_b")};
  for (const NamedSpectrum* c : curve)
    if (!c || c->kind != NamedSpectrumKind::Sensor || c->interleaved.empty()) return std::nullopt;
  if (!(white_balance_kelvin > 0.0)) throw std::invalid_argument("PixelSensor::camera: white balance must be > 0 K");
  PixelSensor s;
  for (int c = 0; c < 3; ++c) {
    s.curves_[c].resize(kDenseCount);
    for (int i = 0; i < kDenseCount; ++i) s.curves_[c][i] = table_or_zero(*curve[c], float(kFirstNm + i));
  }
  // pbrt-v4's PixelSensor constructor: the camera's responses to each swatch under the balance
  // illuminant over its green response to that illuminant, and the swatch's XYZ under the output
  // white over that white's Y, times Y / G of the balance illuminant.
  double g_illum = 0.0, y_illum = 0.0, y_white = 0.0;
  for (int l = kFirstNm; l <= kLastNm; ++l) {
    const double e = white_balance_illuminant(white_balance_kelvin, l);
    g_illum += s.response(1, float(l)) * e;
    y_illum += cie_xyz_bar(float(l)).y * e;
    y_white += cie_xyz_bar(float(l)).y * output_white(l);
  }
  double camera_rgb[kSwatchCount][3] = {}, xyz_out[kSwatchCount][3] = {};
  for (int i = 0; i < kSwatchCount; ++i) {
    for (int l = kFirstNm; l <= kLastNm; ++l) {
      const double r = swatch_reflectance(i, l);
      if (r == 0.0) continue;
      const double e = white_balance_illuminant(white_balance_kelvin, l) * r;
      const double w = output_white(l) * r;
      const Vec3 bar = cie_xyz_bar(float(l));
      for (int c = 0; c < 3; ++c) {
        camera_rgb[i][c] += s.response(c, float(l)) * e;
        xyz_out[i][c] += bar[c] * w;
      }
    }
    for (int c = 0; c < 3; ++c) {
      camera_rgb[i][c] /= g_illum;
      xyz_out[i][c] *= (y_illum / g_illum) / y_white;
    }
  }
  s.set_matrix(least_squares(camera_rgb, xyz_out));
  return s;
}

std::vector<std::string> PixelSensor::camera_names() {
  std::vector<std::string> names;
  for (const std::string& n : named_spectrum_names()) {
    if (n.size() < 3 || n.compare(n.size() - 2, 2, "_r") != 0) continue;
    const std::string base = n.substr(0, n.size() - 2);
    const NamedSpectrum* s = find_named_spectrum(n);
    if (s && s->kind == NamedSpectrumKind::Sensor && find_named_spectrum(base + "_g") &&
        find_named_spectrum(base + "_b"))
      names.push_back(base);
  }
  std::sort(names.begin(), names.end());
  return names;
}

bool PixelSensor::finite() const {
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(xyz_from_responses_d_[j][i])) return false;
  return true;
}

float PixelSensor::response(int c, float lambda_nm) const {
  if (curves_[0].empty()) return cie_xyz_bar(lambda_nm)[c];
  const float x = lambda_nm - float(kFirstNm);
  if (!(x >= 0.f && x <= float(kDenseCount - 1))) return 0.f;
  const int i = std::min(int(x), kDenseCount - 2);
  const float t = x - float(i);
  return (1.f - t) * curves_[c][i] + t * curves_[c][i + 1];
}

Vec3 PixelSensor::responses(const SampledSpectrum& L, const SampledWavelengths& lambda) const {
  if (curves_[0].empty()) return sampled_to_xyz(L, lambda);
  // As sampled_to_xyz, with the camera's curves for the colour-matching functions.
  const SampledSpectrum pdf = lambda.pdf();
  Vec3 rgb(0.f);
  for (int i = 0; i < kSpectrumSamples; ++i) {
    if (pdf[i] == 0.f || L[i] == 0.f) continue;
    const float w = L[i] / pdf[i];
    for (int c = 0; c < 3; ++c) rgb[c] += response(c, lambda[i]) * w;
  }
  return rgb / (float(kSpectrumSamples) * cie_y_integral());
}

}  // namespace eyetrace
