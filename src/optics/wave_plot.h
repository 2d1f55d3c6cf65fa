// The wave-optics figure of one field (`eyetrace optics --wave --plot DIR`): its MTF curves and
// its PSF as an image, rasterised into RGB (raster.h; the caller writes the file, the optics
// library does no image I/O).
#pragma once

#include <string>
#include <vector>

#include "optics/mtf.h"
#include "optics/psf.h"
#include "optics/raster.h"

namespace eyetrace::optics {

struct WavePlotOptions {
  bool log_psf = true;  // the PSF as log10 of its peak over 3 decades (else linear)
  int width = 960, height = 440;
};

// Left: the MTF against cycles per degree of visual angle, 0 to the tangential cut-off
// D cos(field) / lambda (tangential blue, sagittal red, computed every 1/100 of it; the
// diffraction limit of the disc grey, dashed tangentially off axis), with `markers` (e.g. the
// polychromatic MTF: tangential dark blue and sagittal dark red squares) when given. Right: the PSF around its
// centroid, on the retina in micrometres (square pixels, both axes labelled), out to 3 EE80 radii or 12 samples, black
// = 0, white = its peak. Throws OpticsError for a size below 480 x 240.
RgbImage wave_figure(const Psf& psf, const std::vector<MtfPoint>& markers, const std::string& title,
                     const WavePlotOptions& options = {});

}  // namespace eyetrace::optics
