// Optics report and spot diagram (contents: see report.h).
#include "optics/report.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/prescription_io.h"

namespace eyetrace::optics {

namespace {

using nlohmann::json;

json finite_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

// Rounded to 1e-6 so reports diff cleanly.
double round6(double v) { return std::round(v * 1e6) / 1e6; }

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
       {std::pair{"entrance_pupil", d.entrance_pupil}, std::pair{"exit_pupil", d.exit_pupil}})
    r[key] = {{"position_mm", round6(pupil.position_mm)},
              {"diameter_mm", round6(pupil.diameter_mm)},
              {"magnification", round6(pupil.magnification)}};
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
  return r;
}

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
  out += fmt::format("  F {}  F' {}  H {}  H' {}  N {}  N' {} mm (from the first vertex)\n",
                     num(r["focal_points_mm"][0]), num(r["focal_points_mm"][1]), num(r["principal_points_mm"][0]),
                     num(r["principal_points_mm"][1]), num(r["nodal_points_mm"][0]), num(r["nodal_points_mm"][1]));
  out += fmt::format("  focal lengths {} / {} mm, back focal distance {} mm\n", num(r["focal_lengths_mm"][0]),
                     num(r["focal_lengths_mm"][1]), num(r["back_focal_distance_mm"]));
  for (const char* key : {"entrance_pupil", "exit_pupil"})
    out += fmt::format("  {}: at {} mm, diameter {} mm (x{})\n", key, num(r[key]["position_mm"]),
                       num(r[key]["diameter_mm"]), num(r[key]["magnification"]));
  out += fmt::format(
      "  stop diameter {} mm; spot (source at {}):\n", num(r["stop_diameter_mm"], "{:.2f}"),
      r["spot_object_distance_m"].is_null() ? std::string("infinity") : num(r["spot_object_distance_m"], "{:.3f} m"));
  for (const json& s : r["spot"])
    out += fmt::format("    field {:>5.1f} deg: RMS radius {:>9} um, 50% of rays within {:>9} um ({} of {} rays)\n",
                       s["field_deg"].get<double>(), num(s["rms_radius_um"], "{:.2f}"),
                       num(s["ee50_radius_um"], "{:.2f}"), s["rays"].get<int>(), s["rays_launched"].get<int>());
  for (const json& n : r["notes"]) out += fmt::format("  note: {}\n", n.get<std::string>());
  return out;
}

RgbImage spot_diagram(const std::vector<SpotResult>& spots, int width, int height) {
  if (width < 16 || height < 16 || spots.empty())
    throw OpticsError(fmt::format("spot diagram: needs >= 16 x 16 pixels and at least one spot (got {} x {}, {} spots)",
                                  width, height, spots.size()));
  RgbImage img{width, height, std::vector<std::uint8_t>(static_cast<size_t>(width) * height * 3, 255)};
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

}  // namespace eyetrace::optics
