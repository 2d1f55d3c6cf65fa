// The polychromatic PSF of one object point, and its Strehl ratio, encircled energy and MTF:
// the monochromatic PSFs (psf.h) of wavelengths across the visible, each traced through the
// model's own dispersion (at_wavelength: the media's laws, the geometry and retina fixed), summed
// on the retina in micrometres with weights V(lambda) x the source's spectral power
// (luminous_efficiency.h; trapezoid rule over the wavelengths, so the sum approximates the
// integral over lambda). Each PSF is of unit energy before weighting, and sits where its chief
// ray meets the retina: the origin is the chief ray's image at the reference wavelength (the
// prescription's), so the chromatic difference of focus (each wavelength's own defocus on the
// fixed retina) and the lateral colour (each chief ray's displacement) both show.
//
// Why not resample the PSFs: each wavelength's FFT samples a different retinal spacing
// (lambda / (N delta) times its own retinal scale), and interpolating a PSF sampled at lambda / 4D
// misses its peak. So the sums are taken where they are exact: the OTF is the weighted sum of the
// wavelengths' OTFs at the same retinal frequency, each times the phase of its displacement; the
// energy within a disc is the weighted sum of each PSF's exact disc integral about the same point
// (encircled_energy.h); the peak is found on the weighted sum of the PSFs summed directly over
// their pupil samples (PsfEvaluator), started from the brightest point of the PSFs resampled onto one
// grid. The Strehl ratio is that peak over the peak of the same weighted sum of the
// diffraction-limited PSFs of the same pupils, all centred on one point (an achromatic perfect
// eye).
#pragma once

#include <complex>
#include <functional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "optics/mtf.h"
#include "optics/prescription.h"
#include "optics/psf.h"
#include "optics/wavefront.h"

namespace eyetrace::optics {

struct PolychromaticOptions {
  double min_wavelength_nm = 400.0;  // wavelengths min, min + step, ..., max (max included)
  double max_wavelength_nm = 700.0;
  double step_nm = 10.0;
  // The source's relative spectral power per nm at a wavelength; empty = equal-energy.
  std::function<double(double)> source;
  std::string source_name = "equal-energy";
};

// Throws OpticsError naming the option when the range is not within [380, 780] nm (where
// V(lambda) is tabulated) and [kMinWavelength_nm, kMaxWavelength_nm], min >= max, or the step is
// not in (0, max - min].
void validate(const PolychromaticOptions& options);

// The wavelengths of the options, min to max every step, max always included.
std::vector<double> polychromatic_wavelengths(const PolychromaticOptions& options);

struct PolychromaticComponent {
  double wavelength_nm = 0.0;
  double weight = 0.0;          // V x source x trapezoid width, normalised so that the weights sum to 1
  glm::dvec2 offset_um{0.0};    // its chief ray's image from the reference's (PSF axes: x sagittal, y tangential)
  glm::dvec2 centroid_um{0.0};  // its PSF's centroid from its own chief ray's image
  double strehl = 0.0;          // its monochromatic Strehl ratio
  int grid = 0, fft_size = 0;
  double sample_x_rad = 0.0, sample_y_rad = 0.0, sample_x_um = 0.0, sample_y_um = 0.0;
  RetinalScale scale;
  std::vector<std::complex<double>> otf_tangential, otf_sagittal;  // axis_otf (mtf.h)
  std::string warning;                                             // its PSF's
};

struct PolychromaticPsf {
  double field_deg = 0.0;
  double reference_wavelength_nm = 0.0;
  RetinalScale reference_scale;  // at the reference wavelength: states the frequencies in cycles/deg
  double pupil_radius_mm = 0.0;  // of the analysis disc (the real stop clips it)
  double cos_field = 1.0;
  std::string source_name;
  std::vector<PolychromaticComponent> components;
  double strehl = 0.0;
  glm::dvec2 peak_um{0.0};      // where the summed PSF peaks, from the reference chief ray's image
  glm::dvec2 centroid_um{0.0};  // the summed PSF's centroid, same origin
  double ee50_um = 0.0, ee80_um = 0.0;
  double energy = 0.0;  // the summed PSF resampled onto one grid, integrated: 1 up to resampling
  // That grid (for pictures): spacing and samples, row-major (y, x), origin at (n/2, n/2), per um^2.
  int image_size = 0;
  double image_sample_x_um = 0.0, image_sample_y_um = 0.0;
  std::vector<double> image;
};

// options: the field, object distance, pupil and starting grid of each wavelength's PSF
// (trace_psf; options.wavelength_nm is ignored). Throws OpticsError for invalid options or when a
// wavelength's trace fails (naming the wavelength).
PolychromaticPsf polychromatic_psf(const Prescription& prescription, const WavefrontOptions& options,
                                   const PolychromaticOptions& poly);

// The summed PSF's MTF at each frequency (cycles per degree of visual angle, converted to the
// retina at the reference wavelength's scale; the cycles/mm keys are those retinal frequencies).
// A wavelength contributes 0 beyond its own cut-off; no frequency is an error but a negative one.
std::vector<MtfPoint> polychromatic_mtf(const PolychromaticPsf& psf, const std::vector<double>& freqs_cpd);

// The same weighted sum of the diffraction-limited MTFs of the wavelengths' pupils (each at the
// same retinal frequency): the limit an achromatic perfect eye with this pupil would reach.
MtfPoint polychromatic_diffraction_limit(const PolychromaticPsf& psf, double freq_cpd);

}  // namespace eyetrace::optics
