// Encircled energy of a PSF (psf.h): the radius on the retina of the circle about the PSF's
// centroid that holds a given fraction of its energy, and the same for a weighted sum of PSFs
// with their own centres (the polychromatic PSF, polychromatic_psf.h).
//
// Method: the PSF is band-limited (its spectrum is the pupil's autocorrelation, zero beyond a
// shear of the pupil's diameter) and periodic over its FFT window, so it is the finite Fourier
// series of its samples, and its integral over a disc of radius r centred at c is exact in
// closed form: (1 / A) sum_k I_k exp(2 pi i f_k.c) r J1(2 pi r |f_k|) / |f_k| (pi r^2 at f = 0),
// I_k the DFT of the samples, A the window's area, f_k its frequencies in cycles per um on the
// retina (the sagittal and tangential sample sizes may differ). Summing pixel values instead
// treats a sample as constant over its pixel, which blurs the PSF by the pixel: the 50 % and 80 %
// radii of the Airy pattern came out 1 to 5 % large at lambda / 4D and lambda / 8D sampling.
// The frequencies are binned by |f| (bins a quarter of the frequency spacing) so that one radius
// costs a few hundred Bessel functions a step; the fraction is found by safeguarded Newton steps.
#pragma once

#include <complex>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "optics/psf.h"

namespace eyetrace::optics {

// Radii (um on the retina) for each fraction in (0, 1); throws OpticsError for other fractions.
std::vector<double> encircled_energy_radii(const Psf& psf, const std::vector<double>& fractions);
double encircled_energy_radius(const Psf& psf, double fraction);

// The fraction of the PSF's energy within radius_um of its centroid.
double encircled_energy(const Psf& psf, double radius_um);

// The low frequencies of a PSF's Fourier series (PsfSpectrum, psf.h): the one compute_psf made
// from the pupil, or else from the PSF's samples.
PsfSpectrum psf_spectrum(const Psf& psf);

// The energy within discs about one point of a weighted sum of PSFs, each given by its spectrum
// and where that point lies in its own coordinates (um on the retina from its zero angle).
class DiscEnergy {
 public:
  explicit DiscEnergy(double bin_cycles_per_um) : bin_(bin_cycles_per_um) {}
  // Adds weight x (the PSF's energy fraction) to the sum; the weights should sum to 1.
  void add(const PsfSpectrum& spectrum, glm::dvec2 centre_um, double weight);
  double fraction(double radius_um) const;
  std::pair<double, double> fraction_and_slope(double radius_um) const;  // and d fraction / d radius
  // The radius holding `fraction` in [0, max_radius_um] (safeguarded Newton steps).
  double radius(double fraction, double max_radius_um) const;

 private:
  double bin_;
  double zero_ = 0.0;  // sum of weight / A: the f = 0 term per um^2
  std::vector<double> weight_, rho_sum_, count_;
};

}  // namespace eyetrace::optics
