// Optics report, spot diagram and chromatic refraction curve (contents: see report.h).
#include "optics/report.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/prescription_io.h"
#include "optics/sphero_cylinder.h"
#include "optics/wave_optics_report.h"

namespace eyetrace::optics {

namespace {

using nlohmann::json;

json finite_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

// Rounded to 1e-6 so reports diff cleanly.
double round6(double v) { return std::round(v * 1e6) / 1e6; }
double round8(double v) { return std::round(v * 1e8) / 1e8; }

// The dispersion laws and where they come from; the chromatic difference of refraction; the
// transverse chromatic aberration at the spot fields (see report.h).
void add_chromatic(json& r, const Prescription& p, const ReportOptions& options) {
  ChromaticOptions c = options.chromatic;
  c.centroid_grid = options.spot_grid;
  validate(c);
  json media = json::array();
  for (const Medium& m : p.media)
    media.push_back(
        {{"medium", m.name},
         {"law", to_string(m.dispersion.law)},
         {"index_reference", m.index},
         {"index_at_range_ends", {round8(m.index_at(c.min_wavelength_nm)), round8(m.index_at(c.max_wavelength_nm))}}});
  r["dispersion"] = {{"source", p.dispersion_source}, {"assumed", p.dispersion_assumed}, {"media", media}};

  const std::vector<RefractionAtWavelength> curve = chromatic_refraction(p, c);
  json list = json::array();
  for (const RefractionAtWavelength& w : curve)
    list.push_back({{"wavelength_nm", w.wavelength_nm}, {"refraction_diopters", round6(w.refraction_D)}});
  r["chromatic_refraction"] = list;
  r["chromatic"] = {{"min_wavelength_nm", c.min_wavelength_nm},
                    {"max_wavelength_nm", c.max_wavelength_nm},
                    {"step_nm", c.step_nm},
                    {"lca_diopters", round6(curve.back().refraction_D - curve.front().refraction_D)}};

  json fields = json::array();
  for (double field : options.fields_deg) {
    const TransverseChromatic t = transverse_chromatic_aberration(p, field, options.object_distance_m, c);
    auto value = [](bool ok, double v) { return ok ? json(round6(v) + 0.0) : json(nullptr); };  // no -0
    json f = {{"field_deg", field},
              {"tca_arcmin", value(t.ok, t.tca_arcmin)},
              {"retina_um", value(t.ok, t.retina_um)},
              {"short_angle_deg", value(t.ok, t.short_angle_deg)},
              {"long_angle_deg", value(t.ok, t.long_angle_deg)},
              {"centroid_tca_arcmin", value(t.centroid_ok, t.centroid_tca_arcmin)},
              {"centroid_retina_um", value(t.centroid_ok, t.centroid_retina_um)}};
    if (!t.ok) f["lost"] = t.lost;
    fields.push_back(f);
  }
  r["tca"] = {{"short_wavelength_nm", c.tca_short_nm},
              {"long_wavelength_nm", c.tca_long_nm},
              {"mapping_wavelength_nm", p.wavelength_nm},
              {"object_distance_m", finite_or_null(options.object_distance_m)},
              {"fields", fields}};
}

json power_vector(const PowerVector& v) {
  return {{"M_diopters", round6(v.M_D) + 0.0},
          {"J0_diopters", round6(v.J0_D) + 0.0},
          {"J45_diopters", round6(v.J45_D) + 0.0}};  // + 0.0: no -0 in the report
}

json wave_entry(const Prescription& p, const ReportOptions& options, double field) {
  WavefrontOptions o = options.wave_options;
  o.field_deg = field;
  o.object_distance_m = options.object_distance_m;
  json f = {{"field_deg", field}, {"object_distance_m", finite_or_null(options.object_distance_m)}};
  try {
    const WavefrontResult w = trace_wavefront(p, o);
    json zernike = json::array();
    for (double c : w.zernike_um) zernike.push_back(round8(c) + 0.0);
    f.update(
        {{"wavelength_nm", w.wavelength_nm},
         {"pupil_radius_mm", round8(w.pupil_radius_mm)},
         {"rms_wavefront_waves", round6(w.rms_waves)},
         {"rms_sampled_waves", round6(w.rms_sampled_waves)},
         {"pv_wavefront_waves", round6(w.pv_waves)},
         {"zernike_order", w.zernike_order},
         {"zernike_osa_um", zernike},
         {"refraction", {{"least_squares", power_vector(w.least_squares)}, {"paraxial", power_vector(w.paraxial)}}},
         {"rays", static_cast<int>(w.opd_waves.size())},
         {"rays_lost", w.rays_lost}});
    if (!w.warning.empty()) f["warning"] = w.warning;
    f.update(wave_optics_json(p, o, options.mtf_freqs_cpd));
    if (options.polychromatic) try {
        f["polychromatic"] = polychromatic_json(p, o, options.polychromatic_options, options.mtf_freqs_cpd);
      } catch (const OpticsError& e) {
        f["polychromatic"] = {{"error", e.what()}};
      }
  } catch (const OpticsError& e) {
    // A field the analysis cannot serve is reported, not dropped: null numbers and the reason.
    for (const char* key :
         {"wavelength_nm", "pupil_radius_mm", "rms_wavefront_waves", "rms_sampled_waves", "pv_wavefront_waves",
          "zernike_osa_um", "refraction", "strehl", "ee50_um", "ee80_um", "mtf"})
      f[key] = nullptr;
    f["error"] = e.what();
  }
  return f;
}

// Validates the wavefront options once (a bad option is an error, not one per field).
void add_wave(json& r, const Prescription& p, const ReportOptions& options) {
  WavefrontOptions probe = options.wave_options;
  probe.field_deg = 0.0;
  probe.object_distance_m = options.object_distance_m;
  validate(probe);
  check_mtf_frequencies(p, probe, options.mtf_freqs_cpd);
  if (options.polychromatic) validate(options.polychromatic_options);
  json fields = json::array();
  for (double field : options.fields_deg) fields.push_back(wave_entry(p, options, field));
  r["wave"] = fields;
}

// Law names with the media that follow each, in the order of the media table:
// "navarro-herzberger (cornea, aqueous, lens, vitreous)".
std::string dispersion_summary(const json& media) {
  std::vector<std::pair<std::string, std::string>> groups;
  for (const json& m : media) {
    const std::string law = m.at("law").get<std::string>(), name = m.at("medium").get<std::string>();
    auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == law; });
    if (it == groups.end())
      groups.emplace_back(law, name);
    else
      it->second += ", " + name;
  }
  std::string out;
  for (const auto& [law, names] : groups) out += (out.empty() ? "" : "; ") + law + " (" + names + ")";
  return out;
}

// The refraction per meridian (sphero_cylinder.h): sphere, cylinder (minus cylinder) and axis,
// and the power vector, at the first vertex.
void add_sphero_cylinder(json& r, const Prescription& p) {
  const SpheroCylinder rx = refraction_sphero_cylinder(p);
  r["sphere_diopters"] = round6(rx.sphere_D) + 0.0;  // + 0.0: no -0 in the report
  r["cylinder_diopters"] = round6(rx.cylinder_D) + 0.0;
  r["axis_deg"] = round6(rx.axis_deg) + 0.0;
  r["M"] = round6(rx.M_D) + 0.0;
  r["J0"] = round6(rx.J0_D) + 0.0;
  r["J45"] = round6(rx.J45_D) + 0.0;
}

}  // namespace

json optics_report(const Prescription& p, const ReportOptions& options) {
  const ParaxialData d = paraxial_analysis(p);
  const Surface& retina = p.surfaces.back();
  json r;
  r["model"] = p.name;
  r["variant"] = p.variant;
  r["source"] = p.source;
  r["wavelength_nm"] = p.wavelength_nm;
  r["reference_wavelength_nm"] = p.reference_wavelength_nm;
  r["notes"] = p.notes;
  r["power_diopters"] = round6(d.power_D);
  r["refraction_diopters"] = round6(d.refraction_D);
  add_sphero_cylinder(r, p);
  // Below 0.005 D (a fiftieth of the clinical 0.25 D step) the eye counts as emmetropic: the
  // relaxed Navarro eye's -1e-5 D, the rounding of its published axial length, would otherwise
  // print a far point 98 km away. refraction_diopters keeps the exact value.
  r["far_point_m"] = std::abs(d.refraction_D) < kEmmetropia_D ? json(nullptr) : json(round6(d.far_point_m));
  r["axial_length_mm"] = round6(d.axial_length_mm);
  r["retina_radius_mm"] = retina.profile.is_flat() ? json(nullptr) : json(round6(1.0 / retina.profile.curvature));
  r["retina_conic"] = retina.profile.conic;
  r["focal_points_mm"] = {round6(d.front_focal_point_mm), round6(d.back_focal_point_mm)};
  r["principal_points_mm"] = {round6(d.front_principal_point_mm), round6(d.back_principal_point_mm)};
  r["nodal_points_mm"] = {round6(d.front_nodal_point_mm), round6(d.back_nodal_point_mm)};
  r["focal_lengths_mm"] = {round6(d.front_focal_length_mm), round6(d.back_focal_length_mm)};
  r["back_focal_distance_mm"] = round6(d.back_focal_distance_mm);
  r["stop_diameter_mm"] = p.stop_diameter_mm();
  for (const auto& [key, pupil] :
       {std::pair{"entrance_pupil", d.entrance_pupil}, std::pair{"exit_pupil", d.exit_pupil}}) {
    r[key] = {{"position_mm", round6(pupil.position_mm)},
              {"diameter_mm", round6(pupil.diameter_mm)},
              {"magnification", round6(pupil.magnification)}};
    if (pupil.centre_x_mm != 0.0 || pupil.centre_y_mm != 0.0)  // a decentred iris
      r[key]["centre_mm"] = {round6(pupil.centre_x_mm) + 0.0, round6(pupil.centre_y_mm) + 0.0};
  }
  r["spot_object_distance_m"] = finite_or_null(options.object_distance_m);
  json spots = json::array();
  for (double field : options.fields_deg) {
    const SpotResult s = trace_spot(p, {field, options.object_distance_m, options.spot_grid});
    spots.push_back({{"field_deg", field},
                     {"rms_radius_um", s.rays > 0 ? json(round6(s.rms_radius_um)) : json(nullptr)},
                     {"ee50_radius_um", s.rays > 0 ? json(round6(s.ee50_radius_um)) : json(nullptr)},
                     {"rays", s.rays},
                     {"rays_launched", s.rays_launched}});
  }
  r["spot"] = spots;
  r["surfaces"] = prescription_to_json(p)["surfaces"];
  add_chromatic(r, p, options);
  if (options.wave) add_wave(r, p, options);
  return r;
}

namespace {

template <class Num>
std::string format_chromatic(const json& r, Num num) {
  const json& d = r["dispersion"];
  std::string out =
      fmt::format("  dispersion{}: {}\n", d["assumed"].get<bool>() ? " (assumed: not published with the model)" : "",
                  dispersion_summary(d["media"]));
  if (!d["source"].get<std::string>().empty()) out += fmt::format("    source: {}\n", d["source"].get<std::string>());
  const json& c = r["chromatic"];
  if (std::all_of(d["media"].begin(), d["media"].end(), [](const json& m) { return m["law"] == "none"; }))
    return out + fmt::format("  chromatic: no medium disperses: refraction {} D at every wavelength, no TCA\n",
                             num(r["chromatic_refraction"][0]["refraction_diopters"], "{:+.3f}"));
  out += fmt::format("  chromatic difference of refraction, {:g}-{:g} nm every {:g} nm (D; LCA {} D):\n",
                     c["min_wavelength_nm"].get<double>(), c["max_wavelength_nm"].get<double>(),
                     c["step_nm"].get<double>(), num(c["lca_diopters"], "{:.3f}"));
  const json& list = r["chromatic_refraction"];
  for (size_t i = 0; i < list.size(); i += 6) {
    out += "   ";
    for (size_t j = i; j < std::min(list.size(), i + 6); ++j)
      out += fmt::format(" {:>5g} {:>+7.3f}", list[j]["wavelength_nm"].get<double>(),
                         list[j]["refraction_diopters"].get<double>() + 0.0);
    out += "\n";
  }
  const json& t = r["tca"];
  out += fmt::format(
      "  transverse chromatic aberration {0:g}-{1:g} nm (visual angle of the {0:g} nm image minus the {1:g} nm "
      "image; + = {0:g} nm farther out):\n",
      t["short_wavelength_nm"].get<double>(), t["long_wavelength_nm"].get<double>());
  for (const json& f : t["fields"])
    out += fmt::format(
        "    field {:>5.1f} deg: TCA {:>8} arcmin, on the retina {:>8} um; spot centroids {:>8} arcmin{}\n",
        f["field_deg"].get<double>(), num(f["tca_arcmin"], "{:+.3f}"), num(f["retina_um"], "{:+.2f}"),
        num(f["centroid_tca_arcmin"], "{:+.3f}"), f.contains("lost") ? " (" + f["lost"].get<std::string>() + ")" : "");
  return out;
}

// One line per field, then the Zernike coefficients through the fourth order.
template <class Num>
std::string format_wave(const json& wave, Num num) {
  std::string out = "  wavefront (OPD against the sphere about the chief ray's image; OSA Zernike, um):\n";
  for (const json& f : wave) {
    if (f.contains("error")) {
      out += fmt::format("    field {:>5.1f} deg: {}\n", f["field_deg"].get<double>(), f["error"].get<std::string>());
      continue;
    }
    const json &ls = f["refraction"]["least_squares"], &px = f["refraction"]["paraxial"];
    out += fmt::format(
        "    field {:>5.1f} deg, {} nm, pupil {} mm: RMS {} waves, PV {} waves; refraction M/J0/J45 {}/{}/{} D "
        "(least squares), {}/{}/{} D (paraxial){}\n",
        f["field_deg"].get<double>(), num(f["wavelength_nm"], "{:g}"), num(f["pupil_radius_mm"], "{:.3f}"),
        num(f["rms_wavefront_waves"], "{:.4f}"), num(f["pv_wavefront_waves"], "{:.4f}"),
        num(ls["M_diopters"], "{:+.3f}"), num(ls["J0_diopters"], "{:+.3f}"), num(ls["J45_diopters"], "{:+.3f}"),
        num(px["M_diopters"], "{:+.3f}"), num(px["J0_diopters"], "{:+.3f}"), num(px["J45_diopters"], "{:+.3f}"),
        f.contains("warning") ? "; " + f["warning"].get<std::string>() : std::string());
    out += "      j 0-14:";
    const json& c = f["zernike_osa_um"];
    for (size_t j = 0; j < std::min<size_t>(15, c.size()); ++j) out += " " + num(c[j], "{:+.4f}");
    out += "\n";
    if (f.contains("mtf") && f["mtf"].is_array()) out += format_wave_optics(f);
  }
  return out;
}

}  // namespace

std::string format_report(const json& r) {
  auto num = [](const json& v, const char* fmt_spec = "{:.4f}") {
    return v.is_null() ? std::string("-") : fmt::format(fmt::runtime(fmt_spec), v.get<double>());
  };
  std::string out =
      fmt::format("{}{} at {} nm\n  source: {}\n", r.at("model").get<std::string>(),
                  r.at("variant").get<std::string>().empty() ? "" : " [" + r.at("variant").get<std::string>() + "]",
                  r.at("wavelength_nm").get<double>(), r.at("source").get<std::string>());
  out += fmt::format("  power {} D, refraction {} D (far point {} m), axial length {} mm, retina radius {} mm\n",
                     num(r["power_diopters"], "{:.3f}"), num(r["refraction_diopters"], "{:.3f}"),
                     num(r["far_point_m"], "{:.3f}"), num(r["axial_length_mm"]), num(r["retina_radius_mm"], "{:.2f}"));
  if (r.contains("sphere_diopters"))
    out += fmt::format("  refraction {} / {} x {} (sphere D / minus cylinder D x axis deg); M {} J0 {} J45 {} D\n",
                       num(r["sphere_diopters"], "{:+.3f}"), num(r["cylinder_diopters"], "{:+.3f}"),
                       num(r["axis_deg"], "{:.1f}"), num(r["M"], "{:+.3f}"), num(r["J0"], "{:+.3f}"),
                       num(r["J45"], "{:+.3f}"));
  out += fmt::format("  F {}  F' {}  H {}  H' {}  N {}  N' {} mm (from the first vertex)\n",
                     num(r["focal_points_mm"][0]), num(r["focal_points_mm"][1]), num(r["principal_points_mm"][0]),
                     num(r["principal_points_mm"][1]), num(r["nodal_points_mm"][0]), num(r["nodal_points_mm"][1]));
  out += fmt::format("  focal lengths {} / {} mm, back focal distance {} mm\n", num(r["focal_lengths_mm"][0]),
                     num(r["focal_lengths_mm"][1]), num(r["back_focal_distance_mm"]));
  for (const char* key : {"entrance_pupil", "exit_pupil"})
    out += fmt::format("  {}: at {} mm, diameter {} mm (x{}){}\n", key, num(r[key]["position_mm"]),
                       num(r[key]["diameter_mm"]), num(r[key]["magnification"]),
                       r[key].contains("centre_mm") ? fmt::format(", centre ({}, {}) mm", num(r[key]["centre_mm"][0]),
                                                                  num(r[key]["centre_mm"][1]))
                                                    : std::string());
  for (size_t i = 0; r.contains("surfaces") && i < r["surfaces"].size(); ++i) {
    const json& s = r["surfaces"][i];
    if (!s.contains("phase_plate")) continue;
    const json& plate = s["phase_plate"];
    out += fmt::format(
        "  phase plate on surface {} '{}': {} ({} OSA terms), measured over a {} mm pupil{}; {} mm here (pupil "
        "magnification {})\n",
        i, s["name"].get<std::string>(), plate["zernike_file"].get<std::string>(), plate["zernike_osa_um"].size(),
        num(plate["measured_pupil_diameter_mm"], "{:g}"),
        plate["measured_wavelength_nm"].get<double>() > 0.0
            ? fmt::format(" at {:g} nm", plate["measured_wavelength_nm"].get<double>())
            : std::string(),
        num(plate["diameter_mm"], "{:.3f}"), num(plate["pupil_magnification"], "{:.4f}"));
  }
  out += fmt::format(
      "  stop diameter {} mm; spot (source at {}):\n", num(r["stop_diameter_mm"], "{:.2f}"),
      r["spot_object_distance_m"].is_null() ? std::string("infinity") : num(r["spot_object_distance_m"], "{:.3f} m"));
  for (const json& s : r["spot"])
    out += fmt::format("    field {:>5.1f} deg: RMS radius {:>9} um, 50% of rays within {:>9} um ({} of {} rays)\n",
                       s["field_deg"].get<double>(), num(s["rms_radius_um"], "{:.2f}"),
                       num(s["ee50_radius_um"], "{:.2f}"), s["rays"].get<int>(), s["rays_launched"].get<int>());
  if (r.contains("dispersion")) out += format_chromatic(r, num);
  if (r.contains("wave")) out += format_wave(r["wave"], num);
  for (const json& n : r["notes"]) out += fmt::format("  note: {}\n", n.get<std::string>());
  return out;
}

RgbImage spot_diagram(const std::vector<SpotResult>& spots, int width, int height) {
  if (width < 16 || height < 16 || spots.empty())
    throw OpticsError(fmt::format("spot diagram: needs >= 16 x 16 pixels and at least one spot (got {} x {}, {} spots)",
                                  width, height, spots.size()));
  RgbImage img(width, height);
  auto put = [&](int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    std::uint8_t* px = &img.rgb[(static_cast<size_t>(y) * width + x) * 3];
    px[0] = r, px[1] = g, px[2] = b;
  };
  const int panels = static_cast<int>(spots.size());
  const int panel_w = width / panels;
  // Common scale: the largest extent of any spot fills 40 % of the smaller panel side.
  double extent = 0.0;
  for (const SpotResult& s : spots)
    for (const glm::dvec2& q : s.points_um) extent = std::max({extent, std::abs(q.x), std::abs(q.y)});
  if (extent == 0.0) extent = 1.0;
  img.um_per_pixel = extent / (0.4 * std::min(panel_w, height));
  // Scale bar: a 1-2-5 length close to a quarter of the panel width.
  const double target = 0.25 * panel_w * img.um_per_pixel;
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  img.scale_bar_um = decade * (target >= 5 * decade ? 5 : target >= 2 * decade ? 2 : 1);

  static constexpr std::uint8_t kPalette[][3] = {{31, 119, 180},  {214, 39, 40},  {44, 160, 44},
                                                 {148, 103, 189}, {255, 127, 14}, {23, 190, 207}};
  for (int k = 0; k < panels; ++k) {
    const int left = k * panel_w, cx = left + panel_w / 2, cy = height / 2;
    for (int y = 0; y < height; ++y) put(left, y, 160, 160, 160);  // panel separator
    for (int x = left + 1; x < left + panel_w; ++x) put(x, cy, 220, 220, 220);
    for (int y = 0; y < height; ++y) put(cx, y, 220, 220, 220);
    const std::uint8_t* c = kPalette[k % 6];
    for (const glm::dvec2& q : spots[k].points_um)  // image y up
      put(cx + static_cast<int>(std::lround(q.x / img.um_per_pixel)),
          cy - static_cast<int>(std::lround(q.y / img.um_per_pixel)), c[0], c[1], c[2]);
    const int bar = static_cast<int>(std::lround(img.scale_bar_um / img.um_per_pixel));
    for (int t = 0; t < 3; ++t)
      for (int x = 0; x < bar; ++x) put(left + 6 + x, height - 8 + t, 0, 0, 0);
  }
  return img;
}

namespace {

// A 1-2-2.5-5 step close to span / wanted.
double nice_step(double span, int wanted) {
  const double raw = span / wanted;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 2.5, 5.0})
    if (m * decade >= raw) return m * decade;
  return 10.0 * decade;
}

}  // namespace

RgbImage chromatic_plot(const json& report, int width, int height) {
  if (width < 240 || height < 160)
    throw OpticsError(fmt::format("chromatic plot: needs >= 240 x 160 pixels (got {} x {})", width, height));
  const json& list = report.at("chromatic_refraction");
  if (list.size() < 2) throw OpticsError("chromatic plot: needs at least two wavelengths");
  const int scale = width >= 480 && height >= 240 ? 2 : 1;
  const int glyph_h = RgbImage::text_height(scale);
  const int left = 6 * 6 * scale, right = 16 * scale, top = 2 * glyph_h + 10 * scale, bottom = 2 * glyph_h + 10 * scale;
  RgbImage img(width, height);
  const Rgb black{0, 0, 0}, grid{225, 225, 225}, curve{31, 119, 180}, marker{214, 39, 40}, axis0{150, 150, 150};

  double lam0 = list.front()["wavelength_nm"].get<double>(), lam1 = list.back()["wavelength_nm"].get<double>();
  double r0 = 1e300, r1 = -1e300;
  for (const json& e : list) {
    r0 = std::min(r0, e["refraction_diopters"].get<double>());
    r1 = std::max(r1, e["refraction_diopters"].get<double>());
  }
  if (r1 - r0 < 0.1) r0 -= 0.05, r1 += 0.05;  // a flat curve (no dispersion) still gets an axis
  const double ystep = nice_step(r1 - r0, 6), xstep = nice_step(lam1 - lam0, 6);
  r0 = std::floor(r0 / ystep) * ystep, r1 = std::ceil(r1 / ystep) * ystep;
  const int x0 = left, x1 = width - right, y0 = top, y1 = height - bottom;
  auto px = [&](double lam) { return x0 + (lam - lam0) / (lam1 - lam0) * (x1 - x0); };
  auto py = [&](double d) { return y1 - (d - r0) / (r1 - r0) * (y1 - y0); };

  for (double v = std::ceil(lam0 / xstep) * xstep; v <= lam1 + 1e-9; v += xstep) {
    img.line(px(v), y0, px(v), y1, grid);
    const std::string label = fmt::format("{:g}", v);
    img.text(static_cast<int>(px(v)) - RgbImage::text_width(label, scale) / 2, y1 + 4 * scale, label, black, scale);
  }
  const int decimals = ystep < 0.1 ? 2 : 1;
  for (double v = r0; v <= r1 + 1e-9 * ystep; v += ystep) {
    img.line(x0, py(v), x1, py(v), std::abs(v) < 1e-9 * ystep ? axis0 : grid);
    const std::string label = std::abs(v) < 1e-9 * ystep ? std::string("0") : fmt::format("{:+.{}f}", v, decimals);
    img.text(x0 - 4 * scale - RgbImage::text_width(label, scale), static_cast<int>(py(v)) - glyph_h / 2, label, black,
             scale);
  }
  // The prescription's own wavelength: a dashed vertical line.
  const double own = report.at("wavelength_nm").get<double>();
  if (own >= lam0 && own <= lam1)
    for (double y = y0; y < y1; y += 8.0) img.line(px(own), y, px(own), std::min<double>(y + 4.0, y1), marker, scale);
  img.line(x0, y0, x1, y0, black), img.line(x0, y1, x1, y1, black);
  img.line(x0, y0, x0, y1, black), img.line(x1, y0, x1, y1, black);
  for (size_t i = 0; i + 1 < list.size(); ++i)
    img.line(px(list[i]["wavelength_nm"].get<double>()), py(list[i]["refraction_diopters"].get<double>()),
             px(list[i + 1]["wavelength_nm"].get<double>()), py(list[i + 1]["refraction_diopters"].get<double>()),
             curve, 2 * scale);
  for (const json& e : list)
    img.line(px(e["wavelength_nm"].get<double>()), py(e["refraction_diopters"].get<double>()),
             px(e["wavelength_nm"].get<double>()), py(e["refraction_diopters"].get<double>()), curve, 3 * scale + 1);

  const std::string variant = report.value("variant", "");
  const std::string title =
      fmt::format("{}{}: refraction (D) vs wavelength, LCA {:.2f} D", report.value("model", ""),
                  variant.empty() ? "" : " " + variant, report.at("chromatic").at("lca_diopters").get<double>());
  img.text(x0, 5 * scale, title, black, scale);
  const std::string xlabel = fmt::format("wavelength (nm), dashed: {:g} nm", own);
  img.text((x0 + x1 - RgbImage::text_width(xlabel, scale)) / 2, y1 + glyph_h + 8 * scale, xlabel, black, scale);
  return img;
}

}  // namespace eyetrace::optics
