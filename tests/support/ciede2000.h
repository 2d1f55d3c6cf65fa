// CIELAB and colour differences for colour tests: CIE 1976 L*a*b* from XYZ and a white, the
// CIE76 difference (Euclidean in Lab) and CIEDE2000 (CIE 142-2001, with kL = kC = kH = 1),
// implemented from Sharma, Wu & Dalal 2005, "The CIEDE2000 color-difference formula:
// implementation notes, supplementary test data, and mathematical observations", Color Res.
// Appl. 30(1), 21-30, and checked against that paper's test data (ciede2000_test.cpp).
// Include it as "../support/ciede2000.h"; link eyetrace_test_colour (tests/CMakeLists.txt).
#pragma once
#include <array>

namespace eyetrace::colour {

struct Lab {
  double L = 0, a = 0, b = 0;
};

// CIE 1976 L*a*b* of `xyz` relative to the reference white `white` (same scale as xyz; the
// white maps to L* = 100, a* = b* = 0).
Lab xyz_to_lab(const std::array<double, 3>& xyz, const std::array<double, 3>& white);

double cie76(const Lab& lab1, const Lab& lab2);
// Symmetric in its arguments; the hue of a colour of zero chroma is taken as 0, as the paper does.
double ciede2000(const Lab& lab1, const Lab& lab2);

}  // namespace eyetrace::colour
