// CIE colorimetric tables at 5 nm from 380 to 780 nm: the 1931 2-degree colour-matching
// functions, standard illuminant D65 and the daylight basis S0, S1, S2 (any CIE D-series
// illuminant is S0 + M1 S1 + M2 S2).
#pragma once
#include <array>

namespace eyetrace {

struct CieRow {
  float lambda_nm;
  float x, y, z;     // CIE 1931 2-degree observer
  float d65;         // relative spectral power, 100 at 560 nm
  float s0, s1, s2;  // daylight components
};

inline constexpr int kCieRows = 81;
inline constexpr float kCieLambdaMin = 380.f, kCieLambdaStep = 5.f, kCieLambdaMax = 780.f;

const std::array<CieRow, kCieRows>& cie_table();

// D65 divided by its luminance (Y in the film's normalisation, core/spectrum.h: the equal-energy
// spectrum 1 has Y = 1) at the table's rows: the colour space's white as an emission of
// luminance 1, which every RGB light multiplies by at every wavelength. The compiler computes
// it, so reading it costs no function-local static's guard and no initialisation order.
extern const std::array<float, kCieRows> kCieWhite;

}  // namespace eyetrace
