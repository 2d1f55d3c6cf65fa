// pbrt-v4 "realistic" camera lens files -> Prescription.
//
// Format (pbrt-v4 RealisticCamera): one interface per line, listed from the object side to the
// image side, whitespace-separated columns
//   curvature radius (mm; 0 = the aperture stop), thickness to the next interface (mm),
//   index of refraction after the interface (0 is also used for air: read as 1),
//   aperture diameter (mm)
// and '#' starts a comment. eyetrace extends it with an optional 5th column, the conic constant.
// pbrt scales mm to metres, halves the diameter, and ignores the last thickness: it places the
// film by focusing at focusdistance. Here the film (a flat, unlimited image plane) is at the last
// thickness as written, unless LensFileOptions::focus_distance_m is given (then it is placed at
// the paraxial image of that object distance), or the last thickness is 0 (then at the paraxial
// focus for infinity, as pbrt would need a focus distance to do anything else).
#pragma once

#include <optional>
#include <string>

#include "optics/prescription.h"

namespace eyetrace::optics {

struct LensFileOptions {
  // Replaces the stop's diameter (pbrt's "aperturediameter"); may not exceed the file's.
  std::optional<double> aperture_diameter_mm;
  // Object distance in metres from the first vertex to focus on (moves the film).
  std::optional<double> focus_distance_m;
};

// `file_name` is used in error messages ("lens.dat:7: expected 4 or 5 numbers, found 3").
Prescription parse_lens_file(const std::string& text, const std::string& file_name,
                             const LensFileOptions& options = {});
// Reads the file at `path` and parses it (the message names the path's file name).
Prescription read_lens_file(const std::string& path, const LensFileOptions& options = {});

}  // namespace eyetrace::optics
