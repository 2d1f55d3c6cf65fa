// A one-surface test system for the wavefront and PSF tests: a refracting conic from air into
// glass (n = 1.5, R = 10 mm) with the stop in its vertex plane and the image plane at the far
// focus n R / (n - 1) = 30 mm behind the vertex. With conic -1/n^2 (an ellipsoid: Descartes'
// oval whose eccentricity is 1/n) it images an axial object at infinity without aberration.
#pragma once

#include "optics/prescription.h"

namespace eyetrace::optics::test {

inline constexpr double kSingleSurfaceIndex = 1.5;

inline Prescription single_surface(double conic, double stop_radius_mm, double wavelength_nm = 589.3) {
  const double n = kSingleSurfaceIndex, R = 10.0;
  Prescription p;
  p.name = "single surface";
  p.wavelength_nm = p.reference_wavelength_nm = wavelength_nm;
  p.media = {{"air", 1.0, wavelength_nm, {}}, {"glass", n, wavelength_nm, {}}};
  Surface stop;
  stop.name = "stop";
  stop.medium = "air";
  stop.role = SurfaceRole::Stop;
  stop.semi_diameter_mm = stop_radius_mm;
  Surface lens;
  lens.name = "conic";
  lens.profile = SurfaceProfile::from_radius(R, conic);
  lens.thickness_mm = n * R / (n - 1.0);
  lens.medium = "glass";
  lens.index_after = n;
  Surface image;
  image.name = "image";
  image.medium = "glass";
  image.index_after = n;
  image.role = SurfaceRole::Image;
  p.surfaces = {stop, lens, image};
  return p;
}

// The stigmatic one: conic -1/n^2.
inline Prescription stigmatic_surface(double stop_radius_mm, double wavelength_nm = 589.3) {
  return single_surface(-1.0 / (kSingleSurfaceIndex * kSingleSurfaceIndex), stop_radius_mm, wavelength_nm);
}

}  // namespace eyetrace::optics::test
