// Polychromatic PSF, Strehl ratio, encircled energy and MTF (see polychromatic_psf.h).
#include "optics/polychromatic_psf.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "optics/chromatic.h"
#include "optics/constants.h"
#include "optics/encircled_energy.h"
#include "optics/luminous_efficiency.h"
#include "optics/medium.h"
#include "optics/optics_error.h"

namespace eyetrace::optics {

namespace {

// One wavelength's PSF as the sum needs it, beside the component's summary: its pupil's phasors
// (for the peak between samples) and its low-frequency spectrum (for the encircled energy).
struct Part {
  PsfEvaluator evaluator;
  PsfSpectrum spectrum;
  double peak_density = 0.0;  // its diffraction-limited peak per um^2 at unit energy
};

// The chief ray's image of the field at a wavelength (the object point fixed by p's own pupil).
ChiefRay chief_ray_at(const Prescription& p, const WavefrontOptions& o, double lambda) {
  const ChiefRay c =
      trace_chief_ray(lambda == p.wavelength_nm ? p : at_wavelength(p, lambda), o.field_deg, o.object_distance_m, &p);
  if (!c.ok)
    throw OpticsError(
        fmt::format("polychromatic PSF: field {} deg at {} nm: chief ray lost: {}", o.field_deg, lambda, c.lost));
  return c;
}

// Where a chief ray's image lies from the reference's, in the PSF's axes (um). Tangentially: a
// wavefront leading the reference sphere at +y of the pupil moves the PSF to +y in angle (psf_at),
// towards larger field angles, which image farther out on the side image_coordinate_mm counts
// positive (a positive field images at -y); tested against the real-ray spot's centroid. x: the
// OSA axis is the prescription's mirrored.
glm::dvec2 displacement_um(const ChiefRay& c, const ChiefRay& ref) {
  return {-1000.0 * (c.image_mm.x - ref.image_mm.x), 1000.0 * (c.image_coordinate_mm - ref.image_coordinate_mm)};
}

// Unit-energy PSF of a part (per um^2) at a retinal point (um from its own chief ray's image).
double density_at(const Part& part, const PolychromaticComponent& c, glm::dvec2 um) {
  const glm::dvec2 rad(um.x / (c.scale.sagittal_mm_per_rad * 1000.0), um.y / (c.scale.tangential_mm_per_rad * 1000.0));
  return part.peak_density * part.evaluator.at(rad);
}

double summed_density(const std::vector<Part>& parts, const PolychromaticPsf& out, glm::dvec2 um) {
  double sum = 0.0;
  for (size_t i = 0; i < parts.size(); ++i) {
    const PolychromaticComponent& c = out.components[i];
    sum += c.weight * density_at(parts[i], c, um - c.offset_um);
  }
  return sum;
}

// The PSFs resampled (bilinearly) onto the grid of the heaviest component, summed: for the
// starting point of the peak search, the energy check and pictures.
void resample(const std::vector<Psf>& psfs, PolychromaticPsf& out) {
  const auto heaviest = std::max_element(out.components.begin(), out.components.end(),
                                         [](const auto& a, const auto& b) { return a.weight < b.weight; });
  const PolychromaticComponent& h = *heaviest;
  const int n = out.image_size = h.fft_size;
  out.image_sample_x_um = h.sample_x_um, out.image_sample_y_um = h.sample_y_um;
  out.image.assign(static_cast<size_t>(n) * n, 0.0);
  for (size_t i = 0; i < psfs.size(); ++i) {
    const Psf& psf = psfs[i];
    const PolychromaticComponent& c = out.components[i];
    const int m = psf.fft_size;
    // Unit energy: the samples sum to m^2 / pupil_samples (psf.h), each sample covers sx sy um^2.
    const double norm = c.weight * psf.pupil_samples / (static_cast<double>(m) * m * psf.sample_x_um * psf.sample_y_um);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const double u = ((x - n / 2) * h.sample_x_um - c.offset_um.x) / psf.sample_x_um + m / 2;
        const double v = ((y - n / 2) * h.sample_y_um - c.offset_um.y) / psf.sample_y_um + m / 2;
        const int iu = static_cast<int>(std::floor(u)), iv = static_cast<int>(std::floor(v));
        if (iu < 0 || iv < 0 || iu + 1 >= m || iv + 1 >= m) continue;
        const double tu = u - iu, tv = v - iv;
        const double value = (1 - tv) * ((1 - tu) * psf.at(iu, iv) + tu * psf.at(iu + 1, iv)) +
                             tv * ((1 - tu) * psf.at(iu, iv + 1) + tu * psf.at(iu + 1, iv + 1));
        out.image[static_cast<size_t>(y) * n + x] += norm * value;
      }
  }
  double sum = 0.0;
  for (double v : out.image) sum += v;
  out.energy = sum * out.image_sample_x_um * out.image_sample_y_um;
}

// Parabolic steps with a halving stencil from the image's brightest sample, on the exact sum.
void find_peak(const std::vector<Part>& parts, PolychromaticPsf& out) {
  const int n = out.image_size;
  const auto brightest = std::max_element(out.image.begin(), out.image.end()) - out.image.begin();
  glm::dvec2 a((brightest % n - n / 2) * out.image_sample_x_um, (brightest / n - n / 2) * out.image_sample_y_um);
  glm::dvec2 h(0.5 * out.image_sample_x_um, 0.5 * out.image_sample_y_um);
  double best = summed_density(parts, out, a);
  for (int iteration = 0; iteration < 8; ++iteration, h *= 0.5)
    for (int axis = 0; axis < 2; ++axis) {
      glm::dvec2 step(0.0);
      step[axis] = h[axis];
      const double minus = summed_density(parts, out, a - step), plus = summed_density(parts, out, a + step);
      const double curvature = plus + minus - 2.0 * best;
      const double t = curvature < 0.0 ? std::clamp(0.5 * (minus - plus) / curvature, -1.0, 1.0) : 0.0;
      const double moved = summed_density(parts, out, a + t * step);
      if (moved > best) best = moved, a += t * step;
    }
  double limit = 0.0;
  for (size_t i = 0; i < parts.size(); ++i) limit += out.components[i].weight * parts[i].peak_density;
  out.strehl = best / limit;
  out.peak_um = a;
}

void encircled(const std::vector<Part>& parts, PolychromaticPsf& out) {
  double widest = 0.0, narrowest = 1e300;
  for (const Part& part : parts) {
    widest = std::max({widest, part.spectrum.window_x_um, part.spectrum.window_y_um});
    narrowest = std::min({narrowest, part.spectrum.window_x_um, part.spectrum.window_y_um});
  }
  DiscEnergy energy(0.25 / widest);
  for (size_t i = 0; i < parts.size(); ++i) {
    const PolychromaticComponent& c = out.components[i];
    energy.add(parts[i].spectrum, out.centroid_um - c.offset_um, c.weight);
  }
  out.ee50_um = energy.radius(0.5, 0.5 * narrowest);
  out.ee80_um = energy.radius(0.8, 0.5 * narrowest);
}

// A complex OTF at fractional FFT frequency k: linear interpolation after removing the phase
// ramp of the PSF's centroid (centre_samples from its zero angle), which would otherwise turn the
// value between the integer frequencies. 0 beyond the table (past the cut-off).
std::complex<double> otf_at(const std::vector<std::complex<double>>& otf, double k, double centre_samples, int n) {
  const size_t i = static_cast<size_t>(std::floor(k));
  if (i + 1 >= otf.size()) return 0.0;
  auto flat = [&](size_t j) { return otf[j] * std::polar(1.0, kTwoPi * j * centre_samples / n); };
  const double t = k - static_cast<double>(i);
  return ((1.0 - t) * flat(i) + t * flat(i + 1)) * std::polar(1.0, -kTwoPi * k * centre_samples / n);
}

}  // namespace

void validate(const PolychromaticOptions& o) {
  const double lo = std::max(kPhotopicMin_nm, kMinWavelength_nm), hi = std::min(kPhotopicMax_nm, kMaxWavelength_nm);
  if (!(o.min_wavelength_nm >= lo && o.max_wavelength_nm <= hi && o.min_wavelength_nm < o.max_wavelength_nm))
    throw OpticsError(
        fmt::format("polychromatic range {},{} nm: must be MIN < MAX within [{}, {}] nm (where V(lambda) is tabulated)",
                    o.min_wavelength_nm, o.max_wavelength_nm, lo, hi));
  if (!(o.step_nm > 0.0 && o.step_nm <= o.max_wavelength_nm - o.min_wavelength_nm))
    throw OpticsError(fmt::format("polychromatic step {} nm: must be in (0, {}] nm (the range's width)", o.step_nm,
                                  o.max_wavelength_nm - o.min_wavelength_nm));
}

std::vector<double> polychromatic_wavelengths(const PolychromaticOptions& o) {
  validate(o);
  std::vector<double> out;
  for (int i = 0;; ++i) {
    const double lambda = o.min_wavelength_nm + i * o.step_nm;
    if (lambda >= o.max_wavelength_nm - 1e-9 * o.step_nm) break;
    out.push_back(lambda);
  }
  out.push_back(o.max_wavelength_nm);
  return out;
}

PolychromaticPsf polychromatic_psf(const Prescription& p, const WavefrontOptions& options,
                                   const PolychromaticOptions& poly) {
  const std::vector<double> lambdas = polychromatic_wavelengths(poly);
  PolychromaticPsf out;
  out.field_deg = options.field_deg;
  out.reference_wavelength_nm = p.wavelength_nm;
  out.reference_scale = retinal_scale(p, options.field_deg, options.object_distance_m, p.wavelength_nm);
  out.cos_field = std::cos(options.field_deg * kRadPerDeg);
  out.source_name = poly.source ? poly.source_name : "equal-energy";
  const ChiefRay reference = chief_ray_at(p, options, p.wavelength_nm);

  std::vector<Part> parts;
  std::vector<Psf> psfs;
  double total = 0.0;
  for (size_t i = 0; i < lambdas.size(); ++i) {
    const double lambda = lambdas[i];
    // Trapezoid rule: each wavelength stands for half of each neighbouring interval.
    const double width = 0.5 * ((i + 1 < lambdas.size() ? lambdas[i + 1] : lambda) - (i > 0 ? lambdas[i - 1] : lambda));
    const double source = poly.source ? poly.source(lambda) : 1.0;
    if (!(source >= 0.0 && std::isfinite(source)))
      throw OpticsError(
          fmt::format("polychromatic PSF: the source's power at {} nm is {} (must be >= 0)", lambda, source));
    WavefrontOptions o = options;
    o.wavelength_nm = lambda;
    TracedPsf t = trace_psf(p, o);
    const Psf& psf = t.psf;
    PolychromaticComponent c;
    c.wavelength_nm = lambda;
    c.weight = photopic_luminous_efficiency(lambda) * source * width;
    c.offset_um = displacement_um(chief_ray_at(p, options, lambda), reference);
    c.centroid_um = {psf.centroid_rad.x / psf.sample_x_rad * psf.sample_x_um,
                     psf.centroid_rad.y / psf.sample_y_rad * psf.sample_y_um};
    c.strehl = psf.strehl;
    c.grid = psf.grid, c.fft_size = psf.fft_size;
    c.sample_x_rad = psf.sample_x_rad, c.sample_y_rad = psf.sample_y_rad;
    c.sample_x_um = psf.sample_x_um, c.sample_y_um = psf.sample_y_um;
    c.scale = psf.scale;
    c.otf_tangential = axis_otf(psf, true), c.otf_sagittal = axis_otf(psf, false);
    c.warning = psf.warning;
    out.pupil_radius_mm = psf.pupil_radius_mm;
    total += c.weight;
    out.components.push_back(std::move(c));
    const double m = psf.fft_size;
    parts.push_back({PsfEvaluator(t.wavefront, out.cos_field), psf_spectrum(psf),
                     psf.pupil_samples / (m * m * psf.sample_x_um * psf.sample_y_um)});
    psfs.push_back(std::move(t.psf));
  }
  if (!(total > 0.0))
    throw OpticsError(fmt::format("polychromatic PSF: the weights V(lambda) x source sum to {} over {}-{} nm", total,
                                  poly.min_wavelength_nm, poly.max_wavelength_nm));
  for (PolychromaticComponent& c : out.components) {
    c.weight /= total;
    out.centroid_um += c.weight * (c.centroid_um + c.offset_um);
  }
  resample(psfs, out);
  find_peak(parts, out);
  encircled(parts, out);
  return out;
}

std::vector<MtfPoint> polychromatic_mtf(const PolychromaticPsf& psf, const std::vector<double>& freqs_cpd) {
  std::vector<MtfPoint> out;
  for (double f : freqs_cpd) {
    if (!(f >= 0.0 && std::isfinite(f)))
      throw OpticsError(fmt::format("polychromatic MTF: frequency {} cycles/deg must be >= 0", f));
    MtfPoint m;
    m.freq_cpd = f;
    m.tangential_cyc_per_mm = f / kRadPerDeg / psf.reference_scale.tangential_mm_per_rad;
    m.sagittal_cyc_per_mm = f / kRadPerDeg / psf.reference_scale.sagittal_mm_per_rad;
    std::complex<double> t(0.0), s(0.0);
    for (const PolychromaticComponent& c : psf.components) {
      // The retinal frequency in this wavelength's object-space cycles per radian, then FFT bins.
      const double kt = m.tangential_cyc_per_mm * c.scale.tangential_mm_per_rad * c.fft_size * c.sample_y_rad;
      const double ks = m.sagittal_cyc_per_mm * c.scale.sagittal_mm_per_rad * c.fft_size * c.sample_x_rad;
      const double shift_t = -kTwoPi * m.tangential_cyc_per_mm * c.offset_um.y * 1e-3;
      const double shift_s = -kTwoPi * m.sagittal_cyc_per_mm * c.offset_um.x * 1e-3;
      t += c.weight * otf_at(c.otf_tangential, kt, c.centroid_um.y / c.sample_y_um, c.fft_size) *
           std::polar(1.0, shift_t);
      s +=
          c.weight * otf_at(c.otf_sagittal, ks, c.centroid_um.x / c.sample_x_um, c.fft_size) * std::polar(1.0, shift_s);
    }
    m.tangential = std::abs(t), m.sagittal = std::abs(s);
    out.push_back(m);
  }
  return out;
}

MtfPoint polychromatic_diffraction_limit(const PolychromaticPsf& psf, double f) {
  MtfPoint m;
  m.freq_cpd = f;
  m.tangential_cyc_per_mm = f / kRadPerDeg / psf.reference_scale.tangential_mm_per_rad;
  m.sagittal_cyc_per_mm = f / kRadPerDeg / psf.reference_scale.sagittal_mm_per_rad;
  const double d_mm = 2.0 * psf.pupil_radius_mm;
  for (const PolychromaticComponent& c : psf.components) {
    const double lambda_mm = c.wavelength_nm * 1e-6;
    m.tangential += c.weight * diffraction_limited_mtf(m.tangential_cyc_per_mm * c.scale.tangential_mm_per_rad *
                                                       lambda_mm / (d_mm * psf.cos_field));
    m.sagittal +=
        c.weight * diffraction_limited_mtf(m.sagittal_cyc_per_mm * c.scale.sagittal_mm_per_rad * lambda_mm / d_mm);
  }
  return m;
}

}  // namespace eyetrace::optics
