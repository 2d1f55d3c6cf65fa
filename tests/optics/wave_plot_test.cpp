// The wave figure (optics/wave_plot.h): its size, its refusal of too small a canvas, and where it
// draws: an Airy pattern's peak at the centre of the PSF panel (the panel is centred on the
// centroid), and the MTF curves of an aberration-free pupil on the diffraction limit's pixels.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "../support/unity_id.h"
#include "optics/mtf.h"
#include "optics/optics_error.h"
#include "optics/psf.h"
#include "optics/wave_plot.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

// A zero-OPD pupil of 1.5 mm radius at 555 nm on a 48 grid: the Airy pattern.
Psf airy() {
  WavefrontResult w;
  w.grid = 48;
  w.wavelength_nm = 555.0;
  w.pupil_radius_mm = 1.5;
  for (int i = 0; i < w.grid; ++i)
    for (int j = 0; j < w.grid; ++j) {
      const glm::dvec2 u(-1.0 + (i + 0.5) * 2.0 / w.grid, -1.0 + (j + 0.5) * 2.0 / w.grid);
      if (glm::dot(u, u) <= 1.0) w.pupil_points.push_back(u), w.opd_waves.push_back(0.0);
    }
  return compute_psf(w, {1000.0 / 60.0, 1000.0 / 60.0});
}

TEST(WavePlot, AiryPeakIsAtThePsfPanelsCentre) {
  const RgbImage img = wave_figure(airy(), {}, "airy");
  ASSERT_EQ(img.width, 960);
  ASSERT_EQ(img.height, 440);
  // The PSF panel: a square of the height less the margins (24 above, 34 below), 12 pixels from
  // the right edge; its brightest pixel is white and at its centre.
  const int side = 440 - 24 - 34, x0 = 960 - 12 - side, y0 = 24;
  int best = -1, bx = 0, by = 0;
  for (int y = y0 + 1; y < y0 + side; ++y)
    for (int x = x0 + 1; x < x0 + side; ++x)
      if (img.at(x, y).r > best) best = img.at(x, y).r, bx = x, by = y;
  EXPECT_EQ(best, 255);
  EXPECT_NEAR(bx, x0 + side / 2, 2);
  EXPECT_NEAR(by, y0 + side / 2, 2);
  EXPECT_LT(img.at(x0 + 3, y0 + 3).r, 80);  // the far wing: below 1 % of the peak (log scale: 2 decades)
}

TEST(WavePlot, AberrationFreeCurvesLieOnTheDiffractionLimit) {
  const Psf psf = airy();
  const RgbImage img = wave_figure(psf, {}, "airy");
  // The MTF panel's box: x from 40 to the PSF panel's left less 56, y from 24 to 24 + side.
  const int side = 440 - 24 - 34, x0 = 40, x1 = 960 - 12 - side - 56, y0 = 24, y1 = y0 + side;
  const double cutoff = tangential_cutoff_cpd(psf);
  for (double nu : {0.25, 0.5, 0.75}) {
    const int x = static_cast<int>(x0 + nu * (x1 - x0));
    const double y = y1 - diffraction_limited_mtf(nu) * (y1 - y0);
    // The tangential curve (drawn last, blue) covers the limit's pixels within a pixel or two.
    bool blue = false;
    for (int dy = -3; dy <= 3; ++dy) {
      const Rgb c = img.at(x, static_cast<int>(y) + dy);
      blue = blue || (c.b > 150 && c.r < 80);
    }
    EXPECT_TRUE(blue) << "nu " << nu << " at " << cutoff * nu << " cycles/deg";
  }
}

TEST(WavePlot, TooSmallACanvasIsAnError) {
  WavePlotOptions o;
  o.width = 300;
  EXPECT_THROW(wave_figure(airy(), {}, "x", o), OpticsError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
