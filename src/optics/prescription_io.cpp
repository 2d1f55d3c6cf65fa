// JSON <-> Prescription. Strict on purpose: the data files are the single source of the eye
// prescriptions, so every field is named, checked for type, and unknown fields are rejected.
#include "optics/prescription_io.h"

#include <cmath>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include "optics/embedded_data.h"
#include "optics/optics_error.h"
#include "optics/phase_plate.h"

namespace eyetrace::optics {

namespace {

using nlohmann::json;

void check_keys(const json& j, const std::set<std::string>& allowed, const std::string& where) {
  if (!j.is_object()) throw OpticsError(fmt::format("{}: expected a JSON object", where));
  for (auto it = j.begin(); it != j.end(); ++it)
    if (!allowed.count(it.key())) throw OpticsError(fmt::format("{}: unknown key '{}'", where, it.key()));
}

double number(const json& j, const char* key, const std::string& where) {
  if (!j.contains(key)) throw OpticsError(fmt::format("{}: missing '{}'", where, key));
  if (!j[key].is_number()) throw OpticsError(fmt::format("{}: '{}' must be a number", where, key));
  return j[key].get<double>();
}

// A number that may be null (returns fallback) or absent (returns fallback).
double number_or(const json& j, const char* key, double fallback, const std::string& where) {
  if (!j.contains(key) || j[key].is_null()) return fallback;
  return number(j, key, where);
}

std::string text(const json& j, const char* key, const std::string& where, bool required = true) {
  if (!j.contains(key)) {
    if (required) throw OpticsError(fmt::format("{}: missing '{}'", where, key));
    return {};
  }
  if (!j[key].is_string()) throw OpticsError(fmt::format("{}: '{}' must be a string", where, key));
  return j[key].get<std::string>();
}

Dispersion read_dispersion(const json& j, const std::string& where) {
  Dispersion d;
  const std::string law = text(j, "law", where);
  if (law == "none") {
    check_keys(j, {"law"}, where);
  } else if (law == "navarro-herzberger") {
    check_keys(j, {"law", "indices_365_486.1_656.3_1014_nm"}, where);
    const json& n = j.at("indices_365_486.1_656.3_1014_nm");
    if (!n.is_array() || n.size() != 4) throw OpticsError(fmt::format("{}: navarro-herzberger needs 4 indices", where));
    d.law = DispersionLaw::NavarroHerzberger;
    for (int i = 0; i < 4; ++i) d.herzberger_indices[i] = n[i].get<double>();
  } else if (law == "cornu") {
    check_keys(j, {"law", "n_inf", "k_nm", "lambda0_nm"}, where);
    d.law = DispersionLaw::Cornu;
    d.cornu_n_inf = number(j, "n_inf", where);
    d.cornu_k_nm = number(j, "k_nm", where);
    d.cornu_lambda0_nm = number(j, "lambda0_nm", where);
  } else if (law == "abbe-linear") {
    check_keys(j, {"law", "nd", "vd"}, where);
    d.law = DispersionLaw::AbbeLinear;
    d.abbe_nd = number(j, "nd", where);
    d.abbe_vd = number(j, "vd", where);
  } else {
    throw OpticsError(
        fmt::format("{}: unknown dispersion law '{}' (none, navarro-herzberger, "
                    "cornu, abbe-linear)",
                    where, law));
  }
  return d;
}

// Two numbers [x, y] (an absent key gives 0, 0).
std::pair<double, double> number_pair(const json& j, const char* key, const std::string& where) {
  if (!j.contains(key)) return {0.0, 0.0};
  const json& v = j[key];
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
    throw OpticsError(fmt::format("{}: '{}' must be a list of two numbers [x, y]", where, key));
  return {v[0].get<double>(), v[1].get<double>()};
}

// A phase plate as prescription_to_json writes it: the coefficients and the plate's diameter
// (in its own plane) make it; the rest says where they came from.
std::shared_ptr<const PhasePlate> read_phase_plate(const json& j, const std::string& where) {
  if (!j.is_object()) throw OpticsError(fmt::format("{}: must be an object", where));
  check_keys(j,
             {"zernike_file", "zernike_osa_um", "measured_pupil_diameter_mm", "measured_wavelength_nm",
              "pupil_magnification", "diameter_mm"},
             where);
  if (!j.contains("zernike_osa_um") || !j["zernike_osa_um"].is_array())
    throw OpticsError(fmt::format("{}: 'zernike_osa_um' must be a list of numbers", where));
  std::vector<double> c;
  for (const json& v : j["zernike_osa_um"]) {
    if (!v.is_number()) throw OpticsError(fmt::format("{}: 'zernike_osa_um' must be a list of numbers", where));
    c.push_back(v.get<double>());
  }
  if (c.size() > static_cast<size_t>((kMaxZernikeFileOrder + 1) * (kMaxZernikeFileOrder + 2) / 2))
    throw OpticsError(fmt::format("{}: more than the {} terms of order {}", where,
                                  (kMaxZernikeFileOrder + 1) * (kMaxZernikeFileOrder + 2) / 2, kMaxZernikeFileOrder));
  auto plate = std::make_shared<PhasePlate>(std::move(c), 0.5 * number(j, "diameter_mm", where));
  plate->origin = j.value("zernike_file", std::string(where));
  plate->measured_pupil_diameter_mm = number_or(j, "measured_pupil_diameter_mm", 0.0, where);
  plate->measured_wavelength_nm = number_or(j, "measured_wavelength_nm", 0.0, where);
  plate->pupil_magnification = number_or(j, "pupil_magnification", 1.0, where);
  return plate;
}

// The optional fields of a biconic or placed surface (see prescription_io.h).
void read_shape(const json& s, Surface& surface, const std::string& where) {
  if (s.contains("cross_radius_mm")) {
    const double cross = number_or(s, "cross_radius_mm", 0.0, where);
    if (!s["cross_radius_mm"].is_null() && cross == 0.0)
      throw OpticsError(fmt::format("{}: cross_radius_mm 0 is not a radius (use null for flat)", where));
    const SurfaceProfile& base = surface.profile;
    surface.profile =
        SurfaceProfile::biconic(base.is_flat() ? 0.0 : base.curvature, base.conic, cross == 0.0 ? 0.0 : 1.0 / cross,
                                number_or(s, "cross_conic", base.conic, where), number_or(s, "axis_deg", 0.0, where));
  } else {
    for (const char* key : {"cross_conic", "axis_deg"})
      if (s.contains(key)) throw OpticsError(fmt::format("{}: '{}' needs 'cross_radius_mm' (a biconic)", where, key));
  }
  std::tie(surface.placement.decentre_x_mm, surface.placement.decentre_y_mm) = number_pair(s, "decentre_mm", where);
  std::tie(surface.placement.tilt_x_deg, surface.placement.tilt_y_deg) = number_pair(s, "tilt_deg", where);
}

SurfaceRole read_role(const std::string& role, const std::string& where) {
  if (role == "refract") return SurfaceRole::Refract;
  if (role == "stop") return SurfaceRole::Stop;
  if (role == "image") return SurfaceRole::Image;
  throw OpticsError(fmt::format("{}: unknown role '{}' (refract, stop, image)", where, role));
}

json write_dispersion(const Dispersion& d) {
  switch (d.law) {
    case DispersionLaw::None: return {{"law", "none"}};
    case DispersionLaw::NavarroHerzberger:
      return {{"law", "navarro-herzberger"}, {"indices_365_486.1_656.3_1014_nm", d.herzberger_indices}};
    case DispersionLaw::Cornu:
      return {{"law", "cornu"}, {"n_inf", d.cornu_n_inf}, {"k_nm", d.cornu_k_nm}, {"lambda0_nm", d.cornu_lambda0_nm}};
    case DispersionLaw::AbbeLinear: return {{"law", "abbe-linear"}, {"nd", d.abbe_nd}, {"vd", d.abbe_vd}};
  }
  return {};
}

}  // namespace

Prescription prescription_from_json(const json& j, const std::string& origin) {
  check_keys(j,
             {"format", "format_version", "model", "variant", "title", "source", "data_source", "status", "units",
              "sign_convention", "conic_convention", "reference_wavelength_nm", "object_index", "media", "surfaces",
              "notes", "accommodation", "dispersion_source", "dispersion_assumed"},
             origin);
  if (text(j, "format", origin) != "eyetrace-prescription")
    throw OpticsError(fmt::format("{}: 'format' must be \"eyetrace-prescription\"", origin));
  if (number(j, "format_version", origin) != 1)
    throw OpticsError(fmt::format("{}: unsupported format_version (this reader knows 1)", origin));
  if (j.contains("units") && text(j, "units", origin) != "mm")
    throw OpticsError(fmt::format("{}: units must be \"mm\"", origin));

  Prescription p;
  p.name = text(j, "model", origin);
  p.variant = text(j, "variant", origin, false);
  p.source = text(j, "source", origin);
  p.reference_wavelength_nm = number(j, "reference_wavelength_nm", origin);
  p.wavelength_nm = p.reference_wavelength_nm;
  p.object_index = number_or(j, "object_index", 1.0, origin);
  if (j.contains("notes"))
    for (const json& n : j.at("notes")) p.notes.push_back(n.get<std::string>());
  p.dispersion_source = text(j, "dispersion_source", origin, false);
  if (j.contains("dispersion_assumed")) {
    if (!j["dispersion_assumed"].is_boolean())
      throw OpticsError(fmt::format("{}: 'dispersion_assumed' must be true or false", origin));
    p.dispersion_assumed = j["dispersion_assumed"].get<bool>();
  }

  if (!j.contains("media") || !j["media"].is_array())
    throw OpticsError(fmt::format("{}: 'media' must be a list", origin));
  for (size_t i = 0; i < j["media"].size(); ++i) {
    const json& m = j["media"][i];
    const std::string where = fmt::format("{}: media[{}]", origin, i);
    check_keys(m, {"name", "index", "dispersion", "note"}, where);
    Medium medium;
    medium.name = text(m, "name", where);
    medium.index = number(m, "index", where);
    medium.reference_wavelength_nm = p.reference_wavelength_nm;
    if (m.contains("dispersion")) medium.dispersion = read_dispersion(m["dispersion"], where + " dispersion");
    if (p.find_medium(medium.name))
      throw OpticsError(fmt::format("{}: medium '{}' is listed twice", where, medium.name));
    p.media.push_back(medium);
  }

  if (!j.contains("surfaces") || !j["surfaces"].is_array())
    throw OpticsError(fmt::format("{}: 'surfaces' must be a list", origin));
  for (size_t i = 0; i < j["surfaces"].size(); ++i) {
    const json& s = j["surfaces"][i];
    const std::string where = fmt::format("{}: surface {}", origin, i);
    check_keys(s,
               {"name", "radius_mm", "conic", "thickness_mm", "medium", "semi_diameter_mm", "role", "note",
                "cross_radius_mm", "cross_conic", "axis_deg", "decentre_mm", "tilt_deg", "phase_plate"},
               where);
    Surface surface;
    surface.name = text(s, "name", where);
    const std::string named = fmt::format("{} '{}'", where, surface.name);
    if (!s.contains("radius_mm")) throw OpticsError(fmt::format("{}: missing 'radius_mm' (null for flat)", named));
    const double radius = number_or(s, "radius_mm", 0.0, named);
    if (!s["radius_mm"].is_null() && radius == 0.0)
      throw OpticsError(fmt::format("{}: radius_mm 0 is not a radius (use null for flat)", named));
    surface.profile = SurfaceProfile::from_radius(radius, number_or(s, "conic", 0.0, named));
    read_shape(s, surface, named);
    if (s.contains("phase_plate")) surface.phase_plate = read_phase_plate(s["phase_plate"], named + ": phase_plate");
    surface.thickness_mm = number(s, "thickness_mm", named);
    surface.medium = text(s, "medium", named);
    surface.semi_diameter_mm = number_or(s, "semi_diameter_mm", 0.0, named);
    surface.role = read_role(text(s, "role", named), named);
    const Medium* m = p.find_medium(surface.medium);
    if (!m) throw OpticsError(fmt::format("{}: medium '{}' is not in the media table", named, surface.medium));
    surface.index_after = m->index;
    p.surfaces.push_back(surface);
  }
  try {
    validate(p);
  } catch (const OpticsError& e) {
    throw OpticsError(fmt::format("{}: {}", origin, e.what()));
  }
  return p;
}

Prescription prescription_from_json_text(const std::string& text, const std::string& origin) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {  // parse_error, or out_of_range for a number like 1e99999
    throw OpticsError(fmt::format("{}: invalid JSON: {}", origin, e.what()));
  }
  try {
    return prescription_from_json(j, origin);
  } catch (const json::exception& e) {  // a value of the wrong type deep inside
    throw OpticsError(fmt::format("{}: {}", origin, e.what()));
  }
}

json prescription_to_json(const Prescription& p) {
  json media = json::array();
  for (const Medium& m : p.media)
    media.push_back({{"name", m.name}, {"index", m.index}, {"dispersion", write_dispersion(m.dispersion)}});
  json surfaces = json::array();
  for (const Surface& s : p.surfaces) {
    json e;
    e["name"] = s.name;
    e["radius_mm"] = s.profile.is_flat() ? json(nullptr) : json(1.0 / s.profile.curvature);
    e["conic"] = s.profile.conic;
    e["thickness_mm"] = s.thickness_mm;
    e["medium"] = s.medium;
    e["semi_diameter_mm"] = s.limited() ? json(s.semi_diameter_mm) : json(nullptr);
    e["role"] = to_string(s.role);
    if (s.profile.kind == ProfileKind::Biconic) {  // radius_mm / conic are the first meridian's
      e["radius_mm"] = s.profile.curvature == 0.0 ? json(nullptr) : json(1.0 / s.profile.curvature);
      e["cross_radius_mm"] = s.profile.cross_curvature == 0.0 ? json(nullptr) : json(1.0 / s.profile.cross_curvature);
      e["cross_conic"] = s.profile.cross_conic;
      e["axis_deg"] = s.profile.axis_deg;
    }
    if (!s.placement.is_identity()) {
      e["decentre_mm"] = {s.placement.decentre_x_mm, s.placement.decentre_y_mm};
      e["tilt_deg"] = {s.placement.tilt_x_deg, s.placement.tilt_y_deg};
    }
    if (const PhasePlate* plate = s.phase_plate.get())
      e["phase_plate"] = {{"zernike_file", plate->origin},
                          {"zernike_osa_um", plate->coefficients_um()},
                          {"measured_pupil_diameter_mm", plate->measured_pupil_diameter_mm},
                          {"measured_wavelength_nm", plate->measured_wavelength_nm},
                          {"pupil_magnification", plate->pupil_magnification},
                          {"diameter_mm", 2.0 * plate->radius_mm()}};
    surfaces.push_back(e);
  }
  return {{"format", "eyetrace-prescription"},
          {"format_version", 1},
          {"model", p.name},
          {"variant", p.variant},
          {"source", p.source},
          {"units", "mm"},
          {"reference_wavelength_nm", p.reference_wavelength_nm},
          {"object_index", p.object_index},
          {"media", media},
          {"surfaces", surfaces},
          {"notes", p.notes},
          {"dispersion_source", p.dispersion_source},
          {"dispersion_assumed", p.dispersion_assumed}};
}

Prescription load_prescription_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw OpticsError(fmt::format("{}: cannot read the prescription file", path));
  std::ostringstream text;
  text << in.rdbuf();
  return prescription_from_json_text(text.str(), path);
}

Prescription load_embedded_prescription(const std::string& file_name) {
  const auto& files = embedded::files();
  const auto it = files.find(file_name);
  if (it == files.end()) throw OpticsError(fmt::format("embedded data file '{}' does not exist", file_name));
  return prescription_from_json_text(it->second, file_name);
}

}  // namespace eyetrace::optics
