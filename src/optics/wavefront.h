// Wavefront aberration of one object point: the optical path difference (OPD) over the pupil,
// its RMS and peak-to-valley, its OSA/ANSI Zernike coefficients and the refraction they give.
//
// Construction (the standard one of optical design codes): rays from the object point fill a
// disc on the entrance-pupil plane; each is traced exactly to the last refracting surface and
// continued in image space to the reference sphere, centred on the chief ray's image point (on
// the image surface, the retina) and passing through the point where the chief ray crosses the
// paraxial exit-pupil plane (radius = that distance). OPD = optical path of the chief ray to the
// sphere minus that of the ray (mm; positive where the wavefront leads the sphere). Why this
// reference: a sphere centred on an image point is what a perfect system would produce, so the
// OPD is the aberration about that point; centring it on the chief ray's point (not the best
// focus or the centroid) leaves defocus and tilt in the wavefront, where the refraction and the
// image displacement are read from; putting it in the exit pupil is where the pupil function
// (amplitude and phase) of a diffraction calculation is defined. The exit pupil of an eye lies
// inside the lens, so the image-space ray is continued backwards to it (a virtual path, in the
// vitreous's index), as the codes do.
//
// Pupil: vision science states an eye's Zernike coefficients over the entrance pupil in object
// space (ANSI Z80.28), so the OPD is indexed by where each ray crosses the paraxial entrance-
// pupil plane (object space, perpendicular to the axis), relative to the chief ray's crossing,
// normalised by the stated radius. Axes as ANSI Z80.28 (right-handed, z out of the eye towards
// the object, y up): x_osa = -x, y_osa = y of the prescription frame (whose z runs into the eye).
// The disc is sampled on a grid x grid square lattice (cell centres inside the disc: uniform
// area weights). The disc is the pupil: by default its radius is the paraxial entrance pupil's
// (the stop's paraxial image) and the stop itself does not clip the rays, the convention of
// design codes without real-ray aiming and of the model-eye literature (a "6 mm pupil" is a 6 mm
// entrance pupil). The real stop's image is slightly smaller: the cornea's pupil aberration
// puts Navarro's real entrance-pupil edge 1 % inside the paraxial one (4 mm stop). With
// clip_at_stop the real stop clips. Rays of the disc that do not reach the image (another
// aperture, or the stop when it clips) are counted and the analysis covers the others, with a
// warning: the Zernike terms are then not orthogonal over what is left.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "optics/prescription.h"
#include "optics/wavefront_refraction.h"

namespace eyetrace::optics {

struct WavefrontOptions {
  // The object point as SpotOptions (spot.h): field angle in the y-z plane, |.| < 85, source
  // above the axis for a positive field; distance from the entrance-pupil centre, +inf = infinity.
  double field_deg = 0.0;
  double object_distance_m = std::numeric_limits<double>::infinity();
  double wavelength_nm = 0.0;    // 0 = the prescription's wavelength_nm
  double pupil_radius_mm = 0.0;  // entrance-pupil radius of the analysis; 0 = the paraxial one
  int grid = 64;                 // samples across the pupil's diameter, [8, 1024]
  int zernike_order = 6;         // highest radial order fitted, [2, 12]
  bool clip_at_stop = false;     // true: the real stop vignettes (else the disc is the pupil)
  // false: the OPD samples, RMS and PV only (zernike_um, refraction and fit residual left empty
  // or zero): a PSF needs no fit, which costs more than the trace on a fine grid.
  bool fit_zernike = true;
};

struct WavefrontResult {
  double field_deg = 0.0;
  double wavelength_nm = 0.0;
  double pupil_radius_mm = 0.0;  // radius of the disc the coefficients are over
  int zernike_order = 0;
  // Geometry of the construction: the entrance-pupil plane and where the chief ray crosses it
  // (prescription frame), the reference sphere's centre (the chief ray's image point) and radius.
  double entrance_pupil_z_mm = 0.0;
  glm::dvec2 pupil_centre_mm{0.0};
  double exit_pupil_z_mm = 0.0;
  glm::dvec3 image_point_mm{0.0};
  double reference_radius_mm = 0.0;
  int grid = 0;           // samples across the disc's diameter (the options')
  int rays_in_pupil = 0;  // grid cells inside the disc
  int rays_lost = 0;      // of those, how many did not reach the image (and the reference sphere)
  std::string warning;    // empty, or what limits the result (vignetting)
  // The OPD map: normalised pupil coordinates (OSA axes, |.| <= 1) and OPD in waves.
  std::vector<glm::dvec2> pupil_points;
  std::vector<double> opd_waves;
  // RMS wavefront error over the disc, piston removed, from the Zernike coefficients: the root
  // sum of squares of c_j, j >= 1 (each term has unit RMS over the disc; ANSI Z80.28's way). It
  // converges with the grid as fast as the coefficients do (1e-5 at 64 across, docs/wavefront.md).
  double rms_waves = 0.0;
  // The same straight from the samples (equal-area cells, about their mean): includes what the
  // fit leaves, but the grid's staircase rim makes it converge only as 1 / grid (7e-3 at 64).
  double rms_sampled_waves = 0.0;
  double pv_waves = 0.0;            // max - min of the samples
  std::vector<double> zernike_um;   // c_j, j = 0 .. (order + 1)(order + 2)/2 - 1, micrometres
  double fit_residual_waves = 0.0;  // RMS of the OPD minus the fitted sum
  PowerVector least_squares;        // refraction from the wavefront (wavefront_refraction.h), D,
  PowerVector paraxial;             // in the entrance-pupil plane (vergence there)
};

// Throws OpticsError naming the option when one is out of its range.
void validate(const WavefrontOptions& options);

// Throws OpticsError for invalid options, a chief ray that is lost, or when fewer rays than
// Zernike terms reach the image (naming the field and the count).
WavefrontResult trace_wavefront(const Prescription& prescription, const WavefrontOptions& options);

}  // namespace eyetrace::optics
