// The pupil-function FFT of psf.cpp, restated here because psf.cpp keeps its steps private.
#include "optics/psf_image.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "optics/fft.h"
#include "optics/optics_error.h"

namespace eyetrace::optics {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// As compute_psf: the smallest power of two >= 4 grid (lambda / 4D), or >= 2 grid above 2048.
int automatic_fft_size(int grid) {
  int n = 1;
  while (n < 4 * grid) n *= 2;
  if (n <= 2048) return n;
  n = 1;
  while (n < 2 * grid) n *= 2;
  return n;
}

int cell_index(double u, int grid) { return static_cast<int>(std::lround((u + 1.0) * 0.5 * grid - 0.5)); }

}  // namespace

PsfImage psf_image(const WavefrontResult& w) {
  if (w.grid < 8 || w.pupil_points.empty() || w.pupil_points.size() != w.opd_waves.size())
    throw OpticsError("psf: the wavefront has no samples on a grid");
  PsfImage out;
  const int n = out.fft_size = automatic_fft_size(w.grid);
  const double spacing = 2.0 * w.pupil_radius_mm / w.grid;
  out.sample_x_rad = w.wavelength_nm * 1e-6 / (n * spacing);
  out.sample_y_rad = out.sample_x_rad / std::cos(w.field_deg * std::numbers::pi / 180.0);
  // Phase on the grid (NaN outside the pupil), its largest step between neighbours, then the
  // zero-padded pupil function.
  std::vector<double> phase(static_cast<size_t>(w.grid) * w.grid, std::nan(""));
  for (size_t i = 0; i < w.pupil_points.size(); ++i) {
    const int ix = cell_index(w.pupil_points[i].x, w.grid), iy = cell_index(w.pupil_points[i].y, w.grid);
    if (ix < 0 || iy < 0 || ix >= w.grid || iy >= w.grid)
      throw OpticsError("psf: a wavefront sample lies off its grid");
    phase[static_cast<size_t>(iy) * w.grid + ix] = kTwoPi * w.opd_waves[i];
  }
  FftBuffer buffer(static_cast<size_t>(n) * n);
  for (int y = 0; y < w.grid; ++y)
    for (int x = 0; x < w.grid; ++x) {
      const double p = phase[static_cast<size_t>(y) * w.grid + x];
      if (std::isnan(p)) continue;
      if (x + 1 < w.grid)
        out.max_phase_step_rad =
            std::max(out.max_phase_step_rad, std::abs(phase[static_cast<size_t>(y) * w.grid + x + 1] - p));
      if (y + 1 < w.grid)
        out.max_phase_step_rad =
            std::max(out.max_phase_step_rad, std::abs(phase[static_cast<size_t>(y + 1) * w.grid + x] - p));
      buffer.data[static_cast<size_t>(y) * n + x] = std::polar(1.0, p);
    }
  fft2_in_place(buffer.data, n);
  const double samples = static_cast<double>(w.pupil_points.size());
  const double norm = 1.0 / (samples * samples);
  out.intensity.resize(static_cast<size_t>(n) * n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      out.intensity[static_cast<size_t>((y + n / 2) % n) * n + (x + n / 2) % n] =
          std::norm(buffer.data[static_cast<size_t>(y) * n + x]) * norm;
  return out;
}

}  // namespace eyetrace::optics
