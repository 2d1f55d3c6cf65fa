// Point-spread function of one object point by FFT of its pupil function, with the Strehl ratio
// and encircled-energy radii; the MTF is mtf.h.
//
// Pupil function: on the wavefront's entrance-pupil grid (wavefront.h: grid x grid cells across
// the disc, spacing delta = 2 r / grid mm), amplitude 1 where the traced ray reaches the image
// (trace the wavefront with clip_at_stop so that the real stop, not the paraxial disc, is the
// pupil) and 0 elsewhere, phase 2 pi OPD / lambda. It is zero-padded to fft_size x fft_size and
// Fourier transformed; |.|^2 is the PSF in angle in object space. Why over the entrance pupil:
// vision science states visual angle and cycles per degree in object space, and the OPD is
// sampled there on a regular grid (the exit-pupil samples are not regular: pupil distortion).
// Scale: a wavefront tilted by a small angle a changes its phase across the entrance-pupil plane
// by 2 pi a cos(theta) y / lambda, theta the angle of the beam with the plane's normal (the axis).
// So the PSF sample spacing is lambda / (fft_size delta) rad sagittally (along x) and
// lambda / (fft_size delta cos theta) tangentially (along y, the field's meridian): the pupil
// seen from the object is foreshortened by cos theta in the meridian. On the retina the angles
// are multiplied by the local scale of the chief ray's image point (RetinalScale), which for a
// paraxial axial image is the front focal length 1/P, the same as lambda R / (n' fft_size
// delta') over the exit pupil (R the reference-sphere radius, delta' the exit-pupil spacing).
// Axes: x and y are the OSA pupil axes (wavefront.h), so x is mirrored from the prescription's.
#pragma once

#include <complex>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "optics/prescription.h"
#include "optics/wavefront.h"

namespace eyetrace::optics {

// How far the retinal image moves per radian of object-space angle at a field (mm/rad):
// tangentially (the field angle changes) and sagittally (the object turns about the axis).
struct RetinalScale {
  double tangential_mm_per_rad = 0.0;
  double sagittal_mm_per_rad = 0.0;
};

// By finite differences of the chief ray (chromatic.h), at the prescription's wavelength or
// wavelength_nm; throws OpticsError when the chief rays are lost.
RetinalScale retinal_scale(const Prescription& prescription, double field_deg, double object_distance_m,
                           double wavelength_nm);

struct PsfOptions {
  // FFT size (samples across the PSF); 0 = automatic: the smallest power of two >= 4 grid (the
  // PSF sampled at lambda / 4D at least, twice the Nyquist rate of an intensity whose bandwidth
  // is D / lambda, which makes an image of it readable), or >= 2 grid (Nyquist: the pupil's
  // autocorrelation, so the MTF and the encircled energy, still unwrapped) when that would
  // exceed 2048. Else in [2 grid, 8192].
  int fft_size = 0;
};

// The low frequencies of a PSF's Fourier series (all of its spectrum: zero beyond the pupil's
// diameter), I_k / (I_0 A) for |kx|, |ky| <= reach, the phase about the PSF's zero angle; A the
// FFT window's area on the retina (its period, the same whatever the FFT size: lambda / delta
// times the retinal scale). The encircled energy is read from it (encircled_energy.h).
struct PsfSpectrum {
  int reach = 0;
  double window_x_um = 0.0, window_y_um = 0.0;
  std::vector<std::complex<double>> terms;  // (2 reach + 1)^2, row-major (ky, kx)
};

struct Psf {
  int grid = 0;      // pupil samples across the disc (the wavefront's)
  int fft_size = 0;  // N: samples across the PSF (and its period)
  int pupil_samples = 0;
  double wavelength_nm = 0.0;
  double pupil_radius_mm = 0.0;
  double pupil_spacing_mm = 0.0;  // delta, entrance-pupil plane
  double cos_field = 1.0;         // foreshortening of the pupil in the meridian
  // Sample spacing in object space (rad) and on the retina (um), sagittal (x) and tangential (y).
  double sample_x_rad = 0.0, sample_y_rad = 0.0;
  double sample_x_um = 0.0, sample_y_um = 0.0;
  RetinalScale scale;
  // Intensity, row-major (y, x), the zero angle (the chief ray's image) at (N/2, N/2); in units
  // of the diffraction-limited peak of the same pupil amplitude, so its maximum is about the
  // Strehl ratio and its sum is N^2 / pupil_samples (Parseval).
  std::vector<double> intensity;
  double strehl = 0.0;                  // peak of the PSF, located between samples, / diffraction-limited peak
  double strehl_phasor = 0.0;           // |mean exp(i phase)|^2: the PSF at the chief ray's image point
  glm::dvec2 peak_rad{0.0};             // where the peak is (x, y), object-space angle from the chief ray
  glm::dvec2 centroid_rad{0.0};         // centroid of the PSF
  double ee50_um = 0.0, ee80_um = 0.0;  // encircled-energy radii about the centroid, on the retina
  PsfSpectrum spectrum;                 // from the pupil's autocorrelation (2 grid FFT, not N)
  double max_phase_step_rad = 0.0;      // largest phase difference between neighbouring pupil samples
  std::string warning;                  // empty, or what limits the result (a too coarse grid)

  double at(int ix, int iy) const { return intensity[static_cast<size_t>(iy) * fft_size + ix]; }
};

// Throws OpticsError when the options are out of range or the wavefront has no samples. The
// wavefront's grid must be the one it was traced with (WavefrontResult::grid).
Psf compute_psf(const WavefrontResult& wavefront, const RetinalScale& scale, const PsfOptions& options = {});

// The PSF of an object point (options: field, distance, wavelength, pupil, grid) with the real
// stop clipping (the pupil of the PSF is the real one), the pupil grid refined from options.grid
// until neighbouring samples differ by at most pi/2 of phase, at most max_grid across (the grid
// fine enough for a Zernike fit, 64, aliases the PSF of an oblique field's steep wavefront:
// Navarro at 20 degrees, 4.5 mm pupil, has 4.5 rad steps at 64 and its EE50 came out 20 % off).
// The PSF's warning says when even max_grid is too coarse. Throws OpticsError when the trace fails.
struct TracedPsf {
  WavefrontResult wavefront;
  Psf psf;
};
TracedPsf trace_psf(const Prescription& prescription, const WavefrontOptions& options, int max_grid = 512);

// The largest phase difference (rad) between neighbouring samples of a wavefront's grid (both in
// the pupil): above pi the phase is aliased and the PSF's geometric extent exceeds its FFT period.
double max_phase_step_rad(const WavefrontResult& wavefront);

// The PSF at an arbitrary angle (x, y) rad by direct summation over the pupil samples (no FFT;
// used to locate the peak between samples, and by tests), in the units of Psf::intensity.
double psf_at(const WavefrontResult& wavefront, double cos_field, glm::dvec2 angle_rad);

// The same for many angles of one wavefront: the pupil's phasors exp(2 pi i OPD) are made once,
// and an angle's tilt is separable on the grid (a factor per column times one per row), so an
// angle costs a complex product per sample instead of a sine and cosine (the peak search makes
// about 50 of them). Samples off the wavefront's grid fall back to psf_at's sum.
class PsfEvaluator {
 public:
  PsfEvaluator(const WavefrontResult& wavefront, double cos_field);
  double at(glm::dvec2 angle_rad) const;

 private:
  int grid_ = 0;
  double k_x_ = 0.0, k_y_ = 0.0;  // phase per radian of angle per unit normalised pupil coordinate
  std::vector<std::complex<double>> phasor_;
  std::vector<int> column_, row_;
  std::vector<glm::dvec2> off_grid_points_;  // with their phasors' OPD (rare: none from trace_wavefront)
  std::vector<double> off_grid_opd_waves_;
  mutable std::vector<std::complex<double>> column_tilt_, row_tilt_;
};

}  // namespace eyetrace::optics
