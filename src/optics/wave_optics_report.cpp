// PSF, Strehl ratio, encircled energy and MTF in the optics report (see wave_optics_report.h).
#include "optics/wave_optics_report.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "optics/constants.h"
#include "optics/mtf.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/psf.h"

namespace eyetrace::optics {

namespace {

using nlohmann::json;

double round6_no_minus_zero(double v) { return std::round(v * 1e6) / 1e6 + 0.0; }

json pair(double sagittal, double tangential) {
  return json::array({round6_no_minus_zero(sagittal), round6_no_minus_zero(tangential)});
}

// The polychromatic object's lines (or its error).
std::string format_polychromatic(const json& poly) {
  if (poly.contains("error")) return "      polychromatic: " + poly["error"].get<std::string>() + "\n";
  const json& w = poly["wavelengths_nm"];
  std::string out = fmt::format(
      "      polychromatic ({}-{} nm every {} nm, V(lambda) x {} source): Strehl {:.4f}, EE50 {:.2f} um, EE80 "
      "{:.2f} um, centroid {:+.2f} um tangentially from the {} nm chief ray\n",
      w["min"].get<double>(), w["max"].get<double>(), w["step"].get<double>(), poly["source"].get<std::string>(),
      poly["strehl"].get<double>(), poly["ee50_um"].get<double>(), poly["ee80_um"].get<double>(),
      poly["centroid_um"][1].get<double>(), poly["reference_wavelength_nm"].get<double>());
  std::string tan = "          tangential", sag = "          sagittal  ";
  for (const json& m : poly["mtf"]) {
    tan += fmt::format(" {:>7.4f}", m["tangential"].get<double>());
    sag += fmt::format(" {:>7.4f}", m["sagittal"].get<double>());
  }
  out += tan + "\n" + sag + "\n";
  if (poly.contains("psf_warning")) out += "      warning: " + poly["psf_warning"].get<std::string>() + "\n";
  return out;
}

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

json wave_optics_json(const Prescription& p, const WavefrontOptions& options, const std::vector<double>& freqs) {
  const TracedPsf traced = trace_psf(p, options);
  const WavefrontResult& w = traced.wavefront;
  const Psf& psf = traced.psf;
  json mtf = json::array();
  for (const MtfPoint& m : compute_mtf(psf, freqs))
    mtf.push_back({{"freq_cpd", m.freq_cpd},
                   {"tangential", round6_no_minus_zero(m.tangential)},
                   {"sagittal", round6_no_minus_zero(m.sagittal)},
                   {"tangential_cyc_per_mm", round6_no_minus_zero(m.tangential_cyc_per_mm)},
                   {"sagittal_cyc_per_mm", round6_no_minus_zero(m.sagittal_cyc_per_mm)}});
  const double arcmin = 60.0 / kRadPerDeg;
  json f = {{"strehl", round6_no_minus_zero(psf.strehl)},
            {"strehl_at_chief_ray", round6_no_minus_zero(psf.strehl_phasor)},
            {"ee50_um", round6_no_minus_zero(psf.ee50_um)},
            {"ee80_um", round6_no_minus_zero(psf.ee80_um)},
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

json polychromatic_json(const Prescription& p, const WavefrontOptions& options, const PolychromaticOptions& poly,
                        const std::vector<double>& freqs) {
  const PolychromaticPsf psf = polychromatic_psf(p, options, poly);
  json mtf = json::array();
  for (const MtfPoint& m : polychromatic_mtf(psf, freqs)) {
    const MtfPoint limit = polychromatic_diffraction_limit(psf, m.freq_cpd);
    mtf.push_back({{"freq_cpd", m.freq_cpd},
                   {"tangential", round6_no_minus_zero(m.tangential)},
                   {"sagittal", round6_no_minus_zero(m.sagittal)},
                   {"tangential_cyc_per_mm", round6_no_minus_zero(m.tangential_cyc_per_mm)},
                   {"sagittal_cyc_per_mm", round6_no_minus_zero(m.sagittal_cyc_per_mm)},
                   {"diffraction_limit", pair(limit.sagittal, limit.tangential)}});
  }
  int grid_max = 0;
  std::string warning;
  for (const PolychromaticComponent& c : psf.components) {
    grid_max = std::max(grid_max, c.grid);
    if (!c.warning.empty() && warning.empty()) warning = fmt::format("{} nm: {}", c.wavelength_nm, c.warning);
  }
  json f = {{"wavelengths_nm",
             {{"min", poly.min_wavelength_nm},
              {"max", poly.max_wavelength_nm},
              {"step", poly.step_nm},
              {"count", psf.components.size()}}},
            {"source", psf.source_name},
            {"reference_wavelength_nm", psf.reference_wavelength_nm},
            {"strehl", round6_no_minus_zero(psf.strehl)},
            {"ee50_um", round6_no_minus_zero(psf.ee50_um)},
            {"ee80_um", round6_no_minus_zero(psf.ee80_um)},
            {"centroid_um", pair(psf.centroid_um.x, psf.centroid_um.y)},
            {"peak_um", pair(psf.peak_um.x, psf.peak_um.y)},
            {"grid_max", grid_max},
            {"mtf", mtf}};
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
  if (f.contains("polychromatic")) out += format_polychromatic(f["polychromatic"]);
  return out;
}

}  // namespace eyetrace::optics
