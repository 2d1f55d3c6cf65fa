// The diffraction part of the optics report's wave section (report.h): per field, the PSF's
// Strehl ratio, encircled energy and sampling, and the MTF at the report's frequencies, as JSON
// and as text.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "optics/polychromatic_psf.h"
#include "optics/prescription.h"
#include "optics/wavefront.h"

namespace eyetrace::optics {

// Throws OpticsError naming the limit when a frequency is negative or beyond the diffraction
// cut-off D / lambda of the analysis' pupil and wavelength (the same for every field).
void check_mtf_frequencies(const Prescription& prescription, const WavefrontOptions& options,
                           const std::vector<double>& freqs_cpd);

// Keys: strehl, strehl_at_chief_ray, ee50_um, ee80_um, mtf [{freq_cpd, tangential, sagittal,
// tangential_cyc_per_mm, sagittal_cyc_per_mm}], psf {grid, fft_size, pupil_samples, rays_clipped,
// sample_arcmin [sagittal, tangential], sample_um [sagittal, tangential], retina_mm_per_deg
// [sagittal, tangential], cutoff_cpd [sagittal, tangential]} and psf_warning when the grid is
// too coarse or the iris clips much of the disc. The wavefront is traced again with the real
// stop clipping (the pupil of the PSF is the real one), on a grid refined from options.grid
// until the pupil's phase is sampled finely enough (psf.h's limit; at most 512 across);
// options.field_deg is the field.
// Throws OpticsError when the analysis fails (the report turns it into the field's error).
nlohmann::json wave_optics_json(const Prescription& prescription, const WavefrontOptions& options,
                                const std::vector<double>& freqs_cpd);

// The polychromatic object of one field (polychromatic_psf.h; options.field_deg is the field):
// wavelengths_nm {min, max, step, count}, source, reference_wavelength_nm, strehl, ee50_um,
// ee80_um, centroid_um and peak_um [sagittal, tangential] (from the reference wavelength's chief
// ray's image: the lateral colour), grid_max (the finest pupil grid a wavelength needed), mtf
// [{freq_cpd, tangential, sagittal, tangential_cyc_per_mm, sagittal_cyc_per_mm,
// diffraction_limit [sagittal, tangential]}], and psf_warning when a wavelength's PSF has one.
// Throws OpticsError when the analysis fails.
nlohmann::json polychromatic_json(const Prescription& prescription, const WavefrontOptions& options,
                                  const PolychromaticOptions& poly, const std::vector<double>& freqs_cpd);

// Two or three lines of text for one field's entry (with the keys above).
std::string format_wave_optics(const nlohmann::json& field);

}  // namespace eyetrace::optics
