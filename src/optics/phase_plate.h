// A phase plate: a wavefront W(x, y) (optical path, mm) laid on a flat surface, as an
// aberrometer's measured wavefront is applied to a schematic eye (docs/eye-camera.md, "Zernike
// wavefront files"). The surface keeps each ray's position; the plate subtracts W from its
// optical path and so, by the eikonal (the optical direction n d is the gradient of the path),
// subtracts grad W from the tangential part of n d: n d_t' = n d_t - grad W. Why minus: W is
// the wavefront in the OSA sign convention (positive where it leads the reference), and a
// wavefront leads where its path is shorter; a positive defocus c(2,0) then converges the beam
// like a plus lens and makes the eye myopic, as ANSI Z80.28 has it. The rule is the same both
// ways along the ray (a plate is reversible), and n d_t is the same on both sides of a flat
// interface (Snell), so the plate applies after any refraction at its surface.
//
// Frames: W is given by OSA/ANSI Zernike coefficients (zernike.h) over a disc of radius
// radius_mm centred on the surface's own axis, in OSA axes: x_osa = -x, y_osa = y of the
// surface's local frame (wavefront.h). Beyond the disc the measurement says nothing; the
// plate's disc is an aperture: rays outside it are blocked (see covers()).
#pragma once

#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "optics/zernike_file.h"

namespace eyetrace::optics {

struct Prescription;

// Second derivatives of W at the plate's centre, 1/mm, in the surface's (prescription) frame:
// the plate's paraxial power matrix (n u' = n u - H y).
struct PlateHessian {
  double xx = 0.0, xy = 0.0, yy = 0.0;
};

class PhasePlate {
 public:
  // coefficients_um: c_j from j = 0; radius_mm > 0: the disc they are normalised to, in the
  // plate's plane. Throws OpticsError beyond kMaxZernikeFileOrder or for a bad radius.
  PhasePlate(std::vector<double> coefficients_um, double radius_mm);

  const std::vector<double>& coefficients_um() const { return coefficients_um_; }
  double radius_mm() const { return radius_mm_; }
  int max_order() const { return order_; }

  // Inside the measured disc (rim included). Rays outside are blocked: the wavefront there is
  // unknown, its Zernike series grows as rho^n outside the disc, and passing them unchanged
  // would put a step in W at the rim that no eye has.
  bool covers(double x, double y) const { return x * x + y * y <= radius_mm_ * radius_mm_; }
  // W at (x, y) of the local frame, mm of optical path.
  double wavefront_mm(double x, double y) const;
  // (dW/dx, dW/dy) at (x, y) of the local frame (dimensionless).
  glm::dvec2 gradient(double x, double y) const;
  PlateHessian hessian_at_centre() const;

  // Where the plate came from, for reports: the file, its measured (entrance-)pupil diameter
  // and wavelength (0 = not stated), and the pupil magnification used to map the measured
  // pupil onto the plate (the measured pupil's diameter / the plate's, add_phase_plate).
  std::string origin;
  double measured_pupil_diameter_mm = 0.0;
  double measured_wavelength_nm = 0.0;
  double pupil_magnification = 1.0;

 private:
  std::vector<double> coefficients_um_;
  double radius_mm_;
  int order_ = 0;
  // W as a polynomial in u = x_osa / r, v = y_osa / r (um): poly_[p (order + 1) + q] multiplies
  // u^p v^q (p + q <= order).
  std::vector<double> poly_;
};

// The measured wavefront of `file` as a plate on the aperture stop (the iris) of p. The file's
// pupil is the entrance pupil (what an aberrometer sees): its rim is the real image of the
// plate's rim through the cornea. So the plate's disc is the iris height at which rays parallel
// to the axis through the measured pupil's rim cross the stop (a real trace, mean over 16
// azimuths), and pupil_magnification = the file's radius / that height. W, an optical path, is
// then the same at the two rims, and inside the pupil to the cornea's pupil distortion. The
// plate's power seen from the entrance pupil is its own divided by the paraxial magnification
// squared, so M = -4 sqrt(3) c(2,0) / r^2 holds with the file's r to the ratio of the real and
// paraxial magnifications squared (docs/eye-camera.md has the numbers). Adds a note to p when
// the iris is wider than the plate's disc (the plate then limits the pupil). Throws OpticsError
// when p has no stop or already has a plate there, or when a rim ray does not reach the iris.
void add_phase_plate(Prescription& p, const ZernikeFile& file);

}  // namespace eyetrace::optics
