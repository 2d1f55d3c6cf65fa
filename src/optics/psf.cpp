// PSF by FFT of the pupil function, Strehl ratio and encircled energy (see psf.h).
#include "optics/psf.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <tuple>

#include <glm/geometric.hpp>

#include <fmt/format.h>

#include "optics/chromatic.h"
#include "optics/constants.h"
#include "optics/encircled_energy.h"
#include "optics/fft.h"
#include "optics/optics_error.h"
#include "optics/psf_image.h"

namespace eyetrace::optics {

namespace {

int automatic_fft_size(int grid) {
  int n = 1;
  while (n < 4 * grid) n *= 2;
  if (n <= 2048) return n;
  n = 1;
  while (n < 2 * grid) n *= 2;
  return n;
}

// Grid index of a normalised pupil coordinate (cell centres at -1 + (i + 0.5) 2 / grid).
int cell_index(double u, int grid) { return static_cast<int>(std::lround((u + 1.0) * 0.5 * grid - 0.5)); }

// The pupil's phase on its grid (NaN outside the traced samples), row-major (y, x).
std::vector<double> phase_grid(const WavefrontResult& w) {
  std::vector<double> phase(static_cast<size_t>(w.grid) * w.grid, std::nan(""));
  for (size_t i = 0; i < w.pupil_points.size(); ++i) {
    const int ix = cell_index(w.pupil_points[i].x, w.grid), iy = cell_index(w.pupil_points[i].y, w.grid);
    if (ix < 0 || iy < 0 || ix >= w.grid || iy >= w.grid)
      throw OpticsError("psf: a wavefront sample lies off its grid (was the grid changed after the trace?)");
    phase[static_cast<size_t>(iy) * w.grid + ix] = kTwoPi * w.opd_waves[i];
  }
  return phase;
}

// Largest phase difference between neighbouring samples (both in the pupil): above pi the
// phase is aliased, and the PSF's geometric extent exceeds its FFT period lambda / delta.
double max_phase_step(const std::vector<double>& phase, int grid) {
  double worst = 0.0;
  for (int y = 0; y < grid; ++y)
    for (int x = 0; x < grid; ++x) {
      const double p = phase[static_cast<size_t>(y) * grid + x];
      if (x + 1 < grid) worst = std::max(worst, std::abs(phase[static_cast<size_t>(y) * grid + x + 1] - p));
      if (y + 1 < grid) worst = std::max(worst, std::abs(phase[static_cast<size_t>(y + 1) * grid + x] - p));
    }
  return worst;  // NaN comparisons are false: pairs with a point outside the pupil are skipped
}

// |FFT|^2 of the zero-padded pupil function, shifted so that the zero angle is at (N/2, N/2),
// in units of the diffraction-limited peak (pupil_samples^2).
std::vector<double> fft_intensity(const std::vector<double>& phase, int grid, int n, int samples) {
  FftBuffer buffer(static_cast<size_t>(n) * n);
  std::complex<double>* data = buffer.data;
  for (int y = 0; y < grid; ++y)
    for (int x = 0; x < grid; ++x) {
      const double p = phase[static_cast<size_t>(y) * grid + x];
      if (std::isnan(p)) continue;
      data[static_cast<size_t>(y) * n + x] = std::polar(1.0, p);
    }
  fft2_in_place(data, n, grid);  // the pupil fills the first `grid` rows
  const double norm = 1.0 / (static_cast<double>(samples) * samples);
  std::vector<double> out(static_cast<size_t>(n) * n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      out[static_cast<size_t>((y + n / 2) % n) * n + (x + n / 2) % n] =
          std::norm(data[static_cast<size_t>(y) * n + x]) * norm;
    }
  return out;
}

// The PSF's spectrum for the encircled energy: the pupil's autocorrelation, by two FFTs of size
// M, the smallest power of two >= 2 grid (no wrap: the autocorrelation reaches grid - 1 samples),
// instead of the FFT of the N x N PSF (N >= 4 grid: 4 to 16 times the work). The M-sample PSF
// |FFT(pupil)|^2 has the same Fourier coefficients up to |k| < M / 2, with its zero angle at 0.
PsfSpectrum pupil_spectrum(const std::vector<double>& phase, int grid, double window_x_um, double window_y_um) {
  int m = 1;
  while (m < 2 * grid) m *= 2;
  FftBuffer buffer(static_cast<size_t>(m) * m);
  std::complex<double>* data = buffer.data;
  for (int y = 0; y < grid; ++y)
    for (int x = 0; x < grid; ++x) {
      const double p = phase[static_cast<size_t>(y) * grid + x];
      if (!std::isnan(p)) data[static_cast<size_t>(y) * m + x] = std::polar(1.0, p);
    }
  fft2_in_place(data, m, grid);
  for (size_t i = 0; i < static_cast<size_t>(m) * m; ++i) data[i] = std::norm(data[i]);
  fft2_in_place(data, m);
  PsfSpectrum s;
  s.window_x_um = window_x_um, s.window_y_um = window_y_um;
  s.reach = std::min(grid, m / 2 - 1);
  const double scale = 1.0 / (data[0].real() * window_x_um * window_y_um);
  const int side = 2 * s.reach + 1;
  s.terms.resize(static_cast<size_t>(side) * side);
  for (int ky = -s.reach; ky <= s.reach; ++ky)
    for (int kx = -s.reach; kx <= s.reach; ++kx)
      s.terms[static_cast<size_t>(ky + s.reach) * side + (kx + s.reach)] =
          data[static_cast<size_t>((ky + m) % m) * m + (kx + m) % m] * scale;
  return s;
}

// The PSF's peak, located between samples: from the brightest sample, parabolic steps on the
// exactly summed PSF with a halving stencil (the sampled maximum alone can be 8 % low at lambda/4D).
std::pair<double, glm::dvec2> refine_peak(const WavefrontResult& w, const Psf& psf) {
  const auto brightest = std::max_element(psf.intensity.begin(), psf.intensity.end()) - psf.intensity.begin();
  const int n = psf.fft_size;
  glm::dvec2 a((brightest % n - n / 2) * psf.sample_x_rad, (brightest / n - n / 2) * psf.sample_y_rad);
  glm::dvec2 h(0.5 * psf.sample_x_rad, 0.5 * psf.sample_y_rad);
  const PsfEvaluator evaluate(w, psf.cos_field);
  double best = evaluate.at(a);
  for (int iteration = 0; iteration < 8; ++iteration, h *= 0.5)
    for (int axis = 0; axis < 2; ++axis) {
      glm::dvec2 step(0.0);
      step[axis] = h[axis];
      const double minus = evaluate.at(a - step), plus = evaluate.at(a + step);
      const double curvature = plus + minus - 2.0 * best;
      const double t = curvature < 0.0 ? std::clamp(0.5 * (minus - plus) / curvature, -1.0, 1.0) : 0.0;
      const double moved = evaluate.at(a + t * step);
      if (moved > best) best = moved, a += t * step;
    }
  return {best, a};
}

glm::dvec2 centroid(const Psf& psf) {
  const int n = psf.fft_size;
  double sum = 0.0;
  glm::dvec2 c(0.0);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double v = psf.at(x, y);
      sum += v;
      c += v * glm::dvec2((x - n / 2) * psf.sample_x_rad, (y - n / 2) * psf.sample_y_rad);
    }
  return c / sum;
}

}  // namespace

RetinalScale retinal_scale(const Prescription& p, double field_deg, double object_distance_m, double wavelength_nm) {
  const double lambda = wavelength_nm == 0.0 ? p.wavelength_nm : wavelength_nm;
  const Prescription p_lambda = lambda == p.wavelength_nm ? p : at_wavelength(p, lambda);
  const double h_deg = 0.05;  // small enough for the local slope, large against the chief ray's 1e-12 mm aim
  auto image = [&](double field) {
    const ChiefRay c = trace_chief_ray(p_lambda, field, object_distance_m, &p);
    if (!c.ok) throw OpticsError(fmt::format("psf: field {} deg: chief ray lost: {}", field, c.lost));
    return c.image_mm;
  };
  const double h_rad = h_deg * std::numbers::pi / 180.0;
  RetinalScale s;
  s.tangential_mm_per_rad = glm::distance(image(field_deg + h_deg), image(field_deg - h_deg)) / (2.0 * h_rad);
  // Turning the object about the axis by phi moves it sin(theta) phi in angle and its image by
  // rho phi (rho: the image's distance from the axis); on the axis the two scales are one.
  const double theta = field_deg * std::numbers::pi / 180.0;
  if (std::abs(field_deg) < 0.5) {
    s.sagittal_mm_per_rad = s.tangential_mm_per_rad;
  } else {
    const glm::dvec3 i = image(field_deg);
    s.sagittal_mm_per_rad = std::hypot(i.x, i.y) / std::abs(std::sin(theta));
  }
  return s;
}

double max_phase_step_rad(const WavefrontResult& w) { return max_phase_step(phase_grid(w), w.grid); }

TracedPsf trace_psf(const Prescription& p, const WavefrontOptions& options, int max_grid) {
  WavefrontOptions o = options;
  o.clip_at_stop = true;
  o.fit_zernike = false;  // the PSF needs the OPD samples only
  TracedPsf t{trace_wavefront(p, o), {}};
  // The phase steps decide the grid before any PSF is made (compute_psf warns on the same limit).
  for (double step = max_phase_step_rad(t.wavefront); step > 0.5 * std::numbers::pi && o.grid < max_grid;
       step = max_phase_step_rad(t.wavefront)) {
    const double needed = o.grid * step / (0.5 * std::numbers::pi);
    o.grid = std::min(max_grid, 16 * static_cast<int>(std::ceil(needed / 16.0)));
    t.wavefront = trace_wavefront(p, o);
  }
  t.psf = compute_psf(t.wavefront, retinal_scale(p, o.field_deg, o.object_distance_m, o.wavelength_nm));
  return t;
}

double psf_at(const WavefrontResult& w, double cos_field, glm::dvec2 angle_rad) {
  // Tilt phase 2 pi (a_x X + a_y cos(theta) Y) / lambda, X, Y in mm on the entrance-pupil plane;
  // the sign matches FFTW's forward transform, so this is the FFT's PSF between its samples.
  const double k = kTwoPi / (w.wavelength_nm * 1e-6) * w.pupil_radius_mm;
  const double kx = k * angle_rad.x, ky = k * angle_rad.y * cos_field;
  std::complex<double> sum(0.0);
  for (size_t i = 0; i < w.pupil_points.size(); ++i)
    sum += std::polar(1.0, kTwoPi * w.opd_waves[i] - kx * w.pupil_points[i].x - ky * w.pupil_points[i].y);
  const double m = static_cast<double>(w.pupil_points.size());
  return std::norm(sum) / (m * m);
}

PsfEvaluator::PsfEvaluator(const WavefrontResult& w, double cos_field) : grid_(w.grid) {
  const double k = kTwoPi / (w.wavelength_nm * 1e-6) * w.pupil_radius_mm;
  k_x_ = k, k_y_ = k * cos_field;
  for (size_t i = 0; i < w.pupil_points.size(); ++i) {
    const glm::dvec2 u = w.pupil_points[i];
    const int ix = cell_index(u.x, grid_), iy = cell_index(u.y, grid_);
    auto centre = [this](int i) { return -1.0 + (i + 0.5) * 2.0 / grid_; };
    if (ix >= 0 && iy >= 0 && ix < grid_ && iy < grid_ && std::abs(centre(ix) - u.x) < 1e-12 &&
        std::abs(centre(iy) - u.y) < 1e-12) {
      phasor_.push_back(std::polar(1.0, kTwoPi * w.opd_waves[i]));
      column_.push_back(ix), row_.push_back(iy);
    } else {
      off_grid_points_.push_back(u), off_grid_opd_waves_.push_back(w.opd_waves[i]);
    }
  }
  column_tilt_.resize(static_cast<size_t>(std::max(grid_, 0))), row_tilt_.resize(column_tilt_.size());
}

double PsfEvaluator::at(glm::dvec2 a) const {
  // Tilt phase as psf_at: -(k_x a_x X + k_y a_y Y), X and Y the normalised cell centres.
  for (int i = 0; i < grid_; ++i) {
    const double u = -1.0 + (i + 0.5) * 2.0 / grid_;
    column_tilt_[static_cast<size_t>(i)] = std::polar(1.0, -k_x_ * a.x * u);
    row_tilt_[static_cast<size_t>(i)] = std::polar(1.0, -k_y_ * a.y * u);
  }
  std::complex<double> sum(0.0);
  for (size_t s = 0; s < phasor_.size(); ++s)
    sum += phasor_[s] * column_tilt_[static_cast<size_t>(column_[s])] * row_tilt_[static_cast<size_t>(row_[s])];
  for (size_t s = 0; s < off_grid_points_.size(); ++s)
    sum += std::polar(
        1.0, kTwoPi * off_grid_opd_waves_[s] - k_x_ * a.x * off_grid_points_[s].x - k_y_ * a.y * off_grid_points_[s].y);
  const double m = static_cast<double>(phasor_.size() + off_grid_points_.size());
  return std::norm(sum) / (m * m);
}

PsfImage psf_image(const WavefrontResult& w) {
  if (w.grid < 8 || w.pupil_points.empty() || w.pupil_points.size() != w.opd_waves.size())
    throw OpticsError("psf: the wavefront has no samples on a grid");
  PsfImage out;
  out.fft_size = automatic_fft_size(w.grid);
  out.sample_x_rad = w.wavelength_nm * 1e-6 / (out.fft_size * (2.0 * w.pupil_radius_mm / w.grid));
  out.sample_y_rad = out.sample_x_rad / std::cos(w.field_deg * std::numbers::pi / 180.0);
  const std::vector<double> phase = phase_grid(w);
  out.max_phase_step_rad = max_phase_step(phase, w.grid);
  out.intensity = fft_intensity(phase, w.grid, out.fft_size, static_cast<int>(w.pupil_points.size()));
  return out;
}

Psf compute_psf(const WavefrontResult& w, const RetinalScale& scale, const PsfOptions& o) {
  if (w.grid < 8 || w.pupil_points.empty() || w.pupil_points.size() != w.opd_waves.size())
    throw OpticsError("psf: the wavefront has no samples on a grid");
  if (o.fft_size != 0 && (o.fft_size < 2 * w.grid || o.fft_size > 8192))
    throw OpticsError(fmt::format("psf: FFT size {} must be 0 (automatic) or in [2 grid, 8192] = [{}, 8192]",
                                  o.fft_size, 2 * w.grid));
  Psf psf;
  psf.grid = w.grid;
  psf.fft_size = o.fft_size == 0 ? automatic_fft_size(w.grid) : o.fft_size;
  psf.pupil_samples = static_cast<int>(w.pupil_points.size());
  psf.wavelength_nm = w.wavelength_nm;
  psf.pupil_radius_mm = w.pupil_radius_mm;
  psf.pupil_spacing_mm = 2.0 * w.pupil_radius_mm / w.grid;
  psf.cos_field = std::cos(w.field_deg * std::numbers::pi / 180.0);
  psf.scale = scale;
  const double lambda_mm = w.wavelength_nm * 1e-6;
  psf.sample_x_rad = lambda_mm / (psf.fft_size * psf.pupil_spacing_mm);
  psf.sample_y_rad = psf.sample_x_rad / psf.cos_field;
  psf.sample_x_um = psf.sample_x_rad * scale.sagittal_mm_per_rad * 1000.0;
  psf.sample_y_um = psf.sample_y_rad * scale.tangential_mm_per_rad * 1000.0;

  const std::vector<double> phase = phase_grid(w);
  psf.max_phase_step_rad = max_phase_step(phase, w.grid);
  if (psf.max_phase_step_rad > 0.5 * std::numbers::pi)
    psf.warning = fmt::format(
        "the pupil grid ({} across) is too coarse for this wavefront: neighbouring samples differ by up "
        "to {:.2f} rad of phase (limit pi/2); the PSF wraps around its {:.1f} arcmin period, raise the grid "
        "to at least {}",
        w.grid, psf.max_phase_step_rad, psf.sample_x_rad * psf.fft_size * 60.0 * 180.0 / std::numbers::pi,
        static_cast<int>(std::ceil(w.grid * psf.max_phase_step_rad / (0.5 * std::numbers::pi))));
  psf.intensity = fft_intensity(phase, w.grid, psf.fft_size, psf.pupil_samples);
  psf.spectrum = pupil_spectrum(phase, w.grid, psf.fft_size * psf.sample_x_um, psf.fft_size * psf.sample_y_um);
  std::tie(psf.strehl, psf.peak_rad) = refine_peak(w, psf);
  psf.strehl_phasor = psf_at(w, psf.cos_field, glm::dvec2(0.0));
  psf.centroid_rad = centroid(psf);
  const std::vector<double> ee = encircled_energy_radii(psf, {0.5, 0.8});
  psf.ee50_um = ee[0], psf.ee80_um = ee[1];
  return psf;
}

}  // namespace eyetrace::optics
