// A film's pixel sensor, as pbrt-v4's PixelSensor (src/pbrt/film.h, film.cpp): how a sample's
// spectral radiance becomes the sensor's three responses, and the matrix that takes those to CIE
// XYZ, white balanced. The film then goes XYZ -> linear sRGB as for every sample.
//
// - "cie1931": the responses are X, Y, Z themselves. With a white balance temperature T > 0
//   the matrix is the Bradford adaptation (core/white_balance.h) from the chromaticity of
//   pbrt-v4's illuminant at T to the colour space's white (D65); T = 0 is none (identity).
// - A camera (pbrt-v4's named spectra NAME_r, NAME_g, NAME_b: canon_eos_5d_mkiv, nikon_d850,
//   sony_ilce_9, ...): the responses are those curves (0 outside their 380-720 nm tables), and
//   the matrix is pbrt-v4's least-squares fit over the 24 ColorChecker swatches
//   (render/swatch_reflectances.h): the camera's responses to each swatch under the white
//   balance illuminant (normalised by the green response to that illuminant) against the
//   swatch's XYZ under the colour space's white (normalised to Y = 1 for a perfect white, then
//   times Y/G of the balance illuminant), which maps an object seen under the balance
//   illuminant to about the XYZ it has under D65: a white card lit by it comes out neutral.
//   Sums over 360-830 nm every 1 nm, as pbrt-v4's ProjectReflectance.
//
// Units: responses are Monte Carlo estimates of integral L(lambda) s(lambda) d lambda divided by
// the integral of y-bar, the film's XYZ normalisation (core/spectrum.h), so that the cie1931
// sensor's responses are exactly sampled_to_xyz().
#pragma once
#include <glm/mat3x3.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/math.h"
#include "core/sampled_spectrum.h"

namespace eyetrace {

class PixelSensor {
 public:
  static PixelSensor cie1931(double white_balance_kelvin);
  // The camera `name` (without the _r, _g, _b suffixes) white balanced for white_balance_kelvin
  // (> 0; pbrt-v4 takes 6500 for a camera when the scene gives none or 0); nullopt when no
  // such named spectra exist.
  static std::optional<PixelSensor> camera(std::string_view name, double white_balance_kelvin);
  // Every camera camera() knows, sorted.
  static std::vector<std::string> camera_names();

  // The sensor's responses to the sample (terminated wavelengths, pdf 0, count for nothing).
  Vec3 responses(const SampledSpectrum& L, const SampledWavelengths& lambda) const;
  // The responses' CIE XYZ.
  Vec3 xyz(const Vec3& responses) const { return xyz_from_responses_ * responses; }
  // The same matrix in double precision (row i, column j is m[j][i], glm's column-major order).
  const glm::dmat3& xyz_from_responses() const { return xyz_from_responses_d_; }

  // Whether the matrix is finite: a white balance temperature so low (below about 25 K, where
  // Planck's law underflows) that its illuminant has no power in the visible range leaves
  // nothing to fit or adapt to.
  bool finite() const;

  // Response c (0 r, 1 g, 2 b) at lambda; for cie1931, the colour-matching functions.
  float response(int c, float lambda_nm) const;

 private:
  PixelSensor() = default;
  void set_matrix(const glm::dmat3& m);
  // Camera curves every 1 nm from 360 to 830 nm (kDenseCount values each); empty for cie1931.
  static constexpr int kDenseCount = 471;
  std::vector<float> curves_[3];
  glm::mat3 xyz_from_responses_{1.f};
  glm::dmat3 xyz_from_responses_d_{1.0};
};

}  // namespace eyetrace
