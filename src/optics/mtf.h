// Modulation transfer function of a PSF (psf.h), tangential and sagittal, in cycles per degree of
// visual angle in object space and in cycles per mm on the retina, and the diffraction limit.
//
// Method: the optical transfer function along one axis is the Fourier transform of the PSF's
// line-spread function (the PSF summed across that axis; the projection-slice theorem), taken at
// integer FFT frequencies k, and |OTF(k)| / OTF(0) is interpolated linearly in k. Frequency k is
// the pupil's autocorrelation at a shear of k pupil samples (the FFT-size padding of psf.h is at
// least twice the pupil, so the discrete autocorrelation does not wrap): in object space k
// delta / lambda cycles per radian sagittally, k delta cos(theta) / lambda tangentially (the
// pupil foreshortened in the meridian). This is vision science's definition (the autocorrelation
// of the pupil function over the entrance pupil at a shear of lambda x frequency); the tests
// compare it with a direct autocorrelation of the pupil samples.
#pragma once

#include <complex>
#include <vector>

#include "optics/psf.h"

namespace eyetrace::optics {

struct MtfPoint {
  double freq_cpd = 0.0;
  double tangential = 0.0;             // frequency along the field's meridian (y)
  double sagittal = 0.0;               // frequency across it (x)
  double tangential_cyc_per_mm = 0.0;  // the same frequencies on the retina
  double sagittal_cyc_per_mm = 0.0;
};

// Incoherent cut-off D / lambda in cycles per degree: sagittal, and tangential (times cos theta).
double sagittal_cutoff_cpd(const Psf& psf);
double tangential_cutoff_cpd(const Psf& psf);

// MTF at each frequency (cycles per degree, >= 0), normalised to 1 at zero frequency. Throws
// OpticsError naming the limit for a frequency beyond the sagittal cut-off D / lambda (where the
// MTF is 0 by diffraction, whatever the aberrations). Between the tangential cut-off and that the
// tangential MTF is 0 (the foreshortened pupil's autocorrelation has no support there).
std::vector<MtfPoint> compute_mtf(const Psf& psf, const std::vector<double>& freqs_cpd);

// The optical transfer function along one axis (tangential: frequencies along y) at the FFT
// frequencies k = 0 .. N/2 (k / (N sample) cycles per radian), normalised to 1 at 0, its phase
// about the PSF's zero angle (the chief ray's image): a PSF moved by d has its OTF times
// exp(-2 pi i k d / (N sample)). The MTF is its modulus.
std::vector<std::complex<double>> axis_otf(const Psf& psf, bool tangential);

// The diffraction-limited MTF of a uniform circular pupil at nu = frequency / cut-off in [0, 1]:
// (2 / pi) (acos nu - nu sqrt(1 - nu^2)); 0 beyond.
double diffraction_limited_mtf(double nu);

}  // namespace eyetrace::optics
