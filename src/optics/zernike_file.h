// Reader of an aberrometer's Zernike export: OSA/ANSI coefficients of an eye's wavefront in
// micrometres, the pupil diameter they were measured over and, optionally, the wavelength. The
// format (docs/eye-camera.md, "Zernike wavefront files") is plain text, one item a line, '#'
// starts a comment:
//
//   pupil_diameter_mm 6.0      # required: the entrance-pupil diameter of the measurement
//   wavelength_nm 555          # optional: the measuring wavelength (reported, not applied)
//   ordering osa               # required, before the coefficients: osa (alias ansi) or nm
//   4 0.25                     # ordering osa: j c_um (OSA/ANSI single index j, Z80.28)
//   2 0 0.25                   # ordering nm: n m c_um (radial order, signed frequency)
//
// Every header key at most once. Every coefficient line names a polynomial of order 0 ..
// kMaxZernikeFileOrder at most once; absent terms are zero. Any problem (an unknown key or
// ordering, a missing pupil size, a value that is not a finite number, a duplicate, an index
// that names no polynomial or lies beyond the supported order) throws OpticsError naming the
// file, the line and the value.
#pragma once

#include <string>
#include <vector>

namespace eyetrace::optics {

// Highest radial order a file may give: 66 terms, more than clinical aberrometers export
// (typically to the 6th or 8th order).
inline constexpr int kMaxZernikeFileOrder = 10;
// Largest coefficient accepted, um: 100 um of defocus over a 2 mm pupil is ~350 D, far beyond
// any eye, so a larger number is a unit mistake (e.g. nm or waves).
inline constexpr double kMaxZernikeCoefficient_um = 100.0;
// Measured pupil diameters accepted, mm.
inline constexpr double kMaxZernikePupil_mm = 12.0;

struct ZernikeFile {
  std::string origin;                   // the file name, for messages and reports
  double pupil_diameter_mm = 0.0;       // entrance-pupil diameter of the measurement
  double wavelength_nm = 0.0;           // 0: not stated
  std::vector<double> coefficients_um;  // c_j, j = 0 .. (order + 1)(order + 2)/2 - 1
  int max_order = 0;                    // highest radial order with a line in the file
};

// Parses the text of a file; `origin` names it in messages.
ZernikeFile parse_zernike_text(const std::string& text, const std::string& origin);
// Reads and parses a file (throws OpticsError naming it when it cannot be read).
ZernikeFile read_zernike_file(const std::string& path);

}  // namespace eyetrace::optics
