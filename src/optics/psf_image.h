// The PSF's intensity samples alone: compute_psf (psf.h) without the Strehl ratio, centroid,
// encircled energy and retinal scale, which cost about three quarters of its time. For tables of
// many PSFs (the diffracting camera, cameras/wave_psf_table.h). Same pupil function, FFT size
// (automatic), sample spacing and units as compute_psf; tested equal to it. Defined in psf.cpp,
// beside compute_psf's steps that it shares.
#pragma once

#include <vector>

#include "optics/wavefront.h"

namespace eyetrace::optics {

struct PsfImage {
  int fft_size = 0;
  double sample_x_rad = 0.0, sample_y_rad = 0.0;  // sagittal, tangential (object space)
  double max_phase_step_rad = 0.0;                // > pi/2: the grid is too coarse (psf.h)
  std::vector<double> intensity;                  // row-major (y, x), zero angle at (N/2, N/2)
  double at(int ix, int iy) const { return intensity[static_cast<size_t>(iy) * fft_size + ix]; }
};

// Throws OpticsError when the wavefront has no samples on its grid.
PsfImage psf_image(const WavefrontResult& wavefront);

}  // namespace eyetrace::optics
