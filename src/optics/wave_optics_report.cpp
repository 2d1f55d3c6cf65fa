// PSF, Strehl ratio, encircled energy and MTF in the optics report (see wave_optics_report.h).
#include "optics/wave_optics_report.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "optics/mtf.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/psf.h"

namespace eyetrace::optics {

namespace {

using nlohmann::json;

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

double round6(double v) { return std::round(v * 1e6) / 1e6 + 0.0; }

json pair(double sagittal, double tangential) { return json::array({round6(sagittal), round6(tangential)}); }

}  // namespace

void check_mtf_frequencies(const Prescription& p, const WavefrontOptions& o, const std::vector<double>& freqs) {
  const double radius =
      o.pupil_radius_mm > 0.0 ? o.pupil_radius_mm : 0.5 * paraxial_analysis(p).entrance_pupil.diameter_mm;
  const double lambda = o.wavelength_nm == 0.0 ? p.wavelength_nm : o.wavelength_nm;
  const double cutoff = 2.0 * radius / (lambda * 1e-6) * kRadPerDeg;
  for (double f : freqs)
    if (!(f >= 0.0 && f <= cutoff))
      throw OpticsError(fmt::format(
          "MTF frequency {} cycles/deg is beyond the diffraction cut-off {:.1f} cycles/deg (D / lambda: the "
          "{:.3f} mm pupil at {} nm)",
          f, cutoff, 2.0 * radius, lambda));
}

// The pupil grid is refined (up to kMaxAutoGrid) until neighbouring samples differ by at most
// pi/2 of phase: the grid fine enough for the Zernike fit (64) aliases the PSF of an oblique
// field's steep wavefront (Navarro at 20 degrees, 4.5 mm pupil: 4.5 rad steps at 64, EE50 off by 20 %).
constexpr int kMaxAutoGrid = 512;

json wave_optics_json(const Prescription& p, const WavefrontOptions& options, const std::vector<double>& freqs) {
  WavefrontOptions o = options;
  o.clip_at_stop = true;
  const RetinalScale scale = retinal_scale(p, o.field_deg, o.object_distance_m, o.wavelength_nm);
  WavefrontResult w = trace_wavefront(p, o);
  Psf psf = compute_psf(w, scale);
  while (!psf.warning.empty() && o.grid < kMaxAutoGrid) {
    const double needed = o.grid * psf.max_phase_step_rad / (0.5 * std::numbers::pi);
    o.grid = std::min(kMaxAutoGrid, 16 * static_cast<int>(std::ceil(needed / 16.0)));
    w = trace_wavefront(p, o);
    psf = compute_psf(w, scale);
  }
  json mtf = json::array();
  for (const MtfPoint& m : compute_mtf(psf, freqs))
    mtf.push_back({{"freq_cpd", m.freq_cpd},
                   {"tangential", round6(m.tangential)},
                   {"sagittal", round6(m.sagittal)},
                   {"tangential_cyc_per_mm", round6(m.tangential_cyc_per_mm)},
                   {"sagittal_cyc_per_mm", round6(m.sagittal_cyc_per_mm)}});
  const double arcmin = 60.0 / kRadPerDeg;
  json f = {{"strehl", round6(psf.strehl)},
            {"strehl_at_chief_ray", round6(psf.strehl_phasor)},
            {"ee50_um", round6(psf.ee50_um)},
            {"ee80_um", round6(psf.ee80_um)},
            {"mtf", mtf},
            {"psf",
             {{"grid", psf.grid},
              {"fft_size", psf.fft_size},
              {"pupil_samples", psf.pupil_samples},
              {"rays_clipped", w.rays_lost},
              {"sample_arcmin", pair(psf.sample_x_rad * arcmin, psf.sample_y_rad * arcmin)},
              {"sample_um", pair(psf.sample_x_um, psf.sample_y_um)},
              {"retina_mm_per_deg",
               pair(psf.scale.sagittal_mm_per_rad * kRadPerDeg, psf.scale.tangential_mm_per_rad * kRadPerDeg)},
              {"cutoff_cpd", pair(sagittal_cutoff_cpd(psf), tangential_cutoff_cpd(psf))}}}};
  std::string warning = psf.warning;
  // The real stop trims the paraxial disc's rim (1 to 2 % of its cells); more means the iris is
  // smaller than the disc asked for, and the PSF is of the iris's pupil.
  if (w.rays_lost > 0.05 * w.rays_in_pupil)
    warning += fmt::format(
        "{}the real pupil passes {} of the {} rays of the {:.3f} mm disc: the PSF is of the "
        "smaller real pupil (open the camera's pupil to analyse the disc)",
        warning.empty() ? "" : "; ", w.rays_in_pupil - w.rays_lost, w.rays_in_pupil, 2.0 * w.pupil_radius_mm);
  if (!warning.empty()) f["psf_warning"] = warning;
  return f;
}

std::string format_wave_optics(const json& f) {
  const json& s = f["psf"];
  std::string out = fmt::format(
      "      Strehl {:.4f}, EE50 {:.2f} um, EE80 {:.2f} um (pupil grid {}, PSF {} x {}, a sample {:.3f} x {:.3f} "
      "arcmin = "
      "{:.3f} x {:.3f} um, sagittal x tangential; cut-off {:.1f} cycles/deg)\n",
      f["strehl"].get<double>(), f["ee50_um"].get<double>(), f["ee80_um"].get<double>(), s["grid"].get<int>(),
      s["fft_size"].get<int>(), s["fft_size"].get<int>(), s["sample_arcmin"][0].get<double>(),
      s["sample_arcmin"][1].get<double>(), s["sample_um"][0].get<double>(), s["sample_um"][1].get<double>(),
      s["cutoff_cpd"][0].get<double>());
  std::string freq = "      MTF cycles/deg", tan = "          tangential", sag = "          sagittal  ";
  for (const json& m : f["mtf"]) {
    freq += fmt::format(" {:>7g}", m["freq_cpd"].get<double>());
    tan += fmt::format(" {:>7.4f}", m["tangential"].get<double>());
    sag += fmt::format(" {:>7.4f}", m["sagittal"].get<double>());
  }
  out += freq + "\n" + tan + "\n" + sag + "\n";
  if (f.contains("psf_warning")) out += "      warning: " + f["psf_warning"].get<std::string>() + "\n";
  return out;
}

}  // namespace eyetrace::optics
