// A measured BRDF of the RGL material database (Dupuy & Jakob 2018), as pbrt-v4's
// MeasuredBxDFData holds it: from a tensor file (tensor_file.h) with the fields
//   theta_i, phi_i [n]        the incident directions' nodes (radians);
//   ndf, sigma [ny, nx]       the microfacet distribution D over (u_theta, u_phi) of the normal
//                             and the projected area sigma(wo) (plain tables);
//   vndf [phi_i, theta_i, ny, nx]       per incident node, the visible normals' density over
//                             the unit square (a warp);
//   luminance [phi_i, theta_i, ny, nx]  the BRDF's luminance over the sample square (a warp);
//   spectra [phi_i, theta_i, wavelengths, ny, nx], wavelengths [n]: the spectral BRDF factor
//                             on the sample square (a plain table, interpolated in wavelength);
//   description, jacobian (uint8; required as by pbrt-v4, not used).
// Angles map to the unit square as u_theta = sqrt(2 theta / pi), u_phi = phi / (2 pi) + 1/2.
// An isotropic file has at most two phi_i nodes (pbrt-v4's rule). Files with `rgb` instead of
// `spectra` are refused, as pbrt-v4 refuses them.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "materials/piecewise_linear_2d.h"
#include "materials/tensor_file.h"

namespace eyetrace {

struct MeasuredBRDF {
  bool isotropic = true;
  std::vector<float> wavelengths;
  PiecewiseLinear2D ndf, sigma, vndf, luminance, spectra;
};

// Checks every field's presence, type, shape and values (TensorFileError saying which and why).
std::shared_ptr<const MeasuredBRDF> make_measured_brdf(const TensorFile& file);

// The BRDF of the file at `path`, read once while any material holds it (a cache keyed by the
// path; thread-safe). TensorFileError for an unreadable or invalid file.
std::shared_ptr<const MeasuredBRDF> load_measured_brdf(const std::string& path);

}  // namespace eyetrace
