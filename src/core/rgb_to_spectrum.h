// RGB -> smooth reflectance spectrum, after Jakob & Hanika 2019 ("A Low-Dimensional Function
// Space for Efficient Spectral Upsampling", EG 2019). A spectrum is a sigmoid of a quadratic
// polynomial of the wavelength, s(lambda) = S(c0 lambda^2 + c1 lambda + c2), which is smooth
// and lies in [0, 1] at every wavelength (a reflectance). The three coefficients of every RGB
// come from a table computed at build time by tools/rgb2spec_opt (CIELAB-optimal under the
// colour space's illuminant), interpolated trilinearly; see docs/spectral.md.
#pragma once
#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>

namespace eyetrace {

// s(lambda) = S(c0 lambda^2 + c1 lambda + c2), lambda in nm, S(x) = 1/2 + x / (2 sqrt(1 + x^2)).
// Exact black and white are c0 = c1 = 0 with c2 = -infinity and +infinity: S(-inf) = 0 and
// S(+inf) = 1 exactly, without NaN. (Coefficients that add infinities of opposite signs are
// not a spectrum; the table never makes them.)
struct SigmoidPolynomial {
  float c0 = 0, c1 = 0, c2 = 0;

  // The sigmoid: 1/2 + x / (2 sqrt(1 + x^2)), 0 and 1 at -inf and +inf. Beyond |x| = 1e18,
  // where x^2 would overflow, it returns its limit (off by less than 3e-37).
  static float sigmoid(float x) {
    if (!(std::abs(x) < 1e18f)) return x > 0.f ? 1.f : 0.f;  // also NaN -> 0
    return 0.5f + x / (2.f * std::sqrt(1.f + x * x));
  }
  float operator()(float lambda_nm) const { return sigmoid((c0 * lambda_nm + c1) * lambda_nm + c2); }
  // The largest value over 360..830 nm: at an end, or at the polynomial's vertex if that lies
  // between them (S is increasing, so s peaks where the polynomial does).
  float max_value() const {
    float m = std::max((*this)(360.f), (*this)(830.f));
    if (c0 != 0.f) {
      float vertex = -c1 / (2.f * c0);  // NaN (never in range) if c0 and c1 are infinite
      if (vertex >= 360.f && vertex <= 830.f) m = std::max(m, (*this)(vertex));
    }
    return m;
  }
};

// The build-time table of one RGB colour space: RGB in [0, 1]^3 -> SigmoidPolynomial.
class RGBToSpectrumTable {
 public:
  // Linear sRGB (Rec.709 primaries, IEC 61966-2-1) with the D65 white: the reflectance whose
  // colour under D65 (CIE 1931 2-degree observer) is the given RGB. Thread-safe; the table is
  // data of the program (no file, no allocation); the first call checks its header.
  static const RGBToSpectrumTable& srgb();

  // Each component is clamped to [0, 1] first (NaN counts as 0): a reflectance cannot be
  // brighter than white, so scale emission outside (e.g. by max component) before calling.
  // Greys (r == g == b, after clamping) take the exact constant spectrum: (g, g, g) gives
  // S(c2) = g at every wavelength, black exactly 0, white exactly 1. No allocation, no lock.
  SigmoidPolynomial operator()(const glm::vec3& rgb) const;

  int resolution() const { return res_; }

 private:
  RGBToSpectrumTable(int res, const float* z, const float* coefficients)
      : res_(res), z_(z), coefficients_(coefficients) {}
  int res_;
  const float* z_;             // res values of the largest component, increasing from 0 to 1
  const float* coefficients_;  // [3 cases][res z][res y][res x][3]
};

}  // namespace eyetrace
